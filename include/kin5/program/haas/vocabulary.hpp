/// @file program/haas/vocabulary.hpp
/// What the Haas reader and writer share beyond ISO's vocabulary (iso/vocabulary.hpp): the
/// dwells `G04 P` takes, and the codes the writer spells as a Haas control reads them.
/// @code
///   kin5::program::dwell_refusal(kin5::program::haas::dwell_steps, 1.5);  // "": G04 P1.5
/// @endcode
#pragma once

#include "../dwell.hpp"
#include "../iso/vocabulary.hpp"
#include "../iso/writer.hpp"

namespace kin5::program::haas {

/// The dwells a Haas control takes with `G04 P`: ISO's, seconds to the millisecond up to
/// 9999.999 s (P without a decimal point counts milliseconds; docs/dialects/haas.md).
inline constexpr dwell_input dwell_steps = iso::detail::dwell_steps;

/// The ISO writer's codes as a Haas mill spells them: TCPC `G234 H n` and no vector form,
/// additional work offsets `G154 P1` … `P99`, a dwell `G04 P` in seconds with a decimal point.
inline constexpr iso::spelling haas_spelling{
    .name = "Haas", .tcp_on = "G234", .vector_tcp = false, .extended = "G154", .extended_count = 99,
    .dwell_letter = 'P'};

}  // namespace kin5::program::haas

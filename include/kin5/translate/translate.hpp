/// @file translate/translate.hpp
/// Translating an NC program from one machine to another, block by block, and its two halves:
/// `reverse` (NC → APT CL data) and `post` (CL data → NC). For each motion block:
///
///     tip_source_mm = programmed XYZ (TCP on),  u_source = tool_axis<From>(angles)   (K1), (G1)
///     tip_target_mm = target_T_source.map_point(tip_source_mm),  u_target = R u_source  (K10)/(K11)
///     all solutions of inverse<To>(u_target) within travel                         (G3)/(G4), S2
///     the sequence of least total rotary travel over the whole program   (kinematics/branch_plan.hpp)
///     F by the feed policy                                                         (K15)–(K17)
///
/// Every input block is accounted for: written (mapped), passed through unchanged, or an
/// error naming its line. Blocks the target cannot reach are errors carrying their gap, never
/// clamped or dropped; any error means the output must not be written. The pieces, in the order
/// data flows through them: options.hpp, source_walk.hpp, setup.hpp, branch plan, feed.hpp,
/// carry_over.hpp, nc_target.hpp / cl_target.hpp, pipeline.hpp, stream.hpp (over a file's text);
/// by id: by_id.hpp. Every function takes machine values (`machine_model`), so one instantiation
/// serves every machine and pair, a machine file's too; the template forms pass `M::model`.
/// Maths and choices: docs/translation.md.
/// @code
///   auto t = kin5::translate<kin5::machines::sajo_12000p, kin5::machines::dmu_80p>(nc);
///   if (!t.ok()) for (const auto& e : t.errors) std::cerr << e.to_string() << '\n';
/// @endcode
#pragma once

#include "../kinematics/machine.hpp"
#include "../program/block.hpp"
#include "options.hpp"
#include "pipeline.hpp"

namespace kin5 {

/// Translates NC program `nc` of machine `from` into one for machine `to` (see the file comment).
/// The source must run with tool-tip tracking; `options.output_dialect` must be an NC dialect.
inline translation translate(const machine_model& from, const machine_model& to, const program::program& nc,
                             const translate_options& options = {}) {
  return translate_detail::run(*make_translator(from, to, nc.language, nc.file, options), nc);
}

/// The inverse post of NC program `nc` of machine `m` (see `reverse<M>`).
inline translation reverse(const machine_model& m, const program::program& nc) {
  return translate_detail::run(*make_reverse(m, nc.language, nc.file), nc);
}

/// The post of APT CL data `cl` for machine `m` (see `post<M>`).
inline translation post(const machine_model& m, const program::program& cl, program::dialect output_dialect) {
  return translate_detail::run(*make_post(m, cl.language, output_dialect, cl.file), cl);
}

/// Translates NC program `nc` of machine From into one for machine To (see the file comment).
/// The source must run with tool-tip tracking; `options.output_dialect` must be an NC dialect.
template <machine From, machine To>
translation translate(const program::program& nc, const translate_options& options = {}) {
  return translate_detail::run(*make_translator<From, To>(nc.language, nc.file, options), nc);
}

/// The inverse post: NC program `nc` of machine M → APT CL data, each motion block a
/// GOTO/x,y,z,i,j,k with the tool axis from `tool_axis<M>` (K1)/(G1); F kept (tool-tip feed).
/// Circular moves are errors (CL data here is GOTO points only).
template <machine M>
translation reverse(const program::program& nc) {
  return translate_detail::run(*make_reverse<M>(nc.language, nc.file), nc);
}

/// The post: APT CL data `cl` → NC for machine M in dialect `output_dialect`: `inverse<M>` of
/// every GOTO tool axis and the same whole-program branch choice as `translate`, F kept.
/// Tool-tip tracking is switched on in the first motion block (TRAORI / M128 / G43.4, as the
/// writer spells it) and off again in the program-end block.
template <machine M>
translation post(const program::program& cl, program::dialect output_dialect) {
  return translate_detail::run(*make_post<M>(cl.language, output_dialect, cl.file), cl);
}

}  // namespace kin5

/// @file machines/every_machine.hpp
/// Every bundled machine as the type list `every_machine`: the catalog (catalog.hpp), then the
/// structures added with the whole-machine chain — a B/C and an A/B trunnion, a nutating B/C
/// table and LinuxCNC's two table-rotary-tilting simulation machines. Each also ships as a machine
/// file, machines/<id>.toml. The matchability tables and the by-id translation cover `catalog`.
/// @code
///   kin5::machines::for_each_machine_in<kin5::machines::every_machine>(
///       []<class M>() { std::cout << M::id << '\n'; });
/// @endcode
#pragma once

#include <tuple>

#include "ab_trunnion.hpp"
#include "bc_nutating_table.hpp"
#include "bc_trunnion.hpp"
#include "catalog.hpp"
#include "xyzac_trt.hpp"
#include "xyzbc_trt.hpp"

namespace kin5::machines {

/// `catalog`, then the machines added with the whole-machine chain, in the order `kin5 machines`
/// lists them.
using every_machine = std::tuple<sajo_12000p, dmu_80p, ac_trunnion, dmu_50v, a_rotary_4axis, ac_head,
                                 b_head_a_tilted_table, bc_trunnion, ab_trunnion, bc_nutating_table, xyzac_trt,
                                 xyzbc_trt>;

/// Calls `f.template operator()<M>()` for each machine M of the type list `List`, in order.
template <class List, class F>
constexpr void for_each_machine_in(F&& f) {
  [&]<class... Ms>(std::tuple<Ms...>*) { (f.template operator()<Ms>(), ...); }(static_cast<List*>(nullptr));
}

}  // namespace kin5::machines

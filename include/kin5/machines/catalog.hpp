/// @file machines/catalog.hpp
/// The catalog: every bundled machine type, and `catalog`, a type list of them for code (tests,
/// the command line) that must do something for each, or for the one with a given id
/// (`with_machine` for its type, `find_machine` for its `machine_model` value), and
/// `catalog_models`, the same machines as values for loops at run time.
#pragma once

#include <array>
#include <string_view>
#include <tuple>

#include "a_rotary_4axis.hpp"
#include "ab_trunnion.hpp"
#include "ac_head.hpp"
#include "ac_trunnion.hpp"
#include "b_head_a_tilted_table.hpp"
#include "bc_nutating_table.hpp"
#include "bc_trunnion.hpp"
#include "dmu_50v.hpp"
#include "dmu_80p.hpp"
#include "sajo_12000p.hpp"
#include "xyzac_trt.hpp"
#include "xyzbc_trt.hpp"

namespace kin5::machines {

/// Every catalog machine, in the order `kin5 machines` lists them: the machines of the source
/// papers and two of Li et al. 2013's structures, then a B/C and an A/B trunnion, a nutating B/C
/// table and LinuxCNC's two table-rotary-tilting simulation machines. Each also ships as a
/// machine file, machines/<id>.toml.
using catalog = std::tuple<sajo_12000p, dmu_80p, ac_trunnion, dmu_50v, a_rotary_4axis, ac_head, b_head_a_tilted_table,
                           bc_trunnion, ab_trunnion, bc_nutating_table, xyzac_trt, xyzbc_trt>;

/// Calls `f.template operator()<M>()` for each catalog machine M, in order.
template <class F>
constexpr void for_each_machine(F&& f) {
  [&]<class... Ms>(std::tuple<Ms...>*) { (f.template operator()<Ms>(), ...); }(static_cast<catalog*>(nullptr));
}

/// The models of the machines of the type list `List`, in its order: for code that does the
/// same for each machine at run time (one instantiation, not one per machine or pair).
template <class List>
consteval auto models_of() {
  return []<class... Ms>(std::tuple<Ms...>*) {
    return std::array<const machine_model*, sizeof...(Ms)>{&Ms::model...};
  }(static_cast<List*>(nullptr));
}

/// The models of every catalog machine, in catalog order.
inline constexpr auto catalog_models = models_of<catalog>();

/// Calls `f.template operator()<M>()` for the catalog machine M with `M::id == id`: the one
/// lookup of a machine by id. False, without calling `f`, when no catalog machine has that id.
template <class F>
constexpr bool with_machine(std::string_view id, F&& f) {
  bool found = false;
  for_each_machine([&]<class M>() {
    if (!found && M::id == id) {
      found = true;
      f.template operator()<M>();
    }
  });
  return found;
}

/// The model of the catalog machine with `M::id == id`, or null when no catalog machine has
/// that id: the one lookup of a machine *value* by id.
constexpr const machine_model* find_machine(std::string_view id) noexcept {
  const machine_model* found = nullptr;
  for_each_machine([&]<class M>() {
    if (!found && M::id == id) found = &M::model;
  });
  return found;
}

}  // namespace kin5::machines

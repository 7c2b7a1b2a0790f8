/// @file machines/every_machine.hpp
/// `every_machine`, the name the whole-machine chain gave the list of every bundled machine while
/// the catalog held only the papers' machines: now the catalog itself (catalog.hpp), kept so that
/// code written against it still reads. `for_each_machine_in<List>` folds over any such list.
/// @code
///   kin5::machines::for_each_machine_in<kin5::machines::every_machine>(
///       []<class M>() { std::cout << M::id << '\n'; });
/// @endcode
#pragma once

#include <tuple>

#include "catalog.hpp"

namespace kin5::machines {

/// Every bundled machine: the catalog, in the order `kin5 machines` lists them.
using every_machine = catalog;

/// Calls `f.template operator()<M>()` for each machine M of the type list `List`, in order.
template <class List, class F>
constexpr void for_each_machine_in(F&& f) {
  [&]<class... Ms>(std::tuple<Ms...>*) { (f.template operator()<Ms>(), ...); }(static_cast<List*>(nullptr));
}

}  // namespace kin5::machines

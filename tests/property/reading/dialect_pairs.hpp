/// @file dialect_pairs.hpp
/// The loop every per-pair reading law shares: `check_each_pair(sources, targets, property)` runs
/// `property(from, to)` as one RapidCheck property per ordered pair of dialects, named
/// `from -> to` in the report, and marks the Catch test case failed for each pair that fails.
/// `all_dialects()` lists every dialect of `kin5::program::dialects`, so a new dialect joins
/// every law that uses it. `pairs::distinct` skips a dialect paired with itself.
/// `fanuc_grammar(d)`: ISO or Haas, the readers that give offset registers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/dialect.hpp>

namespace kin5::test {

/// Every dialect of the type list, in its order.
inline std::vector<program::dialect> all_dialects() {
  std::vector<program::dialect> out;
  for (std::size_t i = 0; i < program::dialect_count; ++i) out.push_back(program::dialect{i});
  return out;
}

/// Whether dialect `d` is ISO or Haas, whose readers share the Fanuc grammar: `G43 H n`,
/// `G41 D n` with offset registers.
inline bool fanuc_grammar(program::dialect d) {
  return d == program::id_of<program::iso::dialect>() || d == program::id_of<program::haas::dialect>();
}

/// Whether a law pairs a dialect with itself.
enum class pairs { all, distinct };

/// Checks `property(from, to)` (a RapidCheck property body) for every `from` of `sources` and
/// `to` of `targets`; one named RapidCheck run and one Catch `CHECK` per pair.
template <class Property>
void check_each_pair(const std::vector<program::dialect>& sources, const std::vector<program::dialect>& targets,
                     Property property, pairs which = pairs::all) {
  for (const program::dialect from : sources)
    for (const program::dialect to : targets) {
      if (which == pairs::distinct && from == to) continue;
      const std::string name = std::string(program::name(from)) + " -> " + std::string(program::name(to));
      const bool ok = rc::check(name, [&property, from, to] { property(from, to); });
      CHECK(ok);
    }
}

}  // namespace kin5::test

/// @file example.hpp
/// Reading a hand-written example program in the dialect tests (`<name>/examples.cpp`):
/// `read_example<D>(text, file, count)`, for every entry D of the list.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "contract.hpp"

namespace kin5::test {

/// The blocks `text` reads as in dialect D from a file named `file`; the test stops unless it
/// reads without errors into exactly `count` blocks.
template <class D>
std::vector<program::block> read_example(std::string_view text, std::string file, std::size_t count) {
  program::read_result r = read_as<D>(text, std::move(file));
  for (const program::diagnostic& e : r.errors) UNSCOPED_INFO(e.to_string());
  REQUIRE(r.errors.empty());
  REQUIRE(r.parsed.blocks.size() == count);
  return std::move(r.parsed.blocks);
}

}  // namespace kin5::test

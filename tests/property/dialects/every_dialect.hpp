/// @file every_dialect.hpp
/// `for_every_dialect<Law>(name, tags)`: registers `Law<D>::check` as the Catch2 test case
/// "<D::name>: <name>" for every entry D of `program::dialects`, so a law is written once and
/// a new entry of the list is checked by every law with no edit to the suite. Used at namespace
/// scope: `const bool registered = for_every_dialect<my_law>("what it says", "[dialects]");`.
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>

#include <catch2/catch.hpp>

#include <kin5/program/dialect.hpp>

#include "contracts.hpp"

namespace kin5::test {

template <template <class> class Law>
bool for_every_dialect(const char* law, const char* tags) {
  program::for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t) {
    static_assert(has_contract<D>, "every dialect needs tests/property/dialects/<name>/contract.hpp");
    Catch::AutoReg(Catch::makeTestInvoker(&Law<D>::check), Catch::SourceLineInfo(__FILE__, __LINE__),
                   Catch::StringRef(), Catch::NameAndTags{std::string(D::name) + ": " + law, tags});
  });
  return true;
}

}  // namespace kin5::test

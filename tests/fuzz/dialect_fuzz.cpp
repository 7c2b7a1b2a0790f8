// libFuzzer target for one dialect of `program::dialects`, built once per entry of the list as
// `<name>_fuzz` (tests/fuzz/CMakeLists.txt passes the name as KIN5_FUZZ_DIALECT). Reading any
// bytes never crashes; a program read without errors is written (the writer may refuse only if
// the dialect's contract allows it), the text reads without errors, and — inside the writer's
// round-trip contract — it reads back as the same model, and writing it again is a fixed point.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <kin5/program/dialect.hpp>
#include <kin5/program/io.hpp>
#include <kin5/program/read_limits.hpp>

#include "../property/dialects/contracts.hpp"

namespace {

using D = kin5::program::KIN5_FUZZ_DIALECT::dialect;
using C = kin5::test::contract<D>;

template <class List>
struct listed;
template <class... E>
struct listed<std::tuple<E...>> : std::bool_constant<(std::is_same_v<D, E> || ...)> {};
static_assert(listed<kin5::program::dialects>::value, "KIN5_FUZZ_DIALECT names an entry of program::dialects");

bool same(const kin5::program::program& a, const kin5::program::program& b, const kin5::test::comparison& c) {
  return kin5::test::model_difference(a, b, c).empty();
}

/// `text` read by D within a bound of executed lines far below the tool's: an input that loops
/// for ever (libFuzzer finds `GOTOB`, `WHILE`, `o100 do` quickly) is refused in milliseconds
/// instead of running 10^8 lines, and its executed blocks stay few.
kin5::program::read_result read_as(std::string_view text) {
  static const kin5::program::read_limits limits = [] {
    kin5::program::read_limits l;
    l.max_executed_lines = 100'000;
    return l;
  }();
  return kin5::program::read(kin5::program::id_of<D>(), text, std::string(C::file), limits);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const kin5::program::read_result first = read_as(text);
  if (!first.ok()) return 0;
  std::string written;
  try {
    written = D::write(first.parsed, C::fuzz_options());
  } catch (const std::invalid_argument&) {
    if (C::writes_all_it_reads) __builtin_trap();
    return 0;  // a block the writer names as unwritable
  }
  const kin5::program::read_result second = read_as(written);
  if (!second.ok()) __builtin_trap();
  if (!C::round_trips(first.parsed)) return 0;
  if (!same(first.parsed, second.parsed, C::fuzz_read_back)) __builtin_trap();
  const kin5::program::read_result third = read_as(D::write(second.parsed, C::fuzz_options()));
  if (!same(second.parsed, third.parsed, C::fuzz_fixed_point)) __builtin_trap();
  return 0;
}

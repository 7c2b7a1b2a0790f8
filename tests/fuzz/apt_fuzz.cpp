// libFuzzer target for the APT reader and writer: reading never crashes, and whatever reads
// without errors writes and reads back to the same model (numbers within the written decimals).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include <kin5/program/apt/dialect.hpp>

#include "../property/program_apt/same_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kin5::program;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const read_result first = apt::read(text, "fuzz.cls");
  if (!first.ok()) return 0;
  std::string written;
  try {
    written = apt::write(first.parsed);
  } catch (const std::invalid_argument&) {
    __builtin_trap();  // everything the APT reader accepts has an APT form
  }
  const read_result second = apt::read(written, "fuzz.cls");
  if (!second.ok()) __builtin_trap();
  // Linear values are written with 3 decimals, vectors with 7, feeds with 1.
  if (!kin5::test::program_difference(first.parsed, second.parsed, 0.05).empty()) __builtin_trap();
  const read_result third = apt::read(apt::write(second.parsed), "fuzz.cls");
  if (!kin5::test::program_difference(second.parsed, third.parsed).empty()) __builtin_trap();
  return 0;
}

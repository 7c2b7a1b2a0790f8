// libFuzzer target for the ISO reader and writer: reading never crashes, and whatever reads
// without errors writes and reads back to the same model (numbers within the written decimals).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include <kin5/program/iso/dialect.hpp>

#include "../property/program_apt/same_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kin5::program;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const read_result first = iso::read(text, "fuzz.nc");
  if (!first.ok()) return 0;
  std::string written;
  try {
    written = iso::write(first.parsed);
  } catch (const std::invalid_argument&) {
    __builtin_trap();  // everything the ISO reader accepts has an ISO form
  }
  const read_result second = iso::read(written, "fuzz.nc");
  if (!second.ok()) __builtin_trap();
  // Linear and angle values are written with 3 decimals, vectors with 7, feeds with 1.
  if (!kin5::test::program_difference(first.parsed, second.parsed, 0.05).empty()) __builtin_trap();
  const read_result third = iso::read(iso::write(second.parsed), "fuzz.nc");
  if (!kin5::test::program_difference(second.parsed, third.parsed).empty()) __builtin_trap();
  return 0;
}

// libFuzzer target for the Siemens reader and writer: reading never crashes, and whatever reads
// without errors writes and reads back to the same model (numbers within the written decimals).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include <kin5/program/siemens/dialect.hpp>

#include "../property/program_siemens/model_difference.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kin5::program;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const read_result first = siemens::read(text, "fuzz.mpf");
  if (!first.ok()) return 0;
  // Six decimals everywhere: a value comes back within 5e-7, an arc centre within 1e-6.
  const siemens::write_options fine{6, 6, 6, 6};
  std::string written;
  try {
    written = siemens::write(first.parsed, fine);
  } catch (const std::invalid_argument&) {
    __builtin_trap();  // everything the reader accepts has a Siemens form
  }
  const read_result second = siemens::read(written, "fuzz.mpf");
  if (!second.ok()) __builtin_trap();
  if (!kin5::test::siemens_check::program_difference(first.parsed, second.parsed, 1e-6).empty()) __builtin_trap();
  // Once written, the text is a fixed point.
  const std::string again = siemens::write(second.parsed, fine);
  const read_result third = siemens::read(again, "fuzz.mpf");
  if (!kin5::test::siemens_check::program_difference(second.parsed, third.parsed, 1e-6).empty()) __builtin_trap();
  return 0;
}

// libFuzzer target for machine files (machines/machine_file.hpp): any bytes through
// `parse_machine_file` never crash (toml++ recursed once per part of a dotted key: the bounds of
// machines/toml_bounds.hpp now stop that before it parses); a file read without errors is
// written (`to_machine_file`), reads back without errors, and writing that again gives the same
// text: the writer's 17 digits keep every number bit for bit.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <kin5/machines/machine_file.hpp>
#include <kin5/machines/machine_file_writer.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const kin5::machine_file_result first = kin5::parse_machine_file(text, "fuzz.toml");
  if (first.ok() != first.errors.empty()) __builtin_trap();
  if (!first.ok()) return 0;
  const std::string written = kin5::to_machine_file(first.machine->model().geometry);
  const kin5::machine_file_result second = kin5::parse_machine_file(written, "written.toml");
  if (!second.ok()) __builtin_trap();  // the writer wrote what the reader refuses
  if (kin5::to_machine_file(second.machine->model().geometry) != written) __builtin_trap();
  return 0;
}

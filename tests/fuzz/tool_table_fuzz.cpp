// libFuzzer target for tool tables (machines/tool_table_file.hpp): any bytes through
// `parse_tool_table_file` never crash (the bounds of machines/toml_bounds.hpp stop nesting that
// would overflow toml++'s stack), and a table is returned exactly when no error is; every
// length in it is finite and 0 or more, as the file's rules say.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <kin5/machines/tool_table_file.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const kin5::tool_table_result r = kin5::parse_tool_table_file(text, "fuzz.toml");
  if (r.ok() != r.errors.empty()) __builtin_trap();
  if (!r.ok()) return 0;
  for (const auto& [number, entry] : r.table->entries) {
    if (number < 0 || !std::isfinite(entry.length_mm) || entry.length_mm < 0.0) __builtin_trap();
    if (entry.radius_mm && (!std::isfinite(*entry.radius_mm) || *entry.radius_mm < 0.0)) __builtin_trap();
  }
  return 0;
}

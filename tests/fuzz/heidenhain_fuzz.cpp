// libFuzzer target for the Heidenhain reader: any bytes must read without a crash, a program
// read without errors must write to a program that reads without errors, and — within the
// writer's round-trip contract (every L has coordinates) — survive write∘read unchanged (block
// numbers aside: the writer renumbers from 0).
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <string_view>

#include <kin5/program/heidenhain/dialect.hpp>

namespace {

// Written with 9 decimals: a value read back may differ by half a unit in the 9th decimal.
bool near(double a, double b) { return std::abs(a - b) <= 1e-9 + 1e-15 * std::abs(a); }
bool near(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || near(*a, *b));
}
bool near(const std::optional<kin5::vec3>& a, const std::optional<kin5::vec3>& b) {
  return a.has_value() == b.has_value() && (!a || (near(a->x, b->x) && near(a->y, b->y) && near(a->z, b->z)));
}

bool same(const kin5::program::block& a, const kin5::program::block& b) {
  auto body = [](const std::string& t) {
    std::size_t k = 0;
    while (k < t.size() && kin5::program::is_space(t[k])) ++k;
    std::size_t d = k;
    while (d < t.size() && kin5::program::is_digit(t[d])) ++d;
    if (d == k) return t.substr(k);
    while (d < t.size() && kin5::program::is_space(t[d])) ++d;
    return t.substr(d);
  };
  const bool arcs = a.arc.has_value() == b.arc.has_value() &&
                    (!a.arc || (a.arc->plane == b.arc->plane && near(a.arc->centre_mm, b.arc->centre_mm) &&
                                near(a.arc->radius_mm, b.arc->radius_mm)));
  return a.program_begin == b.program_begin && a.program_end == b.program_end && a.comment == b.comment &&
         a.tcp == b.tcp && a.feed_mode == b.feed_mode && a.metric == b.metric && a.tool == b.tool &&
         near(a.spindle_rpm, b.spindle_rpm) && a.m_codes == b.m_codes && a.motion == b.motion &&
         near(a.axes.x_mm, b.axes.x_mm) && near(a.axes.y_mm, b.axes.y_mm) && near(a.axes.z_mm, b.axes.z_mm) &&
         near(a.axes.a_deg, b.axes.a_deg) && near(a.axes.b_deg, b.axes.b_deg) && near(a.axes.c_deg, b.axes.c_deg) &&
         near(a.axes.tool_axis, b.axes.tool_axis) && arcs && near(a.feed, b.feed) && a.feed_rapid == b.feed_rapid &&
         a.machine_coordinates == b.machine_coordinates && a.kept_words == b.kept_words &&
         a.passthrough == b.passthrough && (!a.passthrough || body(a.text) == body(b.text));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace hh = kin5::program::heidenhain;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const kin5::program::read_result first = hh::read(text, "fuzz.h");
  if (!first.ok()) return 0;
  // Read values have at most the decimals written in the input; write with enough to keep them.
  const hh::write_options exact{9, 9, 9, 9};
  std::string written;
  try {
    written = hh::write(first.parsed, exact);
  } catch (const std::invalid_argument&) {
    return 0;  // a block the writer names as unwritable
  }
  const kin5::program::read_result second = hh::read(written, "fuzz.h");
  if (!second.ok()) __builtin_trap();
  // The writer's contract: an L without coordinates is never written as an L (its F and FMAX
  // move to the next move), so such programs are only required to write something readable.
  for (const auto& b : first.parsed.blocks)
    if (b.axes.empty() && !b.arc && (b.motion || b.feed_rapid)) return 0;
  if (second.parsed.blocks.size() != first.parsed.blocks.size()) __builtin_trap();
  for (std::size_t i = 0; i < first.parsed.blocks.size(); ++i)
    if (!same(first.parsed.blocks[i], second.parsed.blocks[i])) __builtin_trap();
  return 0;
}

/// @file translate/slide_travel.hpp
/// `slide_past_travel(to, slides_mm, placement)`: the linear slide (X, Y, Z) of machine `to`
/// farthest past its travel at `slides_mm`, if any is by more than the inverse's linear slack,
/// with what a translation reports: the slide, its value and excess, its travel, and the tool
/// length and work offset of `placement` that put it there.
/// @code
///   if (auto past = kin5::translate_detail::slide_past_travel(to, slides_mm, placement))
///     out.errors.push_back(at(b, "block unreachable on " + id + ": " + past->why));
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "../core/vec.hpp"
#include "../kinematics/forward.hpp"
#include "../kinematics/inverse.hpp"
#include "diagnostic_text.hpp"

namespace kin5::translate_detail {

/// A slide past its travel: the largest excess, mm, and what to say.
struct slide_excess {
  double excess_mm;
  std::string why;
};

/// The slide of `slides_mm` (X, Y, Z of `to`, mm) farthest past its travel, if any is by more
/// than `inverse_options::linear_slack_mm`; `placement` only names the inputs in the message.
inline std::optional<slide_excess> slide_past_travel(const machine_model& to, const vec3& slides_mm,
                                                     const run_inputs& placement) {
  const std::array<double, 3> x{slides_mm.x, slides_mm.y, slides_mm.z};
  std::size_t worst = 0;
  double excess = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
    if (const double e = to.linear(i).travel.excess_mm(x[i]); e > excess) excess = e, worst = i;
  if (!(excess > inverse_options{}.linear_slack_mm)) return std::nullopt;
  const linear_travel& t = to.linear(worst).travel;
  const char letter = to_char(to.linear(worst).letter);
  const vec3& offset_mm = placement.work_offset.translation_mm;
  return slide_excess{excess, std::string("slide ") + letter + "=" + fixed(x[worst], 3) + " mm, " + fixed(excess, 3) +
                                  " mm past its travel [" + fixed(t.lower_mm, 3) + ", " + fixed(t.upper_mm, 3) +
                                  "] mm (tool length " + fixed(placement.tool_length_mm, 3) + " mm, work offset " +
                                  fixed(offset_mm.x, 3) + "," + fixed(offset_mm.y, 3) + "," + fixed(offset_mm.z, 3) + ")"};
}

}  // namespace kin5::translate_detail

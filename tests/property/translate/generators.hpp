/// @file generators.hpp
/// RapidCheck generators for translation laws: angles within a machine's travel (uniform, away
/// from the limits), tool tips in a work cube, and short programs built from them.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <rapidcheck.h>

#include <kin5/kin5.hpp>

namespace kin5::test {

/// Uniform in [lo, hi] at every RapidCheck size.
inline rc::Gen<double> uniform(double lo, double hi) {
  constexpr std::int64_t steps = std::int64_t{1} << 40;
  return rc::gen::resize(100, rc::gen::map(rc::gen::inRange<std::int64_t>(0, steps + 1), [lo, hi](std::int64_t k) {
    return lo + (hi - lo) * (static_cast<double>(k) / static_cast<double>(steps));
  }));
}

/// A commanded angle of axis `a`, radians, uniform over its travel shrunk by `margin_deg` at
/// both ends (a continuous axis: uniform over a turn).
inline rc::Gen<radians> commanded(const rotary_axis& a, double margin_deg = 0.5) {
  if (a.travel.continuous) return rc::gen::map(uniform(-pi, pi), [](double v) { return radians{v}; });
  const double lo = a.travel.lower.value + margin_deg, hi = a.travel.upper.value - margin_deg;
  return rc::gen::map(uniform(lo, hi), [](double v) { return to_radians(degrees{v}); });
}

/// Commanded angles of machine M within its travel.
template <machine M>
rc::Gen<rotary_angles<M>> angles_within(double margin_deg = 0.5) {
  if constexpr (rotary_count<M> == 2) {
    return rc::gen::apply([](radians a, radians b) { return rotary_angles<M>{a, b}; },
                          commanded(M::rotary[0], margin_deg), commanded(M::rotary[1], margin_deg));
  } else {
    return rc::gen::map(commanded(M::rotary[0], margin_deg), [](radians a) { return rotary_angles<M>{a}; });
  }
}

/// A tool tip in a 400 mm cube about the workpiece origin, millimetres.
inline rc::Gen<vec3> tip() {
  return rc::gen::apply([](double x, double y, double z) { return vec3{x, y, z}; }, uniform(-200, 200),
                        uniform(-200, 200), uniform(-200, 200));
}

/// One motion of machine M: tip and commanded angles.
template <machine M>
struct pose {
  vec3 tip_mm{};
  rotary_angles<M> angles{};
};

template <machine M>
rc::Gen<pose<M>> pose_within(double margin_deg = 0.5) {
  return rc::gen::apply([](vec3 t, rotary_angles<M> a) { return pose<M>{t, a}; }, tip(), angles_within<M>(margin_deg));
}

/// 1 to `max` poses of M.
template <machine M>
rc::Gen<std::vector<pose<M>>> path_within(std::size_t max, double margin_deg = 0.5) {
  return rc::gen::mapcat(rc::gen::inRange<std::size_t>(1, max + 1), [margin_deg](std::size_t n) {
    return rc::gen::container<std::vector<pose<M>>>(n, pose_within<M>(margin_deg));
  });
}

/// Axis words of M's commanded angles (degrees) in a block.
template <machine M>
void set_rotary_words(program::axis_words& w, const rotary_angles<M>& angles) {
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const double deg = to_degrees(angles[i]).value;
    switch (M::rotary[i].letter) {
      case axis_letter::A: w.a_deg = deg; break;
      case axis_letter::B: w.b_deg = deg; break;
      default: w.c_deg = deg; break;
    }
  }
}

/// M's commanded angles (radians) read back from a block's words; 0 for a missing word.
template <machine M>
rotary_angles<M> rotary_of(const program::axis_words& w) {
  rotary_angles<M> out{};
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const auto& word = M::rotary[i].letter == axis_letter::A ? w.a_deg
                       : M::rotary[i].letter == axis_letter::B ? w.b_deg
                                                               : w.c_deg;
    out[i] = to_radians(degrees{word.value_or(0.0)});
  }
  return out;
}

}  // namespace kin5::test

/// @file generators.hpp
/// RapidCheck generators for translation laws: tool tips in a work cube, and short programs
/// built from them and from angles within a machine's travel (`angle_generators.hpp`).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <rapidcheck.h>

#include <kin5/kin5.hpp>

#include "../branch_plan/angle_generators.hpp"

namespace kin5::test {

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

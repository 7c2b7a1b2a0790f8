/// @file angle_generators.hpp
/// RapidCheck generators of commanded rotary angles: uniform over an axis' travel (away from its
/// limits) and per machine. Kinematics only: no program or translation header.
#pragma once

#include <cstddef>
#include <cstdint>

#include <rapidcheck.h>

#include <kin5/kinematics.hpp>

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

/// Commanded angles of M within travel, its continuous axes up to two whole turns either way;
/// with `poles`, one time in four at a pole of M (when one lies within travel), its free angle
/// kept random. Drawn inside a property (`*` on generators).
template <machine M>
rotary_angles<M> angles_with_turns(bool poles) {
  rotary_angles<M> a = *angles_within<M>(0.5);
  if constexpr (rotary_count<M> == 2) {
    if (poles && *rc::gen::inRange(0, 4) == 0) {
      const vec3 p = (*rc::gen::arbitrary<bool>() ? 1.0 : -1.0) * M::model.orientation.p;
      for (const auto& s : inverse<M>(p))
        if (s.within_travel) {
          a[1] = s.angles[1];
          break;
        }
    }
  }
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    if (M::rotary[i].travel.continuous) a[i].value += 2.0 * pi * *rc::gen::inRange(-2, 3);
  return a;
}

}  // namespace kin5::test

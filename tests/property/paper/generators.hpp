// Generators for the paper identities: angles in a range, unit vectors, draws near poles and
// region boundaries. RapidCheck's integer `inRange` is mapped onto doubles at full size, so
// every draw covers the whole interval.
#pragma once

#include <cmath>
#include <cstdint>
#include <ostream>

#include <Eigen/Geometry>
#include <rapidcheck.h>

#include <kin5/core/vec.hpp>

namespace kin5 {
// Lets RapidCheck print a failing vector (found by argument-dependent lookup).
inline void showValue(const vec3& v, std::ostream& os) {
  os.precision(17);
  os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}
}  // namespace kin5

namespace paper_test {

/// Uniform double in [lo, hi], 2^40 steps.
inline rc::Gen<double> uniform(double lo, double hi) {
  constexpr std::int64_t steps = std::int64_t{1} << 40;
  return rc::gen::map(rc::gen::resize(100, rc::gen::inRange<std::int64_t>(0, steps + 1)), [lo, hi](std::int64_t k) {
    return lo + (hi - lo) * (static_cast<double>(k) / static_cast<double>(steps));
  });
}

/// A positive distance log-uniform in [10^lo_exp, 10^hi_exp], for draws near a pole or a limit.
inline rc::Gen<double> log_uniform(double lo_exp, double hi_exp) {
  return rc::gen::map(uniform(lo_exp, hi_exp), [](double e) { return std::pow(10.0, e); });
}

/// An angle in (centre − max_offset, centre + max_offset), offsets log-uniform down to 1e-7·max,
/// on both sides: points close to a pole or a region boundary.
inline rc::Gen<double> near(double centre, double max_offset) {
  return rc::gen::apply(
      [centre, max_offset](double magnitude, bool above) { return centre + (above ? 1.0 : -1.0) * max_offset * magnitude; },
      log_uniform(-7.0, 0.0), rc::gen::arbitrary<bool>());
}

/// Uniform unit vector on the sphere.
inline rc::Gen<kin5::vec3> unit_vector() {
  return rc::gen::apply(
      [](double z, double phi) {
        const double r = std::sqrt(1.0 - z * z);
        return kin5::vec3{r * std::cos(phi), r * std::sin(phi), z};
      },
      uniform(-1.0, 1.0), uniform(-M_PI, M_PI));
}

/// Unit vector with z in [z_lo, z_hi] (uniform in z, so uniform in area).
inline rc::Gen<kin5::vec3> unit_vector_z_between(double z_lo, double z_hi) {
  return rc::gen::apply(
      [](double z, double phi) {
        const double r = std::sqrt(1.0 - z * z);
        return kin5::vec3{r * std::cos(phi), r * std::sin(phi), z};
      },
      uniform(z_lo, z_hi), uniform(-M_PI, M_PI));
}

/// Unit vector at an angle log-uniform in [1e-7, 1]·max_angle_rad from the unit vector `axis`,
/// in a uniformly random direction: draws near a pole.
inline rc::Gen<kin5::vec3> near_direction(kin5::vec3 axis, double max_angle_rad) {
  return rc::gen::apply(
      [axis, max_angle_rad](double fraction, double phi) {
        const kin5::vec3 helper = std::fabs(axis.x) < 0.9 ? kin5::unit_x : kin5::unit_y;
        const kin5::vec3 e1 = kin5::normalized(kin5::cross(axis, helper));
        const kin5::vec3 e2 = kin5::cross(axis, e1);
        const double theta = max_angle_rad * fraction;
        return std::cos(theta) * axis + std::sin(theta) * (std::cos(phi) * e1 + std::sin(phi) * e2);
      },
      log_uniform(-7.0, 0.0), uniform(-M_PI, M_PI));
}

inline double max_abs_diff(const kin5::vec3& a, const kin5::vec3& b) {
  return std::fmax(std::fabs(a.x - b.x), std::fmax(std::fabs(a.y - b.y), std::fabs(a.z - b.z)));
}

/// |a − b| modulo 360°, in [0°, 180°].
inline double angle_diff_deg(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

inline constexpr double deg = M_PI / 180.0;

/// Tolerance in degrees for an angle recovered by a formula whose conditioning degrades as
/// `distance_rad` (the distance to its pole or reach limit) shrinks: an argument rounded by
/// ~1e-16 near ±1 of arccos/arcsin, or an azimuth about a pole at that distance, is fixed only
/// to about 1e-16/distance radians. 2e-13 degrees = 3.5e-15 radians leaves a factor ~16.
inline double conditioned_tol_deg(double distance_rad, double base_deg = 1e-9) {
  return base_deg + 2e-13 / distance_rad;
}

/// Independent oracle: R(n, θ) from Eigen's angle-axis, θ in degrees.
inline kin5::vec3 eigen_rotate(const kin5::vec3& n, double theta_deg, const kin5::vec3& v) {
  const Eigen::Vector3d r = Eigen::AngleAxisd(theta_deg * deg, Eigen::Vector3d(n.x, n.y, n.z).normalized()) *
                            Eigen::Vector3d(v.x, v.y, v.z);
  return {r.x(), r.y(), r.z()};
}

inline kin5::radians rad(double degrees_value) { return kin5::radians{degrees_value * deg}; }
inline double to_deg(kin5::radians r) { return r.value / deg; }

}  // namespace paper_test

// math.hpp: the constexpr series (kin5::math::detail) against <cmath>, special values, and the
// angle wrapping helpers.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/core/math.hpp>

#include "generators.hpp"

namespace {

namespace d = kin5::math::detail;
using kin5::pi;

/// Distance in units in the last place of `reference`, at least one ulp of `floor` so that
/// results near zero (where only an absolute error is meaningful) are measured against it.
double ulps(double value, double reference, double floor = 0.0) {
  const double scale = std::max(std::abs(reference), floor);
  const double ulp = std::nextafter(scale, std::numeric_limits<double>::infinity()) - scale;
  return std::abs(value - reference) / ulp;
}

}  // namespace

TEST_CASE("constexpr series agree with <cmath>", "[core][math]") {
  rc::prop("sin, cos on [-2pi, 2pi]: within 4 ulp (absolute near zero)", [] {
    const double x = *kin5::test::real_in(-2 * pi, 2 * pi);
    RC_ASSERT(ulps(d::sin(x), std::sin(x), 0.25) <= 4.0);
    RC_ASSERT(ulps(d::cos(x), std::cos(x), 0.25) <= 4.0);
  });
  rc::prop("sin, cos up to |x| = 1e6: error within a few ulp of x's reduction", [] {
    const double x = *rc::gen::oneOf(kin5::test::real_in(-1e6, 1e6), kin5::test::real_in(-1e3, 1e3));
    // Reducing x by multiples of pi/2 is exact in the ideal; a double x carries ulp(x)/2 of
    // representation error that no implementation removes, so compare at that scale.
    const double floor = std::max(0.25, std::abs(x) * 1e-3);
    RC_LOG() << "x = " << x << ", sin " << d::sin(x) << " vs " << std::sin(x) << "\n";
    RC_ASSERT(ulps(d::sin(x), std::sin(x), floor) <= 4.0);
    RC_ASSERT(ulps(d::cos(x), std::cos(x), floor) <= 4.0);
  });
  rc::prop("sin near small arguments keeps relative precision", [] {
    const double x = *kin5::test::log_uniform(-300.0, -1.0) * (*rc::gen::arbitrary<bool>() ? 1.0 : -1.0);
    RC_ASSERT(ulps(d::sin(x), std::sin(x)) <= 2.0);
    RC_ASSERT(ulps(d::cos(x), std::cos(x)) <= 2.0);
  });
  rc::prop("sqrt over many decades: within 1 ulp", [] {
    const double x = *kin5::test::log_uniform(-300.0, 300.0);
    RC_ASSERT(ulps(d::sqrt(x), std::sqrt(x)) <= 1.0);
  });
  rc::prop("atan2 over the plane and across decades: within 4 ulp", [] {
    const double r = *kin5::test::log_uniform(-100.0, 100.0);
    const double phi = *kin5::test::real_in(-pi, pi);
    const double y = r * std::sin(phi), x = r * std::cos(phi);
    RC_ASSERT(ulps(d::atan2(y, x), std::atan2(y, x), 1e-300) <= 4.0);
  });
  rc::prop("asin, acos through atan2 on [-1, 1]: within 4 ulp of <cmath> (absolute near 0)", [] {
    const double x = *kin5::test::real_in(-1.0, 1.0);
    RC_ASSERT(ulps(kin5::math::asin(x), std::asin(x), 0.25) <= 4.0);
    RC_ASSERT(ulps(kin5::math::acos(x), std::acos(x), 0.25) <= 4.0);
  });
}

TEST_CASE("constexpr series: special values", "[core][math]") {
  CHECK(d::sin(0.0) == 0.0);
  CHECK(d::cos(0.0) == 1.0);
  CHECK(d::sin(pi / 2) == 1.0);
  CHECK(d::cos(pi) == -1.0);
  CHECK(std::abs(d::cos(pi / 2)) <= 1e-16);  // cos of the double nearest pi/2 is 6.1e-17
  CHECK(std::abs(d::sin(pi)) <= 2e-16);
  CHECK(std::abs(d::sin(-pi / 2) + 1.0) == 0.0);
  CHECK(ulps(d::sin(pi / 6), 0.5) <= 2.0);
  CHECK(ulps(d::cos(pi / 3), 0.5) <= 2.0);
  CHECK(ulps(d::sin(pi / 4), std::sqrt(0.5)) <= 2.0);
  CHECK(ulps(d::sin(1e6), std::sin(1e6), 1e6 * 1e-3) <= 4.0);
  CHECK(ulps(d::cos(-1e6), std::cos(-1e6), 1e6 * 1e-3) <= 4.0);

  CHECK(d::atan2(0.0, 0.0) == 0.0);
  CHECK(d::atan2(0.0, 1.0) == 0.0);
  CHECK(d::atan2(1.0, 0.0) == pi / 2);
  CHECK(d::atan2(-1.0, 0.0) == -pi / 2);
  CHECK(d::atan2(0.0, -1.0) == pi);
  CHECK(ulps(d::atan2(1.0, 1.0), pi / 4) <= 1.0);
  CHECK(ulps(d::atan2(-1.0, -1.0), -3 * pi / 4) <= 1.0);
  CHECK(ulps(d::atan2(1.0, std::sqrt(3.0)), pi / 6) <= 2.0);

  CHECK(d::sqrt(0.0) == 0.0);
  CHECK(d::sqrt(1.0) == 1.0);
  CHECK(d::sqrt(4.0) == 2.0);
  CHECK(ulps(d::sqrt(2.0), 1.4142135623730951) <= 1.0);
  CHECK(std::isnan(d::sqrt(-1.0)));
  CHECK(d::sqrt(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());

  CHECK(kin5::math::asin(1.0) == pi / 2);
  CHECK(kin5::math::asin(-1.0) == -pi / 2);
  CHECK(kin5::math::acos(-1.0) == pi);
  CHECK(kin5::math::acos(1.0) == 0.0);
}

TEST_CASE("wrap_pi and unwrap_near", "[core][math]") {
  rc::prop("wrap_pi lands in (-pi, pi] and is congruent modulo 2pi", [] {
    const double x = *rc::gen::oneOf(kin5::test::real_in(-1e4, 1e4), kin5::test::real_in(-7.0, 7.0),
                                     rc::gen::map(rc::gen::inRange(-50, 51), [](int k) { return k * pi; }));
    const double w = kin5::math::wrap_pi(x);
    RC_ASSERT(w > -pi);
    RC_ASSERT(w <= pi);
    RC_ASSERT(std::abs(std::remainder(w - x, 2 * pi)) <= 1e-12 * std::max(1.0, std::abs(x)));
  });
  CHECK(kin5::math::wrap_pi(pi) == pi);
  CHECK(kin5::math::wrap_pi(-pi) == pi);
  CHECK(kin5::math::wrap_pi(3 * pi) == pi);
  CHECK(kin5::math::wrap_pi(0.0) == 0.0);
  rc::prop("unwrap_near: within pi of the reference, congruent to a", [] {
    const double a = *kin5::test::real_in(-100, 100), ref = *kin5::test::real_in(-100, 100);
    const double u = kin5::math::unwrap_near(kin5::radians{a}, kin5::radians{ref}).value;
    RC_ASSERT(std::abs(u - ref) <= pi + 1e-12);
    RC_ASSERT(std::abs(std::remainder(u - a, 2 * pi)) <= 1e-12);
  });
}

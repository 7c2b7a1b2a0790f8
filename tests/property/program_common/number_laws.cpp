// NC numbers: `read_number` reads the longest `[+-]digits[.digits]` (at least one digit) at the
// start of any text, with the value strtod gives for it; `append_number` writes what
// `std::to_chars` writes, trimmed, and reads back to the value rounded to its decimals;
// `rate_decimals` writes a feed or speed other than 0 within 0.5 %, never as 0, or refuses it.
#include <algorithm>
#include <bit>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/number.hpp>

namespace {

using namespace kin5::program;

/// The reference reader: scan the grammar by hand, then let strtod convert.
parsed_number reference(std::string_view s) {
  parsed_number out{};
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) {
    out.error = i == 0 ? number_error::empty : number_error::not_a_number;
    return out;
  }
  const std::string text(s.substr(0, i));
  const double v = std::strtod(text.c_str(), nullptr);
  if (std::abs(v) > max_magnitude) {
    out.error = number_error::too_large;
    return out;
  }
  out.value = v;
  out.length = i;
  return out;
}

rc::Gen<std::string> nc_text() {
  return rc::gen::container<std::string>(rc::gen::element('0', '1', '5', '9', '.', '+', '-', 'e', 'E', 'X', ' ', ';'));
}

}  // namespace

TEST_CASE("read_number reads the NC number grammar with strtod's value") {
  std::setlocale(LC_NUMERIC, "C");
  rc::prop("any text over digits, points, signs and neighbours", [] {
    const std::string s = *nc_text();
    const parsed_number got = read_number(s), want = reference(s);
    RC_ASSERT(got.error == want.error);
    RC_ASSERT(got.length == want.length);
    if (got.error == number_error::none) RC_ASSERT(got.value == want.value);
  });
  rc::prop("numbers as CAM writes them, with trailing and leading points", [] {
    const long long whole = *rc::gen::inRange<long long>(0, 1000000000);
    const int decimals = *rc::gen::inRange(0, 10);
    std::string s = (*rc::gen::arbitrary<bool>() ? "-" : "") + std::to_string(whole) + ".";
    for (int k = 0; k < decimals; ++k) s += static_cast<char>('0' + *rc::gen::inRange(0, 10));
    const parsed_number got = read_number(s), want = reference(s);
    RC_ASSERT(got.error == want.error);
    RC_ASSERT(got.length == want.length);
    RC_ASSERT(got.value == want.value);
  });
}

namespace {

/// What `append_number` must write: `std::to_chars`' fixed digits, trailing zeros and point
/// removed, "-0" as "0".
std::string to_chars_trimmed(double v, int decimals) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string want(buf, r.ptr);
  if (want.find('.') != std::string::npos) {
    while (want.back() == '0') want.pop_back();
    if (want.back() == '.') want.pop_back();
  }
  if (want == "-0") want = "0";
  return want;
}

/// Values as programs hold them (up to 1e5, and up to 2^31 / 10^d or 1e9), and the ones whose rounding
/// is a tie or next to one: halves of the last place, binary fractions, and their neighbours.
rc::Gen<double> nc_scale_double(int decimals) {
  const double unit = std::pow(10.0, -decimals);
  return rc::gen::resize(100, rc::gen::oneOf(  // the whole range at every size
      rc::gen::map(rc::gen::inRange<long long>(-100000000000, 100000000000),
                   [](long long n) { return static_cast<double>(n) * 1e-6; }),
      rc::gen::map(rc::gen::arbitrary<double>(), [=](double x) { return std::isfinite(x) ? std::fmod(x, std::min(max_magnitude, 2147483648.0 * unit)) : 0.0; }),
      rc::gen::map(rc::gen::pair(rc::gen::inRange<long long>(-2000000, 2000000), rc::gen::inRange(-2, 3)),
                   [=](std::pair<long long, int> p) {
                     double v = (static_cast<double>(p.first) + 0.5) * unit;  // a half of the last place
                     for (int k = 0; k < std::abs(p.second); ++k) v = std::nextafter(v, p.second > 0 ? 1e300 : -1e300);
                     return v;
                   }),
      rc::gen::map(rc::gen::pair(rc::gen::inRange<long long>(-1000000, 1000000), rc::gen::inRange(1, 40)),
                   [](std::pair<long long, int> p) { return std::ldexp(static_cast<double>(p.first), -p.second); }),
      rc::gen::element(0.0, -0.0, -1e-300, 1e-300, 0.5, -0.5, 999999999.5, -999999999.5, 1e9, -1e9)));
}

}  // namespace

TEST_CASE("append_number writes to_chars' digits, trimmed, and reads back") {
  rc::prop("values as programs hold them and next to ties, 0 to 12 decimals", [] {
    const int decimals = *rc::gen::resize(100, rc::gen::inRange(0, 13));
    const double v = *nc_scale_double(decimals);
    std::string got;
    append_number(got, v, decimals);
    RC_ASSERT(got == to_chars_trimmed(v, decimals));
    std::string plus;
    append_number(plus, v, decimals, true);
    RC_ASSERT(plus == (got.front() == '-' ? got : "+" + got));
  });
  rc::prop("finite values up to 1e9, 0 to 6 decimals", [] {
    const double v = *rc::gen::map(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x) ? std::fmod(x, 1e9) : 0.0; });
    const int decimals = *rc::gen::inRange(0, 7);
    std::string got;
    append_number(got, v, decimals);
    const std::string want = to_chars_trimmed(v, decimals);
    RC_ASSERT(got == want);
    const parsed_number back = read_number(got);
    RC_ASSERT(back.length == got.size());
    RC_ASSERT(std::abs(back.value - v) <= 0.5 * std::pow(10.0, -decimals) * (1 + 1e-9) + 1e-9 * std::abs(v));
    std::string plus;
    append_number(plus, v, decimals, true);
    RC_ASSERT(plus == (want.front() == '-' ? want : "+" + want));
  });
}

namespace {

/// Any double, by its bits: huge, tiny, subnormal, ±0, ±inf and NaNs with any payload included.
rc::Gen<double> any_bits_double() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [](std::uint64_t bits) { return std::bit_cast<double>(bits); }),
      rc::gen::element(0.0, -0.0, max_magnitude, -max_magnitude, std::nextafter(max_magnitude, 2e9),
                       std::nextafter(-max_magnitude, -2e9), 999999999.99999994, 1e62, 1e100, 1e300,
                       std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                       std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                       -std::numeric_limits<double>::denorm_min(), 1e-80, std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
                       -std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::signaling_NaN()),
      rc::gen::map(rc::gen::arbitrary<double>(), [](double x) { return x * 1e9; }));
}

}  // namespace

TEST_CASE("append_number, for every double: the NC number read_number reads back, or a refusal with nothing written") {
  rc::prop("any bits, any decimals", [] {
    const double v = *any_bits_double();
    const int decimals = *rc::gen::inRange(-3, 20);
    const bool plus = *rc::gen::arbitrary<bool>();
    std::string out = "X";
    bool refused = false;
    try {
      append_number(out, v, decimals, plus);
    } catch (const number_out_of_range&) {
      refused = true;
    }
    const bool holdable = std::isfinite(v) && std::abs(v) <= max_magnitude;
    RC_ASSERT(refused == !holdable);
    if (refused) {
      RC_ASSERT(out == "X");
      return;
    }
    // What was written is one whole NC number, the value rounded to the clamped decimals.
    const std::string text = out.substr(1);
    const parsed_number back = read_number(text);
    RC_ASSERT(back.error == number_error::none);
    RC_ASSERT(back.length == text.size());
    const int d = std::clamp(decimals, 0, 12);
    RC_ASSERT(std::abs(back.value - v) <= 0.5 * std::pow(10.0, -d) * (1 + 1e-9) + 1e-15 * std::abs(v));
    for (char c : text) RC_ASSERT((is_digit(c) || c == '.' || c == '-' || c == '+'));
    RC_ASSERT(text.size() <= 25);
  });
}

TEST_CASE("rate_decimals: a rate other than 0 is written within 0.5 % and never as 0, or refused") {
  rc::prop("rates of either sign from 1e-12 to 1e9, 0 to 3 decimals asked, 0 to 12 the finest", [] {
    const double v = *rc::gen::element(1.0, -1.0) * std::pow(10.0, *rc::gen::inRange(-12'000'000, 9'000'001) / 1e6);
    const int decimals = *rc::gen::inRange(0, 4);
    const int finest = *rc::gen::inRange(0, 13);
    const double error_at_finest = std::abs(read_number(format_number(v, std::max(decimals, finest))).value - v);
    int d = 0;
    try {
      d = rate_decimals(v, decimals, finest);
    } catch (const number_out_of_range&) {
      // Refused only when the finest decimals the controller reads cannot write it within 0.5 %.
      RC_ASSERT(error_at_finest > 0.005 * std::abs(v) * (1 - 1e-9));
      return;
    }
    RC_ASSERT(d >= decimals);
    RC_ASSERT(d <= std::max(decimals, finest));
    const std::string s = format_number(v, d);
    const parsed_number back = read_number(s);
    RC_ASSERT(back.length == s.size());
    RC_ASSERT(back.value != 0.0);
    RC_ASSERT((back.value > 0.0) == (v > 0.0));
    RC_ASSERT(std::abs(back.value - v) <= 0.005 * std::abs(v) * (1 + 1e-9));
    // More decimals than asked only where three significant digits need them.
    if (d > decimals) RC_ASSERT(std::abs(v) < std::pow(10.0, 3 - d) * (1 + 1e-9));
  });
  CHECK(format_number(0.02, rate_decimals(0.02, 1, 3)) == "0.02");  // 1000 mm at F20, inverse time
  CHECK(format_number(0.04, rate_decimals(0.04, 1, 3)) == "0.04");
  CHECK(format_number(5.25, rate_decimals(5.25, 1, 3)) == "5.25");
  CHECK(format_number(1091.26, rate_decimals(1091.26, 1, 3)) == "1091.3");
  CHECK(format_number(0.0, rate_decimals(0.0, 1, 3)) == "0");
  CHECK(format_number(0.0004, rate_decimals(0.0004, 1, 6)) == "0.0004");
  CHECK_THROWS_AS(rate_decimals(0.0004, 1, 3), number_out_of_range);  // F0 at 3 decimals
  CHECK_THROWS_AS(rate_decimals(0.0016, 1, 3), number_out_of_range);  // F0.002: 25 % off
}

// An independent oracle for LinuxCNC expressions: LinuxCNC's own interpreter, rs274 (Debian's
// linuxcnc-uspace), run standalone (`rs274 -g FILE`) on a generated program that assigns each
// random expression to a parameter and feeds to it: its STRAIGHT_FEED gives the value it
// computed. rs274 prints 4 decimals, so each value v goes out as three words: X v, Y the whole
// part of v·10⁴, Z the rest times 10⁵; that is v to about 1e-13. kin5's value must agree within
// 1e-9 (relative above 1), and where kin5 refuses an expression rs274 must stop with an error.
// Where the two are known to differ (trigonometry at exact multiples of 90° and of huge angles,
// model.hpp `trig_differs_from_radians`; ROUND past 2³¹, `round_overflows_int`; ASIN and ACOS
// next to ±1, where one bit of rounding is 1e-6°, `inverse_trig_near_end`; MOD of 10⁶ or more,
// `remainder_of_large`;
// docs/dialects/linuxcnc.md) the expression is left out.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/interp/evaluate.hpp>
#include <kin5/program/linuxcnc/expression.hpp>
#include <kin5/program/linuxcnc/parameter_rules.hpp>

#include "model.hpp"

namespace {

using namespace kin5::program;
using interp_model::spelling;

struct run_output {
  std::string text;
  int status = 0;
  std::vector<std::array<double, 3>> feeds;  // X Y Z of each STRAIGHT_FEED
};

run_output run_rs274(const std::string& program) {
  static int count = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const std::string file = (dir / ("kin5-rs274-" + std::to_string(::getpid()) + "-" + std::to_string(count++) + ".ngc")).string();
  std::ofstream(file) << program;
  run_output out;
  const std::string command = std::string(KIN5_RS274) + " -g " + file + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) {
    out.text += buffer;
    const std::string line = buffer;
    if (const auto k = line.find("STRAIGHT_FEED("); k != std::string::npos) {
      std::array<double, 3> v{};
      if (std::sscanf(line.c_str() + k, "STRAIGHT_FEED(%lf, %lf, %lf", &v[0], &v[1], &v[2]) == 3) out.feeds.push_back(v);
    }
  }
  out.status = ::pclose(pipe);
  std::filesystem::remove(file);
  return out;
}

std::string assignments(const interp_model::parameters& p) {
  std::string out;
  for (int k = 0; k < 5; ++k) out += interp_model::parameter_text(spelling::linuxcnc, k) + " = " + interp_model::fixed3(p.values[k]) + "\n";
  return out;
}

interp::parameter_store store_of(const interp_model::parameters& p) {
  interp::parameter_store s(linuxcnc::parameter_rules());
  const interp::parameter_key keys[] = {{"#", 1}, {"#", 31}, {"", 0, "#<depth>"}, {"", 0, "#<_rate>"}, {"#", 4999}};
  for (int k = 0; k < 5; ++k) s.assign(keys[k], std::round(p.values[k] * 1000) / 1000);
  return s;
}

}  // namespace

TEST_CASE("LinuxCNC expressions: kin5 computes what rs274 computes") {
  rc::prop("a batch of random expressions per program, then one kin5 refuses", [] {
    interp_model::parameters p{};
    for (double& v : p.values) v = *rc::gen::inRange(-50000, 50000) / 1000.0;
    const interp::parameter_store store = store_of(p);
    std::string program = assignments(p);
    program += "F100\n";  // appended, not `+`: GCC 12 warns falsely (-Wrestrict) on that
    std::vector<std::pair<std::string, double>> expected;
    std::string refused, why;  // the first expression kin5 refuses, if one is drawn, and why
    for (int i = 0; i < 40; ++i) {
      const interp_model::tree t = interp_model::draw(spelling::linuxcnc, *rc::gen::inRange(1, 6));
      if (interp_model::trig_differs_from_radians(spelling::linuxcnc, t, p) ||
          interp_model::round_overflows_int(spelling::linuxcnc, t, p) ||
          interp_model::inverse_trig_near_end(spelling::linuxcnc, t, p) ||
          interp_model::remainder_of_large(spelling::linuxcnc, t, p))
        continue;
      std::string text = "[";
      text += interp_model::print(spelling::linuxcnc, t);
      text += "]";
      const parsed_expression e = linuxcnc::read_value(text);
      RC_ASSERT(e.ok());
      const interp::evaluation v = interp::evaluate(e.tree, store);
      if (!v.ok()) {
        if (refused.empty()) refused = text, why = v.error->message;
        continue;
      }
      if (std::abs(v.value) >= 1e5) continue;
      program += "#100 = " + text + "\nG1 X#100 Y[fix[#100*10000]] Z[[#100*10000 - fix[#100*10000]]*100000]\n";
      expected.emplace_back(text, v.value);
    }
    // rs274 checks for infinity and NaN only where a bracket closes, so a comparison in the same
    // brackets may absorb one ([10**400 GT 1] is 1); kin5 refuses it where it arises.
    const bool absorbed = why.find("overflows") != std::string::npos || why.find("not a number") != std::string::npos ||
                          why == "remainder of a division by zero" || why == "zero raised to a negative power";
    if (!refused.empty() && !absorbed) program += "#100 = " + refused + "\nG1 X#100\n";
    program += "M2\n";
    const run_output r = run_rs274(program);
    RC_LOG() << program << "\n--- rs274:\n" << r.text << "\n";
    if (!refused.empty()) RC_LOG() << "refused by kin5: " << refused << " (" << why << ")\n";
    RC_ASSERT(r.feeds.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const auto& f = r.feeds[k];
      const double theirs = (f[1] + f[2] / 1e5) / 1e4;
      const double ours = expected[k].second;
      RC_LOG() << expected[k].first << ": kin5 " << ours << ", rs274 " << theirs << "\n";
      RC_ASSERT(std::abs(f[0] - ours) <= 5.1e-5 * std::max(1.0, std::abs(ours)));
      RC_ASSERT(std::abs(theirs - ours) <= 1e-9 * std::max(1.0, std::abs(ours)));
    }
    RC_ASSERT((r.status != 0) == (!refused.empty() && !absorbed));  // rs274 stops at the refused one
  });
}

TEST_CASE("LinuxCNC expressions at the edges: kin5 computes what rs274 computes") {
  // signs, levels, the EQ tolerance's edge, rounding of negatives, indirection, EXISTS, ATAN's quadrants
  const char* const cases[] = {
      "[-2**2]",          "[2**3**2]",          "[2*-3**2]",          "[2**-2]",          "[0 OR 1 AND 0]",
      "[1 + 2 EQ 3.00009]", "[1 EQ 1.0001]",    "[0 EQ 0.0001]",      "[1 NE 1.00005]",   "[1 GE 1.00001]",
      "[-7 MOD 3]",       "[7 MOD -3]",         "[7.5 MOD 2]",        "[fix[-0.5]]",      "[fup[-0.5]]",
      "[round[-2.5]]",    "[round[2.5]]",       "[fix[2.999]]",       "[#[1.00005]]",     "[##2]",
      "[exists[#<nope>]]", "[exists[#<_rate>]]", "[atan[1]/[-1]]",    "[atan[-1]/[-1]]",  "[atan[0]/[0]]",
      "[asin[-1]]",       "[acos[-1]]",         "[sqrt[2] * sqrt[2]]", "[ln[exp[2.5]]]",  "[1 XOR 1 + 1]",
      "[3 - 2 - 1]",      "[12 / 3 / 2]",       "[sin[30] + cos[60]]", "[tan[45.5]]",     "[abs[-3] ** 0.5]",
  };
  interp::parameter_store store(linuxcnc::parameter_rules());
  REQUIRE_FALSE(store.assign({"#", 1}, 7));
  REQUIRE_FALSE(store.assign({"#", 2}, 1));
  REQUIRE_FALSE(store.assign({"", 0, "#<_rate>"}, 100));
  std::string program = "#1 = 7\n#2 = 1\n#<_rate> = 100\nF100\n";
  std::vector<double> ours;
  for (const char* text : cases) {
    const parsed_expression e = linuxcnc::read_value(text);
    REQUIRE(e.ok());
    const interp::evaluation v = interp::evaluate(e.tree, store);
    INFO(text);
    REQUIRE(v.ok());
    ours.push_back(v.value);
    program += std::string("#100 = ") + text + "\nG1 X#100 Y[fix[#100*10000]] Z[[#100*10000 - fix[#100*10000]]*100000]\n";
  }
  program += "M2\n";
  const run_output r = run_rs274(program);
  INFO(r.text);
  REQUIRE(r.feeds.size() == std::size(cases));
  for (std::size_t k = 0; k < ours.size(); ++k) {
    INFO(cases[k] << ": kin5 " << ours[k]);
    const double theirs = (r.feeds[k][1] + r.feeds[k][2] / 1e5) / 1e4;
    CHECK(std::abs(theirs - ours[k]) <= 1e-9 * std::max(1.0, std::abs(ours[k])));
  }
}

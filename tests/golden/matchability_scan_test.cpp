// docs/matchability.md: a_s in 0.1° steps over [−120°, 30°] with random b_s, SAJO 12000P → DMU 80P.
// Expected classes (docs/matchability.md, P13, P14): other_branch exactly on [−120°, −90.1°],
// direct on [−90°, 0°], unreachable on [0.1°, 30°] with gap = a_s.
#include <cmath>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>
#include <kin5/program/number.hpp>

#include "program_builder.hpp"

using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;

TEST_CASE("matchability scan: classes and gaps of SAJO poses on the DMU 80P") {
  std::mt19937 random(20100612);
  std::uniform_real_distribution<double> b_deg(-180.0, 180.0);
  auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::siemens::dialect>(), "scan.mpf");
  std::vector<double> a_values, b_values;
  for (int k = -1200; k <= 300; ++k) {
    // B anywhere, each move the least way round (B is endless): a move of 180° or more is a
    // sweep, which the DMU 80P follows only where its axes turn the tool the same way.
    const double a = k / 10.0, drawn = b_deg(random);
    const double b = b_values.empty() ? drawn : b_values.back() + std::remainder(drawn - b_values.back(), 360.0);
    a_values.push_back(a), b_values.push_back(b);
    kin5::test::add_motion(p, {1.0 * k, 2.0, 3.0, a, b, std::nullopt, 500.0});
  }
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(p, {});
  REQUIRE(t.reports.size() == a_values.size());
  std::size_t unreachable = 0;
  for (std::size_t i = 0; i < a_values.size(); ++i) {
    const double a = a_values[i];
    const auto& r = t.reports[i];
    CAPTURE(a, b_values[i]);
    CHECK(r.where.line == i + 2);
    if (a <= -90.1 + 1e-9) {
      CHECK(r.match == kin5::matchability::other_branch);
    } else if (a <= 1e-9) {
      CHECK(r.match == kin5::matchability::direct);
    } else {
      ++unreachable;
      REQUIRE(r.match == kin5::matchability::unreachable);
      // P14: the smallest angle from T·u_s to the upper hemisphere is a_s.
      CHECK(std::abs(kin5::to_degrees(r.gap).value - a) <= 1e-9);
      CHECK_FALSE(r.why.empty());
    }
  }
  CHECK(unreachable == 300);
  // Every unreachable block is an error naming its line, source angles and gap; nothing else is.
  CHECK_FALSE(t.ok());
  REQUIRE(t.errors.size() == unreachable);
  for (const auto& e : t.errors) {
    const std::size_t i = e.where.line - 2;
    CAPTURE(e.message);
    CHECK(a_values[i] > 0.0);
    CHECK(e.where.file == "scan.mpf");
    CHECK(e.message.find(t.reports[i].source_angles) != std::string::npos);
    CHECK(e.message.find(kin5::program::format_number(a_values[i], 1)) != std::string::npos);
  }
  // Unreachable blocks are not written (never clamped): the block count shows the gap.
  CHECK(t.blocks_written == t.blocks_read - unreachable);
}

TEST_CASE("matchability scan: reachable blocks reproduce the tool axis exactly (P12, P13)") {
  const auto T = kin5::sajo_12000p_dmu_80p_setup.rotation;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> b_deg(-180.0, 180.0);
  for (int k = -1200; k <= 0; k += 7) {
    const double a = k / 10.0, b = b_deg(random);
    auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::siemens::dialect>());
    kin5::test::add_motion(p, {0, 0, 0, a, b, std::nullopt, 500.0});
    const auto t = kin5::translate<sajo_12000p, dmu_80p>(p, {});
    REQUIRE(t.ok());
    const auto& w = t.output.blocks.back().axes;
    const kin5::vec3 u_s = kin5::tool_axis<sajo_12000p>(
        {kin5::to_radians(kin5::degrees{b}), kin5::to_radians(kin5::degrees{a})});
    const kin5::vec3 u_d = kin5::tool_axis<dmu_80p>(
        {kin5::to_radians(kin5::degrees{*w.c_deg}), kin5::to_radians(kin5::degrees{*w.b_deg})});
    CAPTURE(a, b);
    CHECK(kin5::norm(u_d - T * u_s) <= 1e-12);
    // (K12): B_d = arccos(−1 − 2 sin a_s) on both branches.
    CHECK(std::abs(*w.b_deg - std::acos(-1.0 - 2.0 * std::sin(a * kin5::pi / 180.0)) * 180.0 / kin5::pi) <= 1e-6);
  }
}

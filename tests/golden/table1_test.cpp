// Table 1 of Tian et al. 2010 (docs/golden.md, P18) through translate<sajo_12000p, dmu_80p> and
// back, and the block-time feed (K17) against the values of docs/golden.md, "Table 1 feed
// column". Table 1's F_d column itself is not asserted.
#include <array>
#include <cmath>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>

#include "program_builder.hpp"

namespace {

using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;
using kin5::program::dialect;

struct row {
  double xs, ys, zs, as, bs, fs;  // SAJO 12000P: X Y Z A B F
  double xd, yd, zd, bd, cd;      // DMU 80P: X Y Z B C (F_d not used, docs/golden.md)
  double bd_exact, cd_exact;      // docs/golden.md: B_d, C_d computed independently
};

// table1.csv, typed in; the last two columns are the computed values of docs/golden.md.
constexpr std::array<row, 4> table1{{
    {-34.983, 9.100, 118.526, -77.954, 3.536, 1091, 34.983, 118.526, 9.100, 17.067, 87.479, 17.067290, 87.479443},
    {-33.824, 9.118, 117.545, -77.913, 4.027, 1093, 33.824, 117.545, 9.118, 17.126, 87.950, 17.125599, 87.949597},
    {-32.674, 9.153, 116.558, -77.918, 4.588, 1094, 32.674, 116.558, 9.153, 17.118, 88.513, 17.118488, 88.513139},
    {-31.531, 9.203, 115.567, -77.963, 5.158, 1096, 31.531, 115.567, 9.203, 17.054, 89.106, 17.054491, 89.106018},
}};

kin5::program::program sajo_program() {
  auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::siemens::dialect>(), "table1.mpf");
  for (const row& r : table1) kin5::test::add_motion(p, {r.xs, r.ys, r.zs, r.as, r.bs, std::nullopt, r.fs});
  kin5::test::add_block(p).spindle_rpm = 4000;
  return p;
}

kin5::program::program dmu_program() {
  auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::heidenhain::dialect>(), "table1.h");
  for (const row& r : table1) kin5::test::add_motion(p, {r.xd, r.yd, r.zd, std::nullopt, r.bd, r.cd, 1000.0});
  return p;
}

std::vector<const kin5::program::block*> motions(const kin5::program::program& p) {
  std::vector<const kin5::program::block*> out;
  for (const auto& b : p.blocks)
    if (b.moves()) out.push_back(&b);
  return out;
}

}  // namespace

TEST_CASE("Table 1, SAJO 12000P -> DMU 80P: positions exact, angles as printed and as computed (P18)") {
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(sajo_program(), {});
  REQUIRE(t.ok());
  CHECK(t.blocks_read == 6);
  CHECK(t.blocks_written == 6);
  CHECK(t.output.language == kin5::program::id_of<kin5::program::heidenhain::dialect>());
  const auto m = motions(t.output);
  REQUIRE(m.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const row& r = table1[i];
    const auto& a = m[i]->axes;
    CAPTURE(i);
    // (K11): (x_d, y_d, z_d) = (−x_s, z_s, y_s), and the table's DMU columns.
    CHECK(std::abs(*a.x_mm - -r.xs) <= 1e-9);
    CHECK(std::abs(*a.y_mm - r.zs) <= 1e-9);
    CHECK(std::abs(*a.z_mm - r.ys) <= 1e-9);
    CHECK(std::abs(*a.x_mm - r.xd) <= 1e-9);
    CHECK(std::abs(*a.y_mm - r.yd) <= 1e-9);
    CHECK(std::abs(*a.z_mm - r.zd) <= 1e-9);
    CHECK_FALSE(a.a_deg.has_value());
    CHECK(std::abs(*a.b_deg - r.bd) <= 1e-3);
    CHECK(std::abs(*a.c_deg - r.cd) <= 1e-3);
    CHECK(std::abs(*a.b_deg - r.bd_exact) <= 1e-5);
    CHECK(std::abs(*a.c_deg - r.cd_exact) <= 1e-5);
    CHECK(t.reports[i].match == kin5::matchability::direct);
    CHECK(m[i]->feed == r.fs);  // tcp policy: F unchanged
  }
  CHECK(t.reports[0].source_angles == "A=-77.954 B=3.536");
  CHECK(t.output.blocks.back().spindle_rpm == 4000.0);  // (24)-(25): S copied
}

TEST_CASE("Table 1, DMU 80P -> SAJO 12000P: positions exact, A and B within 0.001 deg (P18)") {
  const auto t = kin5::translate<dmu_80p, sajo_12000p>(dmu_program(), kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::siemens::dialect>()));
  REQUIRE(t.ok());
  const auto m = motions(t.output);
  REQUIRE(m.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const row& r = table1[i];
    const auto& a = m[i]->axes;
    CAPTURE(i);
    CHECK(std::abs(*a.x_mm - r.xs) <= 1e-9);
    CHECK(std::abs(*a.y_mm - r.ys) <= 1e-9);
    CHECK(std::abs(*a.z_mm - r.zs) <= 1e-9);
    CHECK(std::abs(*a.a_deg - r.as) <= 1e-3);  // (K13): within 0.00055° (docs/golden.md)
    CHECK(std::abs(*a.b_deg - r.bs) <= 1e-3);
    CHECK_FALSE(a.c_deg.has_value());
  }
}

TEST_CASE("Table 1 round trip SAJO -> DMU -> SAJO gives the SAJO program back") {
  const auto there = kin5::translate<sajo_12000p, dmu_80p>(sajo_program(), {});
  const auto back = kin5::translate<dmu_80p, sajo_12000p>(there.output, kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::siemens::dialect>()));
  REQUIRE(back.ok());
  const auto m = motions(back.output);
  REQUIRE(m.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(std::abs(*m[i]->axes.x_mm - table1[i].xs) <= 1e-9);
    CHECK(std::abs(*m[i]->axes.a_deg - table1[i].as) <= 1e-9);
    CHECK(std::abs(*m[i]->axes.b_deg - table1[i].bs) <= 1e-9);
  }
}

TEST_CASE("block-time feed is (K17) with (K16) lengths and gives the Table 1 feed column values from the rounded table") {
  // The (K17) table of docs/golden.md: l_s, l_d from the printed (rounded) Table 1 columns.
  constexpr std::array<double, 3> expected{1089.25, 1094.48, 1102.02};
  for (std::size_t i = 1; i < 4; ++i) {
    const row &p = table1[i - 1], &r = table1[i];
    const double l_s = std::sqrt(std::pow(r.xs - p.xs, 2) + std::pow(r.ys - p.ys, 2) + std::pow(r.zs - p.zs, 2) +
                                 std::pow(r.as - p.as, 2) + std::pow(r.bs - p.bs, 2));
    const double l_d = std::sqrt(std::pow(r.xd - p.xd, 2) + std::pow(r.yd - p.yd, 2) + std::pow(r.zd - p.zd, 2) +
                                 std::pow(r.bd - p.bd, 2) + std::pow(r.cd - p.cd, 2));
    CHECK(std::abs(kin5::block_time_feed_mm_per_min(r.fs, l_s, l_d) - expected[i - 1]) <= 0.005);
  }
  CHECK(kin5::block_time_feed_mm_per_min(1000.0, 0.0, 3.0) == 1000.0);  // l_s = 0 keeps F

  // Through the translator: (K17) by hand from the source rows and the written DMU angles.
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(sajo_program(), kin5::test::options(kin5::feed_policy::block_time));
  REQUIRE(t.ok());
  const auto m = motions(t.output);
  CHECK(*m[0]->feed == table1[0].fs);  // no previous block: F kept
  for (std::size_t i = 1; i < 4; ++i) {
    const row &p = table1[i - 1], &r = table1[i];
    const auto &a = m[i]->axes, &b = m[i - 1]->axes;
    const double l_s = std::sqrt(std::pow(r.xs - p.xs, 2) + std::pow(r.ys - p.ys, 2) + std::pow(r.zs - p.zs, 2) +
                                 std::pow(r.as - p.as, 2) + std::pow(r.bs - p.bs, 2));
    const double l_d = std::sqrt(std::pow(*a.x_mm - *b.x_mm, 2) + std::pow(*a.y_mm - *b.y_mm, 2) +
                                 std::pow(*a.z_mm - *b.z_mm, 2) + std::pow(*a.b_deg - *b.b_deg, 2) +
                                 std::pow(*a.c_deg - *b.c_deg, 2));
    CAPTURE(i);
    CHECK(std::abs(*m[i]->feed - r.fs * l_d / l_s) <= 1e-9);
    // Unrounded angles give a slightly different l_d than the rounded table: within 0.5 mm/min.
    CHECK(std::abs(*m[i]->feed - expected[i - 1]) <= 0.5);
  }
}

TEST_CASE("inverse-time feed is G93 with F = 1 over the block time and is refused where the dialect has no G93") {
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(
      sajo_program(), kin5::test::options(kin5::feed_policy::inverse_time, kin5::program::id_of<kin5::program::siemens::dialect>()));
  REQUIRE(t.ok());
  const auto m = motions(t.output);
  // The first feed block's start is unknown, so is its time: in G93 it would have no F, so it
  // keeps its per-minute F (G94), and G93 starts with the second.
  CHECK(m[0]->feed_mode != kin5::program::feed_unit::inverse_time);
  REQUIRE(m[0]->feed.has_value());
  CHECK(*m[0]->feed == table1[0].fs);
  CHECK(m[1]->feed_mode == kin5::program::feed_unit::inverse_time);
  CHECK(t.warnings.empty());
  for (std::size_t i = 1; i < 4; ++i) {
    const row &p = table1[i - 1], &r = table1[i];
    const double tip = std::sqrt(std::pow(r.xs - p.xs, 2) + std::pow(r.ys - p.ys, 2) + std::pow(r.zs - p.zs, 2));
    CHECK(std::abs(*m[i]->feed - r.fs / tip) <= 1e-9);  // 1 / (tip length / F)
  }
  const auto refused = kin5::translate<sajo_12000p, dmu_80p>(sajo_program(), kin5::test::options(kin5::feed_policy::inverse_time));
  CHECK_FALSE(refused.ok());
}

TEST_CASE("golden values of SAJO poses through translate, one block each") {
  struct value { double a, b, bd, cd; };
  // C_d as printed, to be compared modulo 360° (continuous C is written in (−180°, 180°]).
  const std::array<value, 5> values{{{-45, 30, 65.530199, 95.530199},
                                     {-10, 200, 130.745757, 232.954835},
                                     {-89, 123, 1.414232, 212.499981},
                                     {-100, 20, 14.160202, 284.980852},
                                     {-135, 0, 65.530199, 245.530199}}};
  for (const value& v : values) {
    auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::siemens::dialect>());
    kin5::test::add_motion(p, {1, 2, 3, v.a, v.b, std::nullopt, 100.0});
    const auto t = kin5::translate<sajo_12000p, dmu_80p>(p, {});
    CAPTURE(v.a, v.b);
    if (v.a < -120.0) {  // past the SAJO's A travel [-120, 30]: not a program for the SAJO
      REQUIRE(t.errors.size() == 1);
      CHECK(t.errors[0].message.find("outside the travel of A on sajo-12000p") != std::string::npos);
      continue;
    }
    REQUIRE(t.ok());
    const auto& a = motions(t.output).at(0)->axes;
    CHECK(std::abs(*a.b_deg - v.bd) <= 1e-5);
    CHECK(std::abs(std::remainder(*a.c_deg - v.cd, 360.0)) <= 1e-5);
    CHECK(*a.c_deg > -180.0);
    CHECK(*a.c_deg <= 180.0);
    CHECK(t.reports.at(0).match == (v.a < -90 ? kin5::matchability::other_branch : kin5::matchability::direct));
  }
}

TEST_CASE("a source program in inverse time (G93) keeps its F, and needs a dialect with G93") {
  auto p = sajo_program();
  p.blocks[1].feed_mode = kin5::program::feed_unit::inverse_time;
  for (std::size_t k = 1; k <= 4; ++k) p.blocks[k].feed = 10.0 * static_cast<double>(k);
  for (auto policy : {kin5::feed_policy::tcp, kin5::feed_policy::block_time, kin5::feed_policy::inverse_time}) {
    const auto t = kin5::translate<sajo_12000p, dmu_80p>(p, kin5::test::options(policy, kin5::program::id_of<kin5::program::iso::dialect>()));
    REQUIRE(t.ok());
    const auto m = motions(t.output);
    REQUIRE(m.size() == 4);
    CHECK(m[0]->feed_mode == kin5::program::feed_unit::inverse_time);
    for (std::size_t k = 0; k < 4; ++k) CHECK(m[k]->feed == 10.0 * static_cast<double>(k + 1));
  }
  const auto refused = kin5::translate<sajo_12000p, dmu_80p>(p, kin5::test::options());  // Heidenhain: no G93
  REQUIRE(refused.errors.size() == 1);
  CHECK(refused.errors[0].where.line == 2);
}

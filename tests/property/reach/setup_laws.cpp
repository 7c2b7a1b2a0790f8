// The setup search (reach/setup_search.hpp) and the program report (reach/program_report.hpp),
// each result checked with the core solver rather than with the search's own closed form.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include <kin5/program/io.hpp>
#include <kin5/reach/program_report.hpp>
#include <kin5/reach/report_text.hpp>

#include "../core/generators.hpp"

using namespace kin5;
using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;

namespace {

constexpr double deg(double v) { return v * pi / 180.0; }

/// Whether every R u reaches To within travel, by `inverse`.
template <machine To>
bool all_reachable(const mat3& r, const std::vector<vec3>& axes) {
  for (const vec3& u : axes)
    if (!inverse<To>(r * u).reachable()) return false;
  return true;
}

/// Tool axes on a circle of `radius` about unit d.
std::vector<vec3> circle(const vec3& d, double radius, int n) {
  std::vector<vec3> out;
  for (int i = 0; i < n; ++i)
    out.push_back(std::cos(radius) * d + std::sin(radius) * test::perpendicular(d, 2.0 * pi * i / n));
  return out;
}

}  // namespace

TEST_CASE("The 24 axis-aligned rotations are distinct proper rotations", "[reach][setup]") {
  const auto rs = reach::axis_aligned_rotations();
  REQUIRE(rs.size() == 24);
  std::set<std::tuple<double, double, double, double, double, double, double, double, double>> seen;
  for (const mat3& r : rs) {
    CHECK(determinant(r) == Approx(1.0));
    const mat3 rrt = r * r.transposed();
    CHECK(norm(rrt.row[0] - unit_x) + norm(rrt.row[1] - unit_y) + norm(rrt.row[2] - unit_z) == Approx(0.0).margin(1e-15));
    seen.insert({r.row[0].x, r.row[0].y, r.row[0].z, r.row[1].x, r.row[1].y, r.row[1].z, r.row[2].x, r.row[2].y, r.row[2].z});
  }
  CHECK(seen.size() == 24);
}

TEST_CASE("A setup found for tool axes the default setup cannot take reaches them all", "[reach][setup]") {
  // 25 random programs of up to 8 tool axes within 85° of a random direction, so that the
  // DMU 80P's hemisphere can hold them (a search costs tens of Ipopt runs: 25, not 100).
  std::mt19937 random(20260412);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 25; ++k) {
    const vec3 d = normalized(vec3{unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5});
    std::vector<vec3> axes;
    const int n = 1 + static_cast<int>(unit(random) * 8);
    for (int i = 0; i < n; ++i) {
      const double radius = deg(85.0) * unit(random);
      axes.push_back(std::cos(radius) * d + std::sin(radius) * test::perpendicular(d, 2.0 * pi * unit(random)));
    }
    const auto found = reach::search_setup(sajo_12000p::model, dmu_80p::model, axes, default_setup<sajo_12000p, dmu_80p>().rotation);
    INFO("program " << k << ", " << n << " axes");
    REQUIRE(found.best.has_value());
    CHECK(all_reachable<dmu_80p>(found.best->rotation, axes));
    CHECK(std::abs(determinant(found.best->rotation) - 1.0) < 1e-9);
    // The ranking is by travel, each the planner's for that rotation.
    for (std::size_t i = 1; i < found.ranked.size(); ++i) CHECK(found.ranked[i - 1].travel_rad <= found.ranked[i].travel_rad + 1e-9);
    CHECK(found.best->travel_rad == Approx(plan_rotary_path<dmu_80p>([&] {
                                          std::vector<vec3> t;
                                          for (const vec3& u : axes) t.push_back(found.best->rotation * u);
                                          return t;
                                        }()).travel_rad));
  }
}

TEST_CASE("Only the continuous refinement finds a setup no axis-aligned rotation gives", "[reach][setup]") {
  // Twelve axes 80° around (1, 1, 1)/√3: every coordinate axis is 134.7° from some of them, so
  // no axis-aligned rotation puts them in the DMU 80P's upper hemisphere; d itself does.
  const std::vector<vec3> axes = circle(normalized(vec3{1, 1, 1}), deg(80.0), 12);
  const auto found = reach::search_setup(sajo_12000p::model, dmu_80p::model, axes, default_setup<sajo_12000p, dmu_80p>().rotation);
  for (const auto& c : found.tried)
    if (c.axis_aligned) CHECK_FALSE(all_reachable<dmu_80p>(c.rotation, axes));
  REQUIRE(found.best.has_value());
  CHECK_FALSE(found.best->axis_aligned);
  CHECK(all_reachable<dmu_80p>(found.best->rotation, axes));
  // ±X, ±Y, ±Z fit in no hemisphere: nothing is found, and the closest is named.
  const std::vector<vec3> wide{unit_x, -1.0 * unit_x, unit_y, -1.0 * unit_y, unit_z, -1.0 * unit_z};
  const auto none = reach::search_setup(sajo_12000p::model, dmu_80p::model, wide, mat3::identity());
  CHECK_FALSE(none.best.has_value());
  CHECK(none.closest.unreachable > 0);
}

TEST_CASE("The setup-rotation option text reads back as the rotation", "[reach][setup]") {
  const mat3 r = rotation(normalized(vec3{0.3, -0.5, 0.8}), radians{1.234});
  const std::string text = reach::rotation_option(r);
  double v[9];
  REQUIRE(std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5],
                      &v[6], &v[7], &v[8]) == 9);
  for (int i = 0; i < 3; ++i) {
    CHECK(v[3 * i] == Approx(r.row[i].x).margin(1e-14));
    CHECK(v[3 * i + 1] == Approx(r.row[i].y).margin(1e-14));
    CHECK(v[3 * i + 2] == Approx(r.row[i].z).margin(1e-14));
  }
  CHECK(reach::rotation_option(default_setup<sajo_12000p, dmu_80p>().rotation) == "-1,0,0,0,0,1,0,1,0");
  const auto [angle, axis] = reach::axis_angle(default_setup<sajo_12000p, dmu_80p>().rotation);
  CHECK(angle == Approx(180.0));  // (K10) = Tian et al. 2010 eqs (15)-(17): the half turn about (0, 1, 1)/√2
  CHECK(std::abs(dot(axis, normalized(vec3{0, 1, 1}))) == Approx(1.0));
}

TEST_CASE("Program report: classes, unreachable runs with their gap, planned travel", "[reach][setup]") {
  // Lines 3-8: A = -45, 5, 6, -30, -100, 20 (B = 30 each): runs {4, 5} and {8}; gaps = A.
  const std::string text =
      "N10 G90 G17\nN20 TRAORI\nN30 G1 X0 Y0 Z50 A-45 B30 F1000\nN40 G1 X1 A5\nN50 G1 X2 A6\n"
      "N60 G1 X3 A-30\nN70 G1 X4 A-100\nN80 G1 X5 A20\nN90 TRAFOOF\nN100 M30\n";
  const auto in = program::read(program::id_of<program::siemens::dialect>(), text, "wall.mpf");
  REQUIRE(in.ok());
  const auto r = reach::make_program_report(sajo_12000p::model, dmu_80p::model, in.parsed, default_setup<sajo_12000p, dmu_80p>(), true);
  CHECK(r.per_class == std::array<std::size_t, 3>{2, 1, 3});
  REQUIRE(r.unreachable.size() == 2);
  CHECK((r.unreachable[0].first_line == 4 && r.unreachable[0].last_line == 5 && r.unreachable[0].blocks == 2));
  CHECK(r.unreachable[0].worst_gap_rad * 180.0 / pi == Approx(6.0).margin(1e-9));
  CHECK((r.unreachable[1].first_line == 8 && r.unreachable[1].last_line == 8));
  CHECK(r.unreachable[1].worst_gap_rad * 180.0 / pi == Approx(20.0).margin(1e-9));
  CHECK(r.other_errors.empty());
  REQUIRE(r.source_axes.size() == 6);
  // The reachable blocks' B_d by (K12) = Tian et al. 2010 eq (19): arccos(-1 - 2 sin A).
  const auto& b_span = r.rotary[1];
  CHECK(b_span.letter == 'B');
  auto b_of = [](double a) { return std::acos(-1.0 - 2.0 * std::sin(deg(a))) * 180.0 / pi; };
  CHECK(b_span.lo_deg == Approx(std::min({b_of(-45), b_of(-30), b_of(-100)})).margin(1e-9));
  CHECK(b_span.hi_deg == Approx(std::max({b_of(-45), b_of(-30), b_of(-100)})).margin(1e-9));
  // Tool tips through (K11): (x_d, y_d, z_d) = (-x_s, z_s, y_s).
  CHECK((r.tip_lo_mm.x == Approx(-5.0) && r.tip_hi_mm.x == Approx(0.0) && r.tip_lo_mm.y == Approx(50.0)));
}

TEST_CASE("Program report: the slides of each reachable block put the tool back on its tip (G6)", "[reach][setup]") {
  // The same wall; tool length 120 mm, the workpiece frame 30 mm above and beside the origin.
  const std::string text =
      "N10 G90 G17\nN20 TRAORI\nN30 G1 X0 Y0 Z50 A-45 B30 F1000\nN40 G1 X1 A5\nN50 G1 X2 A6\n"
      "N60 G1 X3 A-30\nN70 G1 X4 A-100\nN80 G1 X5 A20\nN90 TRAFOOF\nN100 M30\n";
  const auto in = program::read(program::id_of<program::siemens::dialect>(), text, "wall.mpf");
  REQUIRE(in.ok());
  const rigid_transform setup = default_setup<sajo_12000p, dmu_80p>();
  run_inputs inputs{.tool_length_mm = 120.0};
  inputs.work_offset.translation_mm = {30.0, -30.0, -200.0};
  const auto r = reach::make_program_report(sajo_12000p::model, dmu_80p::model, in.parsed, setup, true, inputs, true);
  REQUIRE(r.blocks.size() == 6);
  REQUIRE(r.linear.size() == 3);
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  std::size_t reachable = 0;
  for (std::size_t i = 0; i < r.blocks.size(); ++i) {
    const auto& b = r.blocks[i];
    INFO("block on line " << b.line);
    CHECK(b.reachable == inverse<dmu_80p>(setup.rotation * r.source_axes[i]).reachable());
    if (!b.reachable) continue;
    ++reachable;
    // Forward through the whole chain, independent of the (G7) inverse that placed the slides.
    const auto pose = forward<dmu_80p>({b.slides_mm, {radians{b.rotary_rad[0]}, radians{b.rotary_rad[1]}}}, inputs);
    CHECK(norm(pose.tip_mm - b.tip_mm) < 1e-9);
    CHECK(norm(pose.axis - setup.rotation * r.source_axes[i]) < 1e-12);
    const std::array<double, 3> x{b.slides_mm.x, b.slides_mm.y, b.slides_mm.z};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], x[k]), hi[k] = std::max(hi[k], x[k]);
  }
  CHECK(reachable == 3);
  for (int k = 0; k < 3; ++k) {
    CHECK(r.linear[k].letter == "XYZ"[k]);
    CHECK((r.linear[k].lo_mm == lo[k] && r.linear[k].hi_mm == hi[k]));
    CHECK(r.linear[k].travel_lo_mm == dmu_80p::linear[k].travel.lower_mm);
    CHECK(r.linear[k].travel_hi_mm == dmu_80p::linear[k].travel.upper_mm);
  }
  // The DMU 80P's Z travel is [-600, 0] mm: a workpiece frame 2 m up puts every block out of it.
  inputs.work_offset.translation_mm = {0.0, 0.0, 2000.0};
  const auto high = reach::make_program_report(sajo_12000p::model, dmu_80p::model, in.parsed, setup, true, inputs, true);
  CHECK(high.linear_exceeded());
  CHECK(high.linear[2].lo_mm == Approx(r.linear[2].lo_mm + 2200.0));  // the slides follow the offset
  // Not placed, only the strokes count, and these few millimetres fit.
  const auto loose = reach::make_program_report(sajo_12000p::model, dmu_80p::model, in.parsed, setup, true, inputs, false);
  CHECK(!loose.linear_exceeded());
}

namespace {

/// The first solution of `inverse` within travel for `u`, if any.
template <machine To>
std::optional<rotary_values> angles_for(const vec3& u) {
  for (const auto& s : inverse<To>(u))
    if (s.within_travel) return rotary_values{s.angles[0], s.angles[1]};
  return std::nullopt;
}

/// The box [lo, hi] of shifts of each slide, from slide values at no shift: every travel
/// narrowed by the margin, the tightest block each way.
struct shift_box {
  std::array<double, 3> lo{-1e300, -1e300, -1e300}, hi{1e300, 1e300, 1e300};
  void add(const machine_model& m, const vec3& slides_mm) {
    const double x[3] = {slides_mm.x, slides_mm.y, slides_mm.z};
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::max(lo[k], m.linear(k).travel.lower_mm + reach::offset_margin_mm - x[k]);
      hi[k] = std::min(hi[k], m.linear(k).travel.upper_mm - reach::offset_margin_mm - x[k]);
    }
  }
  double narrowest() const { return std::min({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
  /// The point of the box nearest the origin.
  vec3 nearest() const {
    return {std::clamp(0.0, lo[0], hi[0]), std::clamp(0.0, lo[1], hi[1]), std::clamp(0.0, lo[2], hi[2])};
  }
};

}  // namespace

TEST_CASE("Setup offset on a head-head machine: the nearest point of the closed-form box", "[reach][setup][offset]") {
  // ac-head moves the tool only: its slides are x = w + p + (L + l) u (L = 150 mm pivot), so the
  // shifts that keep every block within travel are an axis-aligned box from the travel and the
  // program's bounding box, and the least shift is the origin clamped to it; none when it is empty.
  using kin5::machines::ac_head;
  std::mt19937 random(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(random); };
  int found = 0, none = 0;
  for (int k = 0; k < 200; ++k) {
    run_inputs inputs{.tool_length_mm = in(0.0, 200.0)};
    inputs.work_offset.translation_mm = {in(-500, 500), in(-500, 500), in(-400, 100)};
    const vec3 centre{in(-800, 800), in(-800, 800), in(-400, 400)};
    const vec3 half{in(0, 1100), in(0, 900), in(0, 350)};
    std::vector<vec3> tips;
    std::vector<rotary_values> angles;
    shift_box box;
    const int n = 1 + static_cast<int>(unit(random) * 12);
    while (static_cast<int>(tips.size()) < n) {
      const vec3 u = normalized(vec3{in(-1, 1), in(-1, 1), in(-1, 1)});
      const auto a = angles_for<ac_head>(u);
      if (!a) continue;
      const vec3 tip{centre.x + half.x * in(-1, 1), centre.y + half.y * in(-1, 1), centre.z + half.z * in(-1, 1)};
      tips.push_back(tip), angles.push_back(*a);
      box.add(ac_head::model, inputs.work_offset.translation_mm + tip + (150.0 + inputs.tool_length_mm) * u);
    }
    const auto shift = reach::setup_offset_shift(ac_head::model, tips, angles, inputs);
    INFO("program " << k << ", " << n << " blocks, narrowest side of the box " << box.narrowest() << " mm");
    if (box.narrowest() < -1e-3) {
      CHECK_FALSE(shift.has_value());
      ++none;
    } else if (box.narrowest() > 1e-2) {
      REQUIRE(shift.has_value());
      CHECK(norm(*shift - box.nearest()) < 1e-3);
      ++found;
    }
  }
  CHECK(found > 50);
  CHECK(none > 15);
}

TEST_CASE("Setup offset on a table machine, one tool axis: the box turned by the tables (G6)", "[reach][setup][offset]") {
  // With every block at the same angles, the tip the slides x give is c + K x (forward, G6),
  // K a rotation: the least shift is K times the origin clamped to the box of Kᵀ-slides.
  std::mt19937 random(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(random); };
  int found = 0, none = 0;
  for (int k = 0; k < 120; ++k) {
    run_inputs inputs{.tool_length_mm = in(0.0, 200.0)};
    inputs.work_offset.translation_mm = {in(-300, 300), in(-300, 300), in(-500, 0)};
    std::optional<rotary_values> a;
    while (!a) a = angles_for<dmu_80p>(normalized(vec3{in(-1, 1), in(-1, 1), in(-0.2, 1)}));
    auto tip_of = [&](const vec3& x) { return forward<dmu_80p>({x, *a}, inputs).tip_mm; };
    const vec3 c = tip_of({0, 0, 0});
    const mat3 K = mat3::from_columns(tip_of(unit_x) - c, tip_of(unit_y) - c, tip_of(unit_z) - c);
    REQUIRE(norm((K * K.transposed()).row[0] - unit_x) < 1e-12);
    const vec3 centre{in(-400, 400), in(-400, 400), in(-400, 400)};
    const double half = in(0, 450);
    std::vector<vec3> tips;
    shift_box box;
    for (int i = 0; i < 6; ++i) {
      tips.push_back(centre + half * normalized(vec3{in(-1, 1), in(-1, 1), in(-1, 1)}));
      box.add(dmu_80p::model, K.transposed() * (tips.back() - c));
    }
    const std::vector<rotary_values> angles(tips.size(), *a);
    const auto shift = reach::setup_offset_shift(dmu_80p::model, tips, angles, inputs);
    INFO("program " << k << ", narrowest side of the box " << box.narrowest() << " mm");
    if (box.narrowest() < -1e-3) {
      CHECK_FALSE(shift.has_value());
      ++none;
    } else if (box.narrowest() > 1e-2) {
      REQUIRE(shift.has_value());
      CHECK(norm(*shift - K * box.nearest()) < 2e-3);
      ++found;
    }
  }
  CHECK(found > 20);
  CHECK(none > 5);
}

TEST_CASE("Setup offset on a table machine, many tool axes: every slide within travel (G6)", "[reach][setup][offset]") {
  std::mt19937 random(20261125);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(random); };
  int found = 0;
  for (int k = 0; k < 60; ++k) {
    run_inputs inputs{.tool_length_mm = in(0.0, 200.0)};
    inputs.work_offset.translation_mm = {in(-300, 300), in(-300, 300), in(-500, 500)};
    const vec3 centre{in(-400, 400), in(-400, 400), in(-400, 400)};
    std::vector<vec3> tips;
    std::vector<rotary_values> angles;
    while (tips.size() < 8) {
      const auto a = angles_for<dmu_80p>(normalized(vec3{in(-1, 1), in(-1, 1), in(-0.2, 1)}));
      if (!a) continue;
      tips.push_back(centre + vec3{in(-150, 150), in(-150, 150), in(-100, 100)}), angles.push_back(*a);
    }
    const auto shift = reach::setup_offset_shift(dmu_80p::model, tips, angles, inputs);
    if (!shift) continue;
    ++found;
    for (std::size_t i = 0; i < tips.size(); ++i) {
      const vec3 x = linear_axes_for(dmu_80p::model, angles[i], inputs.work_offset.map_point(tips[i] + *shift), inputs);
      CHECK(norm(forward<dmu_80p>({x, angles[i]}, inputs).tip_mm - (tips[i] + *shift)) < 1e-9);  // G6 agrees
      const double v[3] = {x.x, x.y, x.z};
      for (std::size_t j = 0; j < 3; ++j) CHECK(dmu_80p::model.linear(j).travel.contains(v[j], 1e-6));
    }
  }
  CHECK(found > 45);
  // Two tips 2 m apart at the same angles: farther than the 800 x 700 x 600 mm travel reaches.
  const auto a = angles_for<dmu_80p>(unit_z);
  const std::vector<vec3> far{{0, 0, 0}, {2000, 0, 0}};
  CHECK_FALSE(reach::setup_offset_shift(dmu_80p::model, far, std::vector<rotary_values>(2, *a), {}).has_value());
}

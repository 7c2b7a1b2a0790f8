// Round trips: reverse∘post = identity on CL paths for every catalog machine, translate A→B→A
// = identity on the reachable set for several machine pairs, translate A→A = identity (sweeps,
// whole turns and poles included), and a sweep into another machine followed or refused.
#include <algorithm>
#include <cmath>
#include <set>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;

program::program cl_program(const std::vector<vec3>& tips, const std::vector<vec3>& axes) {
  program::program p;
  p.language = program::id_of<program::apt::dialect>();
  p.file = "path.cl";
  for (std::size_t k = 0; k < tips.size(); ++k) {
    program::block b;
    b.where = {p.file, k + 1, 1};
    b.motion = program::motion_kind::linear;
    b.axes.x_mm = tips[k].x, b.axes.y_mm = tips[k].y, b.axes.z_mm = tips[k].z;
    b.axes.tool_axis = axes[k];
    b.feed = 1000.0;
    p.blocks.push_back(b);
  }
  program::block end;
  end.where = {p.file, tips.size() + 1, 1};
  end.program_end = "FINI";
  p.blocks.push_back(end);
  return p;
}

template <machine M>
program::program nc_program(const std::vector<test::pose<M>>& path) {
  program::program p;
  p.language = program::id_of<program::siemens::dialect>();
  p.file = "path.mpf";
  program::block on;
  on.where = {p.file, 1, 1};
  on.tcp = true;
  p.blocks.push_back(on);
  for (const auto& q : path) {
    program::block b;
    b.where = {p.file, p.blocks.size() + 1, 1};
    b.motion = program::motion_kind::linear;
    b.axes.x_mm = q.tip_mm.x, b.axes.y_mm = q.tip_mm.y, b.axes.z_mm = q.tip_mm.z;
    test::set_rotary_words<M>(b.axes, q.angles);
    b.feed = 500.0;
    p.blocks.push_back(b);
  }
  return p;
}

/// Whether the unit tool axis `u` lies within `pole_zone` (plus rounding) of a pole ±p of M,
/// where the branch planner takes the pole itself (kinematics/branch_plan.hpp).
template <machine M>
bool near_pole(const vec3& u) {
  if (rotary_count<M> < 2) return false;
  const vec3 p = M::model.orientation.p;
  return angle_between(u, p).value <= pole_zone.value + 1e-9 || angle_between(u, -p).value <= pole_zone.value + 1e-9;
}

std::vector<const program::block*> motions(const program::program& p) {
  std::vector<const program::block*> out;
  for (const auto& b : p.blocks)
    if (b.moves()) out.push_back(&b);
  return out;
}

}  // namespace

TEST_CASE("reverse after post is the identity on reachable CL paths, every catalog machine") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("reverse∘post = id on ") + std::string(M::id), [] {
      const auto path = *test::path_within<M>(8);
      std::vector<vec3> tips, axes;
      for (const auto& q : path) tips.push_back(q.tip_mm), axes.push_back(tool_axis<M>(q.angles));
      const auto cl = cl_program(tips, axes);
      // Exact doubles, no rounding to absorb: the angle tolerance below the law's bound (as in
      // the A -> B -> A law below); with the default 0.0005° a solution that far past a travel
      // edge counts as on it and may be chosen, turning the axis by up to that.
      common_options exact;
      exact.angle_tolerance = degrees{2.5e-8};
      const auto nc = translate_detail::run(
          *make_post<M>(cl.language, program::id_of<program::siemens::dialect>(), cl.file, report_detail::every_block, exact), cl);
      RC_ASSERT(nc.ok());
      RC_ASSERT(nc.blocks_written == nc.blocks_read);
      for (const auto& r : nc.reports) RC_ASSERT(r.match == matchability::direct);
      const auto back = reverse<M>(nc.output);
      RC_ASSERT(back.ok());
      RC_ASSERT(back.output.language == program::id_of<program::apt::dialect>());
      // Where post's least move turns a bounded axis by 180° or more (the only way there), that
      // move is a sweep, which reverse writes as GOTO points along it before the block's own:
      // the last GOTO of each block is the block.
      std::vector<const program::block*> m;
      for (const program::block* b : motions(back.output)) {
        if (!m.empty() && m.back()->where.line == b->where.line) m.pop_back();
        m.push_back(b);
      }
      RC_ASSERT(m.size() == tips.size());
      for (std::size_t k = 0; k < m.size(); ++k) {
        RC_ASSERT(*m[k]->axes.x_mm == tips[k].x);
        RC_ASSERT(*m[k]->axes.y_mm == tips[k].y);
        RC_ASSERT(*m[k]->axes.z_mm == tips[k].z);
        // Within the pole zone the planner takes the pole itself (kinematics/branch_plan.hpp):
        // the axis moves by at most the zone. Elsewhere by at most the target's travel slack,
        // never below 1e-9 rad (nc_target.hpp): a solution that far past a limit is on it and
        // clamped, turning the axis by at most 1e-9 per rotary axis; plus the rounding of doubles.
        const double angle = angle_between(*m[k]->axes.tool_axis, axes[k]).value;
        if (near_pole<M>(axes[k]))
          RC_ASSERT(angle <= pole_zone.value + 1e-9);
        else
          RC_ASSERT(angle <= static_cast<double>(rotary_count<M>) * 1e-9 + 1e-12);
      }
    });
  });
}

namespace {

/// A random program of From whose tool axes To reaches: draw To's angles, map the axis back
/// through the setup, solve From, and pick one of From's within-travel solutions at random.
template <machine From, machine To>
std::vector<test::pose<From>> reachable_path(const rigid_transform& target_T_source) {
  const auto count = *rc::gen::inRange<std::size_t>(1, 9);
  std::vector<test::pose<From>> path;
  const rigid_transform source_T_target = target_T_source.inverse();
  for (std::size_t k = 0; k < count; ++k) {
    const auto target = *test::angles_within<To>(1.0);
    const vec3 u_s = source_T_target.map_direction(tool_axis<To>(target));
    const auto solutions = inverse<From>(u_s);
    // Each move the least way round, and none of 180° or more on a bounded axis either: such a
    // move is a sweep, which a target other than the source may be unable to follow (refused;
    // the sweep laws below).
    std::vector<rotary_angles<From>> within;
    for (const auto& s : solutions) {
      if (!s.within_travel) continue;
      const rotary_angles<From> a = path.empty() ? s.angles : unwrap_continuous<From>(s.angles, path.back().angles);
      bool sweeps = false;
      for (std::size_t i = 0; !path.empty() && i < rotary_count<From>; ++i)
        sweeps = sweeps || std::abs(a[i].value - path.back().angles[i].value) >= pi;
      if (!sweeps) within.push_back(a);
    }
    RC_PRE(!within.empty());
    const auto pick = *rc::gen::inRange<std::size_t>(0, within.size());
    path.push_back({*test::tip(), within[pick]});
  }
  return path;
}


template <machine From, machine To>
void check_round_trip() {
  rc::prop(std::string(From::id) + " -> " + std::string(To::id) + " -> back is the identity", [] {
    const rigid_transform d_T_s = default_setup<From, To>();
    const auto path = reachable_path<From, To>(d_T_s);
    const auto source = nc_program<From>(path);
    // The program holds exact doubles, not rounded text: the rounding the angle tolerance
    // absorbs (angle_tolerance.hpp) is absent, so the tolerance is set below the law's 1e-9 rad
    // (2.5e-8° is 4.4e-10 rad per axis). With the default, 0.0005° for a program without a
    // resolution, a solution that far past a travel edge is taken as on it and may be chosen
    // over an exact one: the tool axis then turns by up to the tolerance, the bound
    // source_check_laws.cpp checks. A tool axis within `pole_zone` of a pole is planned as the
    // pole whatever the tolerance (pole_laws.cpp): there each leg may turn it by that much.
    constexpr degrees exact_program_tolerance{2.5e-8};
    translate_options there;
    there.output_dialect = program::id_of<program::iso::dialect>();
    there.common.angle_tolerance = exact_program_tolerance;
    const auto t = translate<From, To>(source, there);
    RC_ASSERT(t.ok());
    RC_ASSERT(t.blocks_written == t.blocks_read);
    RC_ASSERT(t.reports.size() == path.size());
    translate_options back_options;
    back_options.output_dialect = program::id_of<program::siemens::dialect>();
    back_options.common.angle_tolerance = exact_program_tolerance;
    const auto back = translate<To, From>(t.output, back_options);
    // The target's least move may turn a bounded axis by 180° or more (the only way there): a
    // sweep of the program written, which the source machine may be unable to follow back.
    if (!back.ok()) {
      for (const auto& e : back.errors)
        RC_ASSERT(e.message.find("cannot follow this block's rotary sweep") != std::string::npos);
      RC_SUCCEED("a sweep of the target refused on the way back");
    }
    RC_ASSERT(back.blocks_written == source.blocks.size());
    const auto m = motions(back.output);
    const auto mid = motions(t.output);
    RC_ASSERT(m.size() == path.size());
    double source_length = 0.0, target_length = 0.0;
    for (std::size_t k = 0; k < m.size(); ++k) {
      const vec3 tip{*m[k]->axes.x_mm, *m[k]->axes.y_mm, *m[k]->axes.z_mm};
      RC_ASSERT(norm(tip - path[k].tip_mm) <= 1e-9);
      const vec3 u = tool_axis<From>(test::rotary_of<From>(m[k]->axes));
      const vec3 u_s = tool_axis<From>(path[k].angles);
      const vec3 u_t = d_T_s.map_direction(u_s);
      const bool target_pole = near_pole<To>(u_t), source_pole = near_pole<From>(u_s);
      const double there_slack = target_pole ? pole_zone.value + 1e-9 : 1e-9;
      const double back_slack = there_slack + (source_pole ? pole_zone.value : 0.0);
      RC_ASSERT(angle_between(u, u_s).value <= back_slack);
      // The target's own tool axis is the mapped source axis.
      const vec3 u_d = tool_axis<To>(test::rotary_of<To>(mid[k]->axes));
      RC_ASSERT(angle_between(u_d, u_t).value <= there_slack);
      if (k > 0) {
        source_length += norm(path[k].tip_mm - path[k - 1].tip_mm);
        const vec3 a{*mid[k]->axes.x_mm, *mid[k]->axes.y_mm, *mid[k]->axes.z_mm};
        const vec3 b{*mid[k - 1]->axes.x_mm, *mid[k - 1]->axes.y_mm, *mid[k - 1]->axes.z_mm};
        target_length += norm(a - b);
      }
    }
    // The setup is rigid: linear path length is preserved (K10, P11).
    RC_ASSERT(std::abs(source_length - target_length) <= 1e-9 * (1.0 + source_length));
  });
}

}  // namespace

TEST_CASE("translate A -> B -> A is the identity on the reachable set") {
  using namespace kin5::machines;
  check_round_trip<sajo_12000p, dmu_80p>();
  check_round_trip<dmu_80p, sajo_12000p>();
  check_round_trip<ac_trunnion, dmu_50v>();
  check_round_trip<dmu_50v, ac_head>();
  check_round_trip<b_head_a_tilted_table, ac_trunnion>();
  check_round_trip<ac_head, b_head_a_tilted_table>();
}

namespace {

/// Machine `m`'s commanded angles (radians, machine order) from a block's words; 0 when missing.
kin5::rotary_values angles_of(const machine_model& m, const program::axis_words& w) {
  kin5::rotary_values out{};
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const char letter = to_char(m.rotary(i).letter);
    const auto& word = letter == 'A' ? w.a_deg : letter == 'B' ? w.b_deg : w.c_deg;
    out[i] = to_radians(degrees{word.value_or(0.0)});
  }
  return out;
}

/// The largest angle (radians) between machine `to`'s tool axis, its angles moving linearly from
/// `to_start` to `to_end`, and machine `from`'s mapped by `target_T_source`, its angles moving
/// from `from_start` to `from_end`, at 64 points of the move.
double largest_axis_deviation(const machine_model& from, const kin5::rotary_values& from_start,
                              const kin5::rotary_values& from_end, const machine_model& to,
                              const kin5::rotary_values& to_start, const kin5::rotary_values& to_end,
                              const rigid_transform& target_T_source) {
  double worst = 0.0;
  for (int j = 1; j < 64; ++j) {
    const double s = j / 64.0;
    kin5::rotary_values a{}, b{};
    for (std::size_t i = 0; i < 2; ++i) {
      a[i] = radians{from_start[i].value + s * (from_end[i].value - from_start[i].value)};
      b[i] = radians{to_start[i].value + s * (to_end[i].value - to_start[i].value)};
    }
    worst = std::max(worst, angle_between(tool_axis(to, b), target_T_source.map_direction(tool_axis(from, a))).value);
  }
  return worst;
}

/// Exact doubles, no rounding to absorb: the angle tolerance of the round-trip law above.
translate_options exact_options() {
  translate_options o;
  o.output_dialect = program::id_of<program::siemens::dialect>();
  o.common.angle_tolerance = degrees{2.5e-8};
  return o;
}

}  // namespace

TEST_CASE("a translation to the same machine is the identity, sweeps, whole turns and poles included") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string(M::id) + " -> " + std::string(M::id) + " keeps every word", [] {
      const auto n = *rc::gen::inRange<std::size_t>(1, 9);
      std::vector<test::pose<M>> path;
      for (std::size_t k = 0; k < n; ++k) path.push_back({*test::tip(), test::angles_with_turns<M>(true)});
      const auto source = nc_program<M>(path);
      const auto t = translate<M, M>(source, exact_options());
      RC_ASSERT(t.ok());
      RC_ASSERT(t.warnings.empty());  // the source's own moves: no branch switch, no sudden turn
      const auto m = motions(t.output);
      RC_ASSERT(m.size() == n);
      for (std::size_t k = 0; k < n; ++k) {
        RC_ASSERT(norm(vec3{*m[k]->axes.x_mm, *m[k]->axes.y_mm, *m[k]->axes.z_mm} - path[k].tip_mm) <= 1e-9);
        const auto out = test::rotary_of<M>(m[k]->axes);
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          RC_ASSERT(std::abs(to_degrees(out[i]).value - to_degrees(path[k].angles[i]).value) <= 1e-9);
      }
    });
  });
}

TEST_CASE("a sweep of 180 degrees or more into another machine is followed or refused at its block") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("sweeps of ") + std::string(M::id) + " on a random machine", [] {
      const machine_model& to =
          *machines::catalog_models[*rc::gen::inRange<std::size_t>(0, machines::catalog_models.size())];
      const auto n = *rc::gen::inRange<std::size_t>(2, 7);
      std::vector<test::pose<M>> path;
      for (std::size_t k = 0; k < n; ++k) path.push_back({*test::tip(), test::angles_with_turns<M>(true)});
      const auto source = nc_program<M>(path);
      const rigid_transform d_T_s = default_setup(M::id, to.geometry.id);
      const auto t = translate(M::model, to, source, exact_options());
      std::set<std::size_t> swept_lines, refused_lines;
      for (std::size_t k = 1; k < n; ++k) {
        double largest = 0.0;
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          largest = std::max(largest, std::abs(path[k].angles[i].value - path[k - 1].angles[i].value));
        if (largest >= pi) swept_lines.insert(source.blocks[k + 1].where.line);
      }
      for (const auto& e : t.errors)
        if (e.message.find("cannot follow this block's rotary sweep") != std::string::npos)
          refused_lines.insert(e.where.line);
      RC_ASSERT(std::includes(swept_lines.begin(), swept_lines.end(), refused_lines.begin(), refused_lines.end()));
      RC_CLASSIFY(t.ok(), "written");
      if (!t.ok()) return;
      const auto m = motions(t.output);
      RC_ASSERT(m.size() == n);
      for (std::size_t k = 1; k < n; ++k) {
        if (!swept_lines.count(source.blocks[k + 1].where.line)) continue;
        kin5::rotary_values from_start{}, from_end{};
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          from_start[i] = path[k - 1].angles[i], from_end[i] = path[k].angles[i];
        // Each sample within the planner's sweep tolerance; between them within what a chord
        // of 22.5° of turn strays (the law samples 64 points, the planner 8 per half turn).
        const double deviation = largest_axis_deviation(M::model, from_start, from_end, to, angles_of(to, m[k - 1]->axes),
                                                        angles_of(to, m[k]->axes), d_T_s);
        RC_ASSERT(deviation <= 1e-5);
      }
    });
  });
}

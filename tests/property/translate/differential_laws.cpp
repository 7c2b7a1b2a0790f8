// Differential testing (docs/reliability.md): random programs in every dialect, translated as the
// tool translates them (`make_translator`, `make_reverse`, `make_post`, then `stream_text`)
// between random machines of the catalog and machine files, and checked against the Eigen chain
// of homogeneous transforms (`kin5::eigen`), which never calls kin5's closed forms. For every
// motion block of the source, in order, the written program read back with the target dialect's
// own reader has one motion block (nothing dropped or added) that:
//   * is a rapid exactly when the source's is, a line when it is a line, an arc when it is an arc;
//   * ends at the source's tool tip mapped by the setup (workpiece frame, target_T_source), with
//     the source's tool axis turned by the setup, each axis taken from the chain (or from the
//     tool-axis vector where the block gives one, as CL data do); an arc keeps its centre and
//     its sense of turning;
//   * has the feed the policy says: `tcp` keeps F (or the block's time, where either side is in
//     inverse time), `inverse-time` writes G93 with F = 1 / the source block's time, `block-time`
//     keeps the time with lengths in millimetres and degrees (K16);
// and the written program, read back, written again and read again, is the same program.
//
// A seeded loop, not RapidCheck: one seed gives the same programs with every standard library
// (std::mt19937_64 is specified to the bit). CI runs 2,000 cases from seed 1; by hand,
// KIN5_DIFFERENTIAL_CASES and KIN5_DIFFERENTIAL_SEED choose others, KIN5_DIFFERENTIAL_SHOW=1
// prints what was checked and refused. A failing case is minimised (blocks of its body dropped
// while it fails for the same reason) and printed with its seed and index, its source text, the
// written text and the first difference.
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/eigen.hpp>
#include <kin5/kin5.hpp>
#include <kin5/machines/catalog.hpp>
#include <kin5/machines/machine_file.hpp>
#include <kin5/machines/machine_file_writer.hpp>
#include <kin5/program/io.hpp>
#include <kin5/translate/stream.hpp>

#include "../dialects/model_difference.hpp"
#include "../reading/law_move.hpp"

namespace {

using namespace kin5;
namespace pg = kin5::program;

/// Draws from a seeded generator, as doubles made from its bits (the same on every library).
struct draws {
  std::mt19937_64 bits;
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(bits() >> 11) * 0x1p-53; }
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(bits() % n); }
  bool chance(double p) { return uniform(0, 1) < p; }
};

std::size_t from_environment(const char* name, std::size_t otherwise) {
  const char* v = std::getenv(name);
  return v && *v ? static_cast<std::size_t>(std::strtoull(v, nullptr, 10)) : otherwise;
}

/// Two machines read from machine files written here: catalog structures with other pivots and
/// axis points, under ids of their own (the tool's `--from-file`, `--to-file`).
std::vector<loaded_machine> file_machines() {
  std::vector<loaded_machine> out;
  const auto from_file = [&](machine_geometry g, std::string_view id, const vec3& shift_mm, double pivot_mm) {
    g.id = id;
    for (auto& a : g.rotary) a.point_mm = a.point_mm + shift_mm;
    g.tool.pivot_length_mm = pivot_mm;
    auto read = parse_machine_file(to_machine_file(g), std::string(id) + ".toml");
    REQUIRE(read.ok());
    out.push_back(std::move(*read.machine));
  };
  from_file(machines::ac_trunnion::model.geometry, "shop-ac-trunnion", {12.5, -40.0, 7.0}, 0.0);
  from_file(machines::dmu_50v::model.geometry, "shop-dmu-50v", {0.0, 3.0, -20.0}, 180.0);
  return out;
}

/// The machines the cases pick from: the catalog, then the machine files.
std::vector<const machine_model*> all_machines(const std::vector<loaded_machine>& files) {
  std::vector<const machine_model*> out(machines::catalog_models.begin(), machines::catalog_models.end());
  for (const auto& f : files) out.push_back(&f.model());
  return out;
}

std::string text_of(const vec3& v) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}
std::string rows(const mat3& m) { return text_of(m.row[0]) + text_of(m.row[1]) + text_of(m.row[2]); }

/// A setup that maps principal planes onto principal planes (so that arcs stay arcs): one of the
/// 24 rotations that permute the axes with signs, and an offset.
rigid_transform axis_permuting_setup(draws& d) {
  const vec3 e[3] = {unit_x, unit_y, unit_z};
  for (;;) {
    const std::size_t i = d.below(3), j = d.below(3);
    if (i == j) continue;
    const vec3 x = (d.chance(0.5) ? 1.0 : -1.0) * e[i], y = (d.chance(0.5) ? 1.0 : -1.0) * e[j];
    const mat3 r = mat3::from_columns(x, y, cross(x, y));
    return {r, vec3{std::round(d.uniform(-200, 200)), std::round(d.uniform(-200, 200)), std::round(d.uniform(-50, 50))}};
  }
}

using angles = std::array<radians, 2>;

/// Angles within the travel of `m`, `margin_deg` inside each end (continuous axes: ±180°).
angles angles_within(const machine_model& m, draws& d, double margin_deg = 1.0) {
  angles a{};
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const auto& t = m.rotary(i).travel;
    const double lo = t.continuous ? -180.0 : t.lower.value + margin_deg;
    const double hi = t.continuous ? 180.0 : t.upper.value - margin_deg;
    a[i] = to_radians(degrees{d.uniform(lo, std::max(lo, hi))});
  }
  return a;
}

/// A tool axis both machines reach: drawn on one, solved on the other; after a few tries, any.
/// Returns the source's angles.
angles shared_orientation(const machine_model& from, const machine_model& to, const mat3& to_R_from, draws& d) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (attempt % 2 == 0) {
      const vec3 u_to = tool_axis(to, angles_within(to, d));
      if (const auto s = inverse(from, to_R_from.transposed() * u_to).first_within_travel()) return *s;
    } else {
      const angles a = angles_within(from, d);
      if (inverse(to, to_R_from * tool_axis(from, a)).first_within_travel()) return a;
    }
  }
  return angles_within(from, d);
}

/// The next pose's angles, drawn as `shared_orientation` draws them, such that no rotary axis turns
/// by 180° or more from `previous` (a continuous axis takes the value nearest its last): under
/// tool-tip tracking such a turn is a sweep, which the plan keeps or refuses and `reverse` cuts into
/// GOTO points (their own laws, translate_laws' sweep laws), so a block would no longer be one
/// written block. After a few draws, the previous angles (no rotary motion).
angles next_orientation(const machine_model& from, const machine_model& to, const mat3& to_R_from, draws& d,
                        const angles& previous) {
  constexpr double half_turn_deg = 179.0;
  for (int attempt = 0; attempt < 8; ++attempt) {
    angles a = shared_orientation(from, to, to_R_from, d);
    bool near = true;
    for (std::size_t i = 0; i < from.rotary_count; ++i) {
      double delta_deg = to_degrees(a[i]).value - to_degrees(previous[i]).value;
      if (from.rotary(i).travel.continuous) {
        delta_deg -= 360.0 * std::round(delta_deg / 360.0);
        a[i] = to_radians(degrees{to_degrees(previous[i]).value + delta_deg});
      }
      near = near && std::abs(delta_deg) < half_turn_deg;
    }
    if (near) return a;
  }
  return previous;
}

/// How a case runs: `translate` NC → NC between two machines, `reverse` NC → APT CL data on one,
/// `post` APT CL data → NC on one.
enum class route { translate, reverse, post };

struct choice {
  route how = route::translate;
  const machine_model* from = nullptr;
  const machine_model* to = nullptr;
  pg::dialect source{}, target{};
  feed_policy feed = feed_policy::tcp;
  /// `--setup-*`: target_T_source when given, else the default (`default_setup`).
  std::optional<rigid_transform> setup;

  /// target_T_source of the run.
  rigid_transform target_T_source() const {
    if (how != route::translate) return rigid_transform::identity();
    return setup.value_or(default_setup(from->geometry.id, to->geometry.id));
  }

  std::string describe() const {
    const char* r = how == route::translate ? "translate" : how == route::reverse ? "reverse" : "post";
    return std::string(r) + " " + std::string(from->geometry.id) + " -> " + std::string(to->geometry.id) + ", " +
           std::string(pg::name(source)) + " -> " + std::string(pg::name(target)) + ", --feed " +
           std::string(name(feed)) +
           (setup ? ", setup rotation " + rows(setup->rotation) + " offset " + text_of(setup->translation_mm) : "");
  }
};

/// A case: where it runs, and the program model written in the source dialect (opening blocks
/// first: the tool change and tracking, which the minimiser keeps).
struct program_case {
  choice c;
  std::vector<pg::block> opening, body;
};

void set_rotary_words(const machine_model& m, pg::axis_words& w, const angles& a) {
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const double deg = to_degrees(a[i]).value;
    switch (m.rotary(i).letter) {
      case axis_letter::A: w.a_deg = deg; break;
      case axis_letter::B: w.b_deg = deg; break;
      default: w.c_deg = deg; break;
    }
  }
}

/// A random program for `c`: tool change and length, tracking on, spindle, then rapids, lines
/// with rotary motion, arcs where both dialects have them, feed changes and inverse time where
/// the source has it; tracking off and the end.
program_case make_case(const choice& c, draws& d) {
  program_case out{c, {}, {}};
  const bool cl_source = pg::capabilities_of(c.source).cl_data;
  const mat3 R = c.target_T_source().rotation;
  out.opening = test::tracking_start(c.source);
  {
    pg::block s;
    s.spindle_rpm = std::round(d.uniform(1000, 12000));
    s.state.spindle = pg::spindle_rotation::clockwise;
    out.opening.push_back(s);
  }
  const bool arcs = pg::capabilities_of(c.source).arcs && pg::capabilities_of(c.target).arcs;
  // G93 and G94 words in the source under every policy but --feed block-time, a per-minute
  // policy the check holds inverse time out of.
  const bool inverse_time_source =
      pg::capabilities_of(c.source).inverse_time_feed && c.feed != feed_policy::block_time;
  const std::size_t n = 1 + d.below(14);
  vec3 tip{d.uniform(-100, 100), d.uniform(-100, 100), d.uniform(0, 100)};
  angles a = shared_orientation(*c.from, *c.to, R, d);
  bool inverse_time = false, have_feed = false;
  std::optional<std::pair<vec3, double>> last_arc;  // centre and radius, while the last move was an arc
  const auto axes_of = [&](pg::block& b) {
    b.axes.x_mm = std::round(tip.x * 1000) / 1000, b.axes.y_mm = std::round(tip.y * 1000) / 1000,
    b.axes.z_mm = std::round(tip.z * 1000) / 1000;
    if (cl_source) b.axes.tool_axis = tool_axis(*c.from, a);
    else set_rotary_words(*c.from, b.axes, a);
  };
  for (std::size_t k = 0; k < n; ++k) {
    pg::block b;
    const double kind = d.uniform(0, 1);
    if (k == 0 || kind < 0.15) {  // a rapid, first to a pose of its own
      tip = {d.uniform(-100, 100), d.uniform(-100, 100), d.uniform(0, 100)};
      a = next_orientation(*c.from, *c.to, R, d, a);
      b.motion = pg::motion_kind::rapid;
      axes_of(b);
    } else if (arcs && kind < 0.3 && !cl_source) {  // an arc in XY under the same orientation
      const double r = d.uniform(5, 60), start = d.uniform(-pi, pi), sweep = d.uniform(0.2, 2.8);
      const bool ccw = d.chance(0.5);
      const vec3 centre{tip.x - r * std::cos(start), tip.y - r * std::sin(start), tip.z};
      const double end = start + (ccw ? sweep : -sweep);
      tip = {centre.x + r * std::cos(end), centre.y + r * std::sin(end), tip.z};
      b.motion = ccw ? pg::motion_kind::arc_ccw : pg::motion_kind::arc_cw;
      b.axes.x_mm = tip.x, b.axes.y_mm = tip.y;
      b.arc = pg::arc_words{pg::arc_plane::xy, centre, std::nullopt};
      last_arc = {centre, r};
    } else {  // a line, its orientation often changing
      if (last_arc && d.chance(0.3)) {  // a chord: to another point of the arc's circle, at another Z
        const auto& [centre, r] = *last_arc;
        const double at = d.uniform(-pi, pi);
        tip = {centre.x + r * std::cos(at), centre.y + r * std::sin(at), tip.z + d.uniform(-20, 20)};
      } else {
        tip = tip + vec3{d.uniform(-30, 30), d.uniform(-30, 30), d.uniform(-20, 20)};
      }
      if (d.chance(0.7)) a = next_orientation(*c.from, *c.to, R, d, a);
      b.motion = pg::motion_kind::linear;
      axes_of(b);
    }
    if (b.motion != pg::motion_kind::rapid) {
      if (inverse_time_source && d.chance(0.15)) {
        inverse_time = !inverse_time;
        b.feed_mode = inverse_time ? pg::feed_unit::inverse_time : pg::feed_unit::per_minute;
        have_feed = false;
      }
      // G93 takes F in every NC block; APT's FEDRAT/INVERS holds for the moves after it.
      if (inverse_time && (!cl_source || !have_feed || d.chance(0.5)))
        b.feed = std::round(d.uniform(0.5, 60) * 100) / 100;
      else if (!have_feed || d.chance(0.3)) b.feed = std::round(d.uniform(50, 5000));
      have_feed = true;
    }
    if (!b.arc) last_arc.reset();
    out.body.push_back(std::move(b));
  }
  return out;
}

/// The closing blocks: back to G94 where the body left G93, tracking off, the end.
std::vector<pg::block> closing(const program_case& p) {
  std::vector<pg::block> out;
  bool inverse_time = false;
  for (const auto& b : p.body)
    if (b.feed_mode) inverse_time = *b.feed_mode == pg::feed_unit::inverse_time;
  pg::block off;
  if (inverse_time) off.feed_mode = pg::feed_unit::per_minute;
  if (!pg::capabilities_of(p.c.source).cl_data) off.tcp = false;
  if (off.tcp || off.feed_mode) out.push_back(off);
  pg::block end;
  end.program_end = "M30";
  out.push_back(end);
  return out;
}

/// The source text of a case, written by its dialect's writer.
std::string source_text(const program_case& p) {
  pg::program model;
  model.language = p.c.source;
  model.file = "differential";
  for (const auto& b : p.opening) model.blocks.push_back(b);
  for (const auto& b : p.body) model.blocks.push_back(b);
  for (auto& b : closing(p)) model.blocks.push_back(std::move(b));
  return pg::write(p.c.source, model);
}

/// One motion block as the chain sees it, with its modal state.
struct motion {
  pg::source_location where;
  bool rapid = false;
  std::optional<pg::motion_kind> kind;
  vec3 start_mm{}, tip_mm{};
  vec3 axis{};
  std::optional<vec3> centre_mm;
  pg::arc_plane plane = pg::arc_plane::xy;
  std::optional<double> feed;
  bool inverse_time = false;
  std::array<double, 3> rotary_deg{};  ///< A, B, C as commanded (modal)
};

/// The motion blocks of `p` for machine `m`, through the Eigen chain; `trouble` names a motion
/// block the check cannot judge (one without tracking).
std::vector<motion> motions_of(const pg::program& p, const machine_model& m, bool cl_data, std::string& trouble) {
  std::vector<motion> out;
  vec3 tip{};
  std::array<double, 3> abc{};
  std::optional<vec3> vector;  // the last tool-axis vector, while the last orientation given was one
  bool tcp = cl_data, inverse_time = false;
  std::optional<double> feed;
  pg::motion_kind mode = pg::motion_kind::rapid;
  for (const pg::block& b : p.blocks) {
    if (b.tcp) tcp = *b.tcp || cl_data;
    if (b.feed_mode) inverse_time = *b.feed_mode == pg::feed_unit::inverse_time;
    if (b.feed) feed = b.feed;
    if (b.motion) mode = *b.motion;
    if (!b.moves() || b.machine_coordinates) continue;
    if (!tcp && trouble.empty()) trouble = b.where.file + ":" + std::to_string(b.where.line) + ": a move without tracking";
    motion mv;
    mv.where = b.where;
    mv.start_mm = tip;
    tip = {b.axes.x_mm.value_or(tip.x), b.axes.y_mm.value_or(tip.y), b.axes.z_mm.value_or(tip.z)};
    if (b.axes.a_deg) abc[0] = *b.axes.a_deg;
    if (b.axes.b_deg) abc[1] = *b.axes.b_deg;
    if (b.axes.c_deg) abc[2] = *b.axes.c_deg;
    if (b.axes.tool_axis) vector = normalized(*b.axes.tool_axis);
    else if (b.axes.has_rotary()) vector.reset();
    basic_axis_position<2> q{};
    for (std::size_t i = 0; i < m.rotary_count; ++i) {
      const auto l = m.rotary(i).letter;
      q.rotary[i] = to_radians(degrees{abc[l == axis_letter::A ? 0 : l == axis_letter::B ? 1 : 2]});
    }
    mv.axis = vector ? *vector
                     : eigen::to_kin5(Eigen::Vector3d(eigen::chain_work_T_tool(m, q).linear() *
                                                      eigen::to_eigen(m.tool_reference())));
    mv.tip_mm = tip;
    mv.rapid = mode == pg::motion_kind::rapid || b.feed_rapid;
    mv.kind = mode;
    if (b.arc) mv.centre_mm = b.arc->centre_mm, mv.plane = b.arc->plane;
    // In inverse time each NC feed move gives its own F (G93 F is not modal: RS274/NGC, Fanuc);
    // APT's FEDRAT/INVERS is a statement of its own that holds for the moves after it.
    mv.feed = inverse_time && !b.feed && !cl_data ? std::nullopt : feed;
    mv.inverse_time = inverse_time;
    mv.rotary_deg = abc;
    out.push_back(mv);
  }
  return out;
}

vec3 normal_of(pg::arc_plane p) { return p == pg::arc_plane::xy ? unit_z : p == pg::arc_plane::zx ? unit_y : unit_x; }

double arc_length(const motion& m) {
  const vec3 n = normal_of(m.plane);
  const vec3 c = *m.centre_mm;
  const vec3 s = m.start_mm - c - dot(m.start_mm - c, n) * n, e = m.tip_mm - c - dot(m.tip_mm - c, n) * n;
  double sweep = std::atan2(dot(cross(s, e), n), dot(s, e));
  if (m.kind == pg::motion_kind::arc_cw) sweep = -sweep;
  if (sweep <= 0) sweep += 2 * pi;
  const double along = dot(m.tip_mm - m.start_mm, n);
  return std::hypot(sweep * norm(s), along);
}

/// The tip's path length of a move, mm.
double tip_length(const motion& m) { return m.centre_mm ? arc_length(m) : norm(m.tip_mm - m.start_mm); }

/// (K16)'s length: tip and commanded rotary travel, millimetres and degrees counted alike.
double block_time_length(const motion& m, const motion* previous) {
  double rotary2 = 0;
  if (previous)
    for (std::size_t i = 0; i < 3; ++i) rotary2 += std::pow(m.rotary_deg[i] - previous->rotary_deg[i], 2);
  return std::sqrt(std::pow(tip_length(m), 2) + rotary2);
}

std::string at(const motion& m) { return m.where.file + ":" + std::to_string(m.where.line) + ": "; }

/// Tolerances: what rounding to the written decimals leaves (positions 0.001 mm or finer, angles
/// 0.001° or finer, F to its last decimal).
constexpr double tip_tolerance_mm = 2e-3;
constexpr double axis_tolerance = 1e-4;

/// The first difference between the source's motions and the written ones, or "".
/// `feed_decimals`: how many decimals the written F has.
std::string compare(const choice& c, const std::vector<motion>& s, const std::vector<motion>& t, int feed_decimals) {
  if (s.size() != t.size())
    return "block accounting: " + std::to_string(s.size()) + " motion blocks read, " + std::to_string(t.size()) +
           " written";
  const rigid_transform setup = c.target_T_source();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const motion &a = s[i], &b = t[i];
    const std::string where = at(a) + "(written " + at(b) + ") ";
    if (a.rapid != b.rapid) return where + (a.rapid ? "a rapid written as a feed move" : "a feed move written as a rapid");
    const bool arc_a = a.kind == pg::motion_kind::arc_cw || a.kind == pg::motion_kind::arc_ccw;
    const bool arc_b = b.kind == pg::motion_kind::arc_cw || b.kind == pg::motion_kind::arc_ccw;
    if (!a.rapid && arc_a != arc_b) return where + (arc_a ? "an arc written as a line" : "a line written as an arc");
    const vec3 tip = setup.rotation * a.tip_mm + setup.translation_mm;
    if (norm(b.tip_mm - tip) > tip_tolerance_mm)
      return where + "tool tip " + text_of(b.tip_mm) + ", source's mapped " + text_of(tip);
    const vec3 axis = setup.rotation * a.axis;
    if (norm(b.axis - axis) > axis_tolerance)
      return where + "tool axis " + text_of(b.axis) + ", source's mapped " + text_of(axis);
    if (arc_a && arc_b) {
      if (!a.centre_mm || !b.centre_mm) return where + "an arc without its centre";
      const vec3 n_a = (a.kind == pg::motion_kind::arc_ccw ? 1.0 : -1.0) * (setup.rotation * normal_of(a.plane));
      const vec3 n_b = (b.kind == pg::motion_kind::arc_ccw ? 1.0 : -1.0) * normal_of(b.plane);
      if (norm(n_a - n_b) > 1e-9) return where + "the arc turns the other way or in another plane";
      const vec3 centre = setup.rotation * *a.centre_mm + setup.translation_mm;
      const vec3 off = *b.centre_mm - centre;
      if (norm(off - dot(off, n_b) * n_b) > tip_tolerance_mm)
        return where + "arc centre " + text_of(*b.centre_mm) + ", source's mapped " + text_of(centre);
    }
    if (a.rapid) continue;
    if (!a.feed || !b.feed) return where + "a feed move without F";
    // The F the policy gives b, in b's unit; what it needs of the tip's path and the source.
    const double l = tip_length(a);
    const auto time_min = [l](const motion& m) { return m.inverse_time ? 1.0 / *m.feed : l / *m.feed; };
    std::optional<double> expected;
    double slack = 0;  // relative, for lengths the library takes from angles before rounding
    if (c.feed == feed_policy::inverse_time) {
      if (!b.inverse_time) return where + "--feed inverse-time wrote a move in per-minute feed";
      if (a.inverse_time || l > 1e-6) expected = 1.0 / time_min(a);  // no tip travel: the policy's own time
    } else if (c.feed == feed_policy::block_time && c.how == route::translate) {
      if (a.inverse_time || b.inverse_time) return where + "--feed block-time with inverse time";
      const double la = block_time_length(a, i ? &s[i - 1] : nullptr), lb = block_time_length(b, i ? &t[i - 1] : nullptr);
      if (la > 1e-6 && lb > 1e-6) expected = *a.feed * lb / la;
      slack = 1e-4;
    } else if (a.inverse_time == b.inverse_time) {
      expected = *a.feed;
    } else if (l > 1e-6) {
      expected = b.inverse_time ? 1.0 / time_min(a) : l / time_min(a);
    }
    if (expected && std::abs(*b.feed - *expected) > 0.5 * std::pow(10.0, -feed_decimals) + (slack + 1e-9) * *expected) {
      std::ostringstream why;
      why.precision(10);
      why << "F " << *b.feed << (b.inverse_time ? " (inverse time)" : "") << ", --feed " << name(c.feed) << " gives "
          << *expected << " (the source's F " << *a.feed << (a.inverse_time ? " inverse time" : "") << ")";
      return where + why.str();
    }
  }
  return {};
}

/// What one case gave: translated and checked, refused (with the first error), or a difference.
struct outcome {
  bool translated = false;
  std::string refusal;     ///< the first error of a refused run
  std::string difference;  ///< why the case fails, "" when it passes
  std::string source, written;
  std::size_t motions = 0, arcs = 0, inverse_time = 0;  ///< motion blocks checked, of them arcs and G93
};

outcome run_text(const choice& c, std::string source_text);

outcome run_case(const program_case& p) {
  std::string text;
  try {
    text = source_text(p);
  } catch (const std::invalid_argument& e) {  // a minimised body that starts with an arc
    outcome o;
    o.difference = std::string("the source cannot be written: ") + e.what();
    return o;
  }
  return run_text(p.c, std::move(text));
}

/// A case's run from its source text (read, as the tool does, with the source's reader: a
/// program that jumps or calls is checked as it runs).
outcome run_text(const choice& c, std::string source_text) {
  outcome o;
  o.source = std::move(source_text);
  const bool cl_source = pg::capabilities_of(c.source).cl_data, cl_target = pg::capabilities_of(c.target).cl_data;
  const pg::read_result source = pg::read(c.source, o.source, "differential");
  if (!source.ok()) {
    o.difference = "the source does not read: " + source.errors.front().to_string();
    return o;
  }
  std::unique_ptr<block_translator> t;
  if (c.how == route::post) t = make_post(*c.to, c.source, c.target, "differential", report_detail::exceptions_only);
  else if (c.how == route::reverse) t = make_reverse(*c.from, c.source, "differential", report_detail::exceptions_only);
  else {
    translate_options options;
    options.feed = c.feed;
    options.output_dialect = c.target;
    options.setup = c.setup;
    t = make_translator(*c.from, *c.to, c.source, "differential", options, report_detail::exceptions_only);
  }
  string_sink out;
  const stream_result run = stream_text(*t, o.source, c.source, "differential", c.target, out);
  if (!run.ok(*t)) {
    const translation& r = t->result();
    o.refusal = !run.input.ok()      ? run.input.errors.front().message
                : !r.errors.empty()  ? r.errors.begin()->message
                : run.writer_error   ? run.writer_error->message
                                     : "the sink failed";
    if (o.refusal.empty()) o.difference = "a refusal without a message";
    return o;
  }
  o.translated = true;
  o.written = out.text;
  if (t->result().blocks_read != source.parsed.blocks.size())  // the blocks run
    o.difference = "block accounting: " + std::to_string(source.parsed.blocks.size()) + " blocks in the source, " +
                   std::to_string(t->result().blocks_read) + " read by the translation";
  const pg::read_result back = pg::read(c.target, o.written, "written");
  if (!back.ok()) {
    o.difference = "the written program does not read back: " + back.errors.front().to_string();
    return o;
  }
  const pg::read_result again =
      pg::read(c.target, pg::write(c.target, back.parsed, write_settings_for(c.target, t->result().output_decimals)), "again");
  if (!again.ok()) {
    o.difference = "the written program, read and written again, does not read: " + again.errors.front().to_string();
    return o;
  }
  if (const std::string d = test::model_difference(back.parsed, again.parsed); !d.empty()) {
    o.difference = "the written program, read and written again, reads as another program: " + d;
    return o;
  }
  std::string trouble;
  const auto s = motions_of(source.parsed, *c.from, cl_source, trouble);
  const auto w = motions_of(back.parsed, *c.to, cl_target, trouble);
  if (!trouble.empty()) o.difference = trouble;
  else if (o.difference.empty()) o.difference = compare(c, s, w, t->result().output_decimals.feed);
  for (const motion& m : w) {
    ++o.motions;
    o.arcs += m.centre_mm ? 1 : 0;
    o.inverse_time += m.inverse_time && !m.rapid ? 1 : 0;
  }
  return o;
}

/// What a difference says without its places and numbers: the minimiser keeps a case failing
/// for the same reason.
std::string reason(const std::string& difference) {
  std::size_t from = difference.rfind(") ");
  from = from == std::string::npos ? 0 : from + 2;
  return difference.substr(from, difference.find_first_of("0123456789(", from) - from);
}

/// The case with blocks of its body dropped, one at a time, for as long as it still fails for
/// the same reason.
program_case minimised(program_case p, const std::string& why) {
  for (bool smaller = true; smaller;) {
    smaller = false;
    for (std::size_t k = 0; k < p.body.size() && p.body.size() > 1; ++k) {
      program_case q = p;
      q.body.erase(q.body.begin() + static_cast<std::ptrdiff_t>(k));
      if (const std::string d = run_case(q).difference; !d.empty() && reason(d) == why) {
        p = std::move(q);
        smaller = true;
        --k;
      }
    }
  }
  return p;
}

/// A random case: the route, the machines, the dialects and the policy, then the program.
program_case draw_case(draws& d, const std::vector<const machine_model*>& ms) {
  const auto nc = pg::nc_dialect_ids();
  choice c;
  const double r = d.uniform(0, 1);
  c.how = r < 0.7 ? route::translate : r < 0.85 ? route::reverse : route::post;
  c.from = ms[d.below(ms.size())];
  c.to = c.how == route::translate ? ms[d.below(ms.size())] : c.from;
  c.source = c.how == route::post ? pg::cl_data_dialect() : nc[d.below(nc.size())];
  c.target = c.how == route::reverse ? pg::cl_data_dialect() : nc[d.below(nc.size())];
  if (c.how == route::translate) {
    if (d.chance(0.3)) c.setup = axis_permuting_setup(d);
    const double f = d.uniform(0, 1);
    c.feed = f < 0.6 ? feed_policy::tcp : f < 0.8 || !pg::capabilities_of(c.target).inverse_time_feed
                                              ? feed_policy::block_time
                                              : feed_policy::inverse_time;
  }
  return make_case(c, d);
}

}  // namespace

TEST_CASE("differential: random programs in every dialect agree with the Eigen chain when translated") {
  const std::size_t cases = from_environment("KIN5_DIFFERENTIAL_CASES", 2000);
  const std::size_t seed = from_environment("KIN5_DIFFERENTIAL_SEED", 1);
  const auto files = file_machines();
  const auto ms = all_machines(files);
  draws d{std::mt19937_64(seed)};
  std::size_t translated = 0, motions = 0, arcs = 0, inverse_time = 0;
  std::map<std::string, std::size_t> refusals, checked;  // by first error; translated by route and dialects
  for (std::size_t k = 0; k < cases; ++k) {
    const program_case p = draw_case(d, ms);
    const outcome o = run_case(p);
    if (!o.difference.empty()) {
      const outcome m = run_case(minimised(p, reason(o.difference)));
      FAIL("seed " << seed << ", case " << k << ": " << p.c.describe() << "\n" << o.difference << "\nminimised: " << m.difference
                   << "\n--- source (minimised) ---\n" << m.source << "--- written ---\n" << m.written);
    }
    if (!o.translated) {
      // One kind once: the message up to its first parenthesis (the angles), or its first words.
      std::string message = o.refusal.substr(0, o.refusal.find('('));
      if (message.size() > 72) message = message.substr(0, message.rfind(' ', 72)) + " …";
      ++refusals[message];
      continue;
    }
    ++translated, motions += o.motions, arcs += o.arcs, inverse_time += o.inverse_time;
    const std::string how = p.c.how == route::translate ? "translate " : p.c.how == route::reverse ? "reverse " : "post ";
    ++checked[how + std::string(pg::name(p.c.source)) + " -> " + std::string(pg::name(p.c.target))];
  }
  std::ostringstream tally;
  tally << translated << " of " << cases << " programs translated and checked (" << motions << " motion blocks, " << arcs
        << " arcs, " << inverse_time << " in inverse time); refused:\n";
  for (const auto& [message, count] : refusals) tally << "  " << count << " x " << message << "\n";
  tally << "checked:\n";
  for (const auto& [pair, count] : checked) tally << "  " << count << " x " << pair << "\n";
  INFO(tally.str());
  if (std::getenv("KIN5_DIFFERENTIAL_SHOW")) WARN(tally.str());
  // The generator reaches the translation: most programs translate, with arcs and inverse time.
  CHECK(translated * 10 >= cases * 9);
  CHECK(arcs > 0);
  CHECK(inverse_time > 0);
}

TEST_CASE("differential: a CAM-style Heidenhain program with Q parameters, subprograms, repeats and jumps") {
  // In the style of hyperMILL's TNC output, of the project's own: feeds in Q parameters, a safe
  // start in a subprogram after M30, passes deepened by a section repeat, a corner subprogram
  // called from it, and a circle of points stepped by an FN 12 jump back. Read as the TNC runs
  // it, translated, and each move of the run checked against the Eigen chain of both machines.
  const std::string text =
      "0 BEGIN PGM SWARF_FLOW MM\n"
      "1 ; --- PROGRAM: SWARF_FLOW / POSTED IN THE STYLE OF A CAM OUTPUT\n"
      "2 BLK FORM 0.1 Z X-50 Y-50 Z-40\n"
      "3 BLK FORM 0.2 X+50 Y+50 Z+0\n"
      "4 FN 0: Q1=+1200 ; XY FEED RATE\n"
      "5 FN 0: Q2=+400 ; Z FEED RATE\n"
      "6 FN 0: Q10=+0 ; DEPTH\n"
      "7 FN 0: Q11=-1.5 ; STEP\n"
      "8 * - SWARF T5\n"
      "9 TOOL CALL 5 Z S9000 DL+0 DR+0\n"
      "10 M3 M8\n"
      "11 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
      "12 CALL LBL 1 ; SAFE START\n"
      "13 L X-40 Y-40 Z+50 B+30 C+45 R0 FMAX\n"
      "14 LBL 2\n"
      "15 Q10 = Q10 + Q11\n"
      "16 L Z+Q10 FQ2\n"
      "17 L X+40 Y-40 B+32.5 C+40 FQ1\n"
      "18 L X+40 Y+40 B+35 C+35\n"
      "19 CALL LBL \"CORNER\"\n"
      "20 L X-40 Y-40 B+30 C+45\n"
      "21 CALL LBL 2 REP 2\n"
      "22 L Z+50 FMAX\n"
      "23 FN 0: Q20=-60\n"
      "24 LBL \"SPIRAL\"\n"
      "25 Q21 = 20 * COS Q20\n"
      "26 Q22 = 20 * SIN Q20\n"
      "27 L X+Q21 Y+Q22 Z-6 B+20 C+Q20 FQ1\n"
      "28 FN 1: Q20 = +Q20 + +30\n"
      "29 FN 12: IF +Q20 LT +180 GOTO LBL \"SPIRAL\"\n"
      "30 L Z+50 FMAX\n"
      "31 CALL LBL 1\n"
      "32 FUNCTION RESET TCPM\n"
      "33 M5 M9\n"
      "34 M30\n"
      "35 * --- LBL BEGIN\n"
      "36 LBL 1 ; SAFE POSITION\n"
      "37 L X+0 Y+0 Z+100 B+0 C+0 R0 FMAX\n"
      "38 LBL 0\n"
      "39 LBL \"CORNER\"\n"
      "40 L X-40 Y+40 B+35 C+50 FQ1\n"
      "41 LBL 0\n"
      "42 END PGM SWARF_FLOW MM\n";
  const pg::read_result run = pg::read(*pg::parse_dialect("heidenhain"), text, "swarf_flow.h");
  REQUIRE(run.ok());
  std::size_t moves = 0;
  for (const pg::block& b : run.parsed.blocks) moves += b.moves() ? 1 : 0;
  CHECK(moves == 1 + 1 + 3 * 5 + 1 + 8 + 1 + 1);  // safe start, approach, 3 passes, up, 8 points, up, retract
  for (const char* to : {"dmu-80p", "ac-trunnion", "bc-trunnion", "sajo-12000p"})
    for (const char* dialect : {"heidenhain", "siemens", "iso"}) {
      CAPTURE(to, dialect);
      choice c;
      c.from = machines::find_machine("dmu-80p");
      c.to = machines::find_machine(to);
      c.source = *pg::parse_dialect("heidenhain");
      c.target = *pg::parse_dialect(dialect);
      const outcome o = run_text(c, text);
      INFO(o.refusal << "\n" << o.written);
      CHECK(o.translated);
      CHECK(o.difference == "");
      CHECK(o.motions == moves);
    }
}

namespace {

/// `g` with the homes of a shop's machine file: X, Y, Z (mm, machine coordinates) and the
/// reference angle 0 of every rotary axis.
loaded_machine with_homes(machine_geometry g, std::string_view id, const vec3& home_mm) {
  g.id = id;
  g.linear[0].home_mm = home_mm.x, g.linear[1].home_mm = home_mm.y, g.linear[2].home_mm = home_mm.z;
  for (auto& a : g.rotary)
    if (a.letter != axis_letter::none) a.home_deg = degrees{0.0};
  auto read = parse_machine_file(to_machine_file(g), std::string(id) + ".toml");
  REQUIRE(read.ok());
  return std::move(*read.machine);
}

/// The tool axis of machine `m` (part frame) at commanded A, B, C (degrees), by the Eigen chain.
vec3 chain_axis(const machine_model& m, const std::array<double, 3>& abc_deg) {
  basic_axis_position<2> q{};
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const auto l = m.rotary(i).letter;
    q.rotary[i] = to_radians(degrees{abc_deg[l == axis_letter::A ? 0 : l == axis_letter::B ? 1 : 2]});
  }
  return eigen::to_kin5(Eigen::Vector3d(eigen::chain_work_T_tool(m, q).linear() * eigen::to_eigen(m.tool_reference())));
}

}  // namespace

TEST_CASE("differential: the CAM safe start in every NC dialect, on other kinematics, agrees with the Eigen chain") {
  // Retract, park, rotary positioning with tracking off, tracking on, approach, cut, retract,
  // park, end: from a B/C trunnion whose homes are its machine zero to an A/C trunnion whose
  // homes are X100 Y-50 Z-10, under a setup turning 90° about Z. The retract and the parks are
  // the same distances from the homes (M140 MB MAX: the top of Z's travel), the positioning
  // gives the same tool axis in the part, and every move under tracking the same tip and axis.
  const loaded_machine from = with_homes(machines::bc_trunnion::model.geometry, "shop-bc", {0, 0, 0});
  const loaded_machine to = with_homes(machines::ac_trunnion::model.geometry, "shop-ac", {100, -50, -10});
  const rigid_transform setup{rotation(unit_z, radians{pi / 2}), {5, -3, 0}};
  struct row {
    std::string_view dialect, text;
    bool tool_axis_limit;  // the first retract is M140 MB MAX
  };
  const std::vector<row> rows = {
      {"iso", "%\nO1000\nG90 G17 G21 G94\nG53 G0 Z0.\nG91 G28 X0. Y0.\nG91 G28 B0. C0.\nG90\nT1 M6\nS8000 M3\n"
              "G0 B30. C45.\nG43.4 H1\nG0 X10. Y5. Z50. B30. C45.\nG1 Z2. F500.\nG1 X40. B20. C60. F800.\nG0 Z50.\nG49\n"
              "G53 G0 Z0.\nG53 G0 X-200. Y-100.\nM30\n%\n", false},
      {"haas", "%\nO1000\nG90 G17 G21 G94\nG53 G0 Z0.\nG91 G28 X0. Y0.\nG91 G28 B0. C0.\nG90\nT1 M6\nS8000 M3\n"
               "G0 B30. C45.\nG234 H1\nG0 X10. Y5. Z50. B30. C45.\nG1 Z2. F500.\nG1 X40. B20. C60. F800.\nG0 Z50.\nG49\n"
               "G53 G0 Z0.\nG53 G0 X-200. Y-100.\nM30\n%\n", false},
      {"linuxcnc", "%\nG21 G90 G17 G94\nG53 G0 Z0\nG53 G0 X0 Y0\nG53 G0 B0 C0\nT1 M6\nG43 H1\nS8000 M3\nG0 B30 C45\nM428\n"
                   "G0 X10 Y5 Z50 B30 C45\nG1 Z2 F500\nG1 X40 B20 C60 F800\nG0 Z50\nM429\nG53 G0 Z0\nG53 G0 X-200 Y-100\nM2\n%\n",
       false},
      {"siemens", "G710 G90 G17 G94\nSUPA G0 Z0\nSUPA G0 X0 Y0\nSUPA G0 B0 C0\nT1 M6\nD1\nS8000 M3\nG0 B30 C45\nTRAORI\n"
                  "G0 X10 Y5 Z50 B30 C45\nG1 Z2 F500\nG1 X40 B20 C60 F800\nG0 Z50\nTRAFOOF\nSUPA G0 Z0\nSUPA G0 X-200 Y-100\nM30\n",
       false},
      {"heidenhain", "0 BEGIN PGM CAM MM\n1 TOOL CALL 1 Z S8000\n2 M140 MB MAX\n3 L X+0 Y+0 FMAX M91\n4 L B+30 C+45 FMAX\n"
                     "5 M128\n6 L X+10 Y+5 Z+50 B+30 C+45 FMAX M3\n7 L Z+2 F500\n8 L X+40 B+20 C+60 F800\n9 L Z+50 FMAX\n"
                     "10 M129\n11 L Z+0 FMAX M91\n12 L X-200 Y-100 FMAX M91\n13 END PGM CAM MM\n", true},
  };
  const std::vector<std::string_view> targets = {"iso", "siemens", "heidenhain", "linuxcnc", "haas"};
  for (const row& r : rows)
    for (const std::string_view target_name : targets) {
      const pg::dialect source = *pg::parse_dialect(r.dialect), target = *pg::parse_dialect(target_name);
      CAPTURE(r.dialect, target_name);
      translate_options options;
      options.output_dialect = target;
      options.setup = setup;
      const auto t = make_translator(from.model(), to.model(), source, "cam", options, report_detail::exceptions_only);
      string_sink out;
      const stream_result run = stream_text(*t, std::string(r.text), source, "cam", target, out);
      CAPTURE(out.text);
      std::string errors;
      for (const auto& e : t->result().errors) errors += e.to_string() + "\n";
      CAPTURE(errors);
      REQUIRE(run.ok(*t));
      const pg::read_result in = pg::read(source, std::string(r.text), "cam");
      const pg::read_result back = pg::read(target, out.text, "written");
      REQUIRE(back.ok());
      // Moves in machine coordinates, in order: retract, park, [positioning], retract, park.
      std::vector<const pg::block*> machine_moves;
      for (const auto& b : back.parsed.blocks)
        if (b.machine_coordinates && b.axes.has_linear()) machine_moves.push_back(&b);
      REQUIRE(machine_moves.size() == 4);
      CHECK(machine_moves[0]->axes.z_mm == (r.tool_axis_limit ? to.model().linear(2).travel.upper_mm : -10.0));
      CHECK((machine_moves[1]->axes.x_mm == 100.0 && machine_moves[1]->axes.y_mm == -50.0));
      CHECK(machine_moves[2]->axes.z_mm == -10.0);
      CHECK((machine_moves[3]->axes.x_mm == -100.0 && machine_moves[3]->axes.y_mm == -150.0));
      // The positioning B30 C45: rotary words alone, with tracking off, for the same tool axis.
      const vec3 u_source = chain_axis(from.model(), {0, 30, 45});
      std::optional<std::array<double, 3>> positioned;
      bool tracking = false;
      for (const auto& b : back.parsed.blocks) {
        if (b.tcp) tracking = *b.tcp;
        if (b.axes.has_rotary() && !b.axes.has_linear() && !tracking && b.axes.a_deg != 0.0)
          positioned = std::array<double, 3>{b.axes.a_deg.value_or(0), b.axes.b_deg.value_or(0), b.axes.c_deg.value_or(0)};
      }
      REQUIRE(positioned);
      CHECK(norm(chain_axis(to.model(), *positioned) - setup.rotation * u_source) <= axis_tolerance);
      // Under tracking: the same tips, mapped by the setup, and the same tool axes.
      std::string trouble;
      std::vector<motion> s = motions_of(in.parsed, from.model(), false, trouble);
      std::vector<motion> w = motions_of(back.parsed, to.model(), false, trouble);
      // the positioning is the one move without tracking on either side
      const auto tracked = [](std::vector<motion>& ms) {
        std::erase_if(ms, [](const motion& m) { return m.rotary_deg == std::array<double, 3>{} || m.tip_mm == vec3{}; });
      };
      tracked(s), tracked(w);
      REQUIRE(s.size() == 4);
      REQUIRE(w.size() == 4);
      for (std::size_t k = 0; k < s.size(); ++k) {
        CAPTURE(k);
        CHECK(norm(w[k].tip_mm - setup.map_point(s[k].tip_mm)) <= tip_tolerance_mm);
        CHECK(norm(w[k].axis - setup.rotation * s[k].axis) <= axis_tolerance);
      }
    }
}

/// @file translate.hpp
/// Translating an NC program from one machine to another, block by block, and its two halves:
/// `reverse` (NC → APT CL data) and `post` (CL data → NC). For each motion block:
///
///     tip_s = programmed XYZ (TCP on),  u_s = tool_axis<From>(angles)      (K1), (G1)
///     tip_d = target_T_source · tip_s,  u_d = R · u_s                        (K10)/(K11)
///     all solutions of inverse<To>(u_d) within travel                       (G3)/(G4), S2
///     the sequence of least total rotary travel over the whole program      (plan_rotary_path)
///     F by the feed policy                                                  (K15)–(K17)
///
/// Every input block is accounted for: written (mapped), passed through unchanged, or an
/// error naming its line. Blocks the target cannot reach are errors carrying their gap, never
/// clamped or dropped; any error means the output must not be written. Maths and choices:
/// docs/translation.md.
/// @code
///   auto t = kin5::translate<kin5::machines::sajo_12000p, kin5::machines::dmu_80p>(nc);
///   if (!t.ok()) for (const auto& e : t.errors) std::cerr << e.to_string() << '\n';
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../kinematics/branch.hpp"
#include "../kinematics/branch_plan.hpp"
#include "feed.hpp"
#include "../kinematics/inverse.hpp"
#include "../machines/catalog.hpp"
#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "../program/modal.hpp"
#include "../program/text.hpp"
#include "setup.hpp"

namespace kin5 {

/// How to translate.
struct translate_options {
  feed_policy feed = feed_policy::tcp;
  /// target_T_source; default: `default_setup<From, To>()`.
  std::optional<rigid_transform> setup;
  program::dialect output_dialect = program::dialect::heidenhain;
};

/// What happened to one motion block.
struct block_report {
  program::source_location where;
  matchability match = matchability::direct;
  radians gap{};              ///< angle from the tool axis to the target's reach, when unreachable
  std::string source_angles;  ///< the source pose as written/modal, e.g. "A=-77.954 B=3.536" (degrees)
  std::string why;            ///< the reason, when not direct
};

/// The result of `translate`, `reverse` or `post`.
struct translation {
  program::program output;                   ///< in the output dialect
  std::vector<block_report> reports;         ///< one per motion block, in program order
  std::vector<program::diagnostic> errors;   ///< any error: the output must not be written
  std::vector<program::diagnostic> warnings; ///< e.g. a branch switch, a passed-through block
  std::size_t blocks_read = 0, blocks_written = 0, passed_through = 0;
  /// Motion blocks per matchability class, indexed by `matchability` (direct, other branch,
  /// unreachable): complete even when `reports` keeps only the exceptions.
  std::array<std::size_t, 3> per_class{};
  bool ok() const { return errors.empty(); }
};

// ---------------------------------------------------------------------------------------------

namespace translate_detail {

inline std::string fixed(double v, int decimals) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, r.ptr);
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);  // no "-0.000"
  return s;
}

inline const std::optional<double>& rotary_word(const program::axis_words& w, axis_letter l) {
  return l == axis_letter::A ? w.a_deg : (l == axis_letter::B ? w.b_deg : w.c_deg);
}
inline std::optional<double>& rotary_word(program::axis_words& w, axis_letter l) {
  return l == axis_letter::A ? w.a_deg : (l == axis_letter::B ? w.b_deg : w.c_deg);
}

inline constexpr std::string_view tcp_off_message =
    "motion without tool-tip tracking (TCP): its tool tip depends on the machine geometry, which "
    "kin5 does not model yet; switch TCP on (TRAORI, M128, G43.4) before the first motion";
inline constexpr std::string_view rotary_tcp_off_message =
    "rotary motion without tool-tip tracking (TCP) needs the machine geometry, which kin5 does not "
    "model yet";

/// One input block after the source side: what it is and, for a motion, its pose.
struct source_step {
  enum class kind { copy, passthrough, motion, failed };
  kind what = kind::copy;
  vec3 tip_mm{};                      ///< source workpiece frame
  vec3 axis = unit_z;                 ///< source workpiece frame, unit
  std::array<double, 2> rotary_deg{}; ///< source commanded angles, machine order (K16)
  std::size_t rotary_n = 0;
  std::array<char, 2> rotary_letters{};  ///< the letters of `rotary_deg`
  bool principal = true;                 ///< set when classified (the second pass)
  program::motion_kind motion = program::motion_kind::linear;
  bool rapid = false;
  std::optional<double> feed;         ///< F in effect
  program::feed_unit feed_mode = program::feed_unit::per_minute;
  std::optional<vec3> start_mm;       ///< tip before the block, when known
  program::arc_plane plane = program::arc_plane::xy;
  std::optional<vec3> centre_mm;      ///< arc centre, in the plane of the start point
  std::optional<double> radius_mm;
};

/// The source pose of a motion step as a report shows it: "A=-77.954 B=3.536" (degrees, letters
/// in alphabetical order), or "I=… J=… K=…" for a tool-axis vector.
inline std::string angles_text(const source_step& s) {
  if (s.rotary_n == 0) return "I=" + fixed(s.axis.x, 7) + " J=" + fixed(s.axis.y, 7) + " K=" + fixed(s.axis.z, 7);
  std::string text;
  for (char letter : {'A', 'B', 'C'})
    for (std::size_t i = 0; i < s.rotary_n; ++i)
      if (s.rotary_letters[i] == letter) {
        if (!text.empty()) text += ' ';
        text += std::string(1, letter) + "=" + fixed(s.rotary_deg[i], 3);
      }
  return text;
}

/// Source side of an NC program of machine From: angles → tool axis by (G1).
template <machine From>
struct nc_source {
  static constexpr bool needs_tcp = true;
  static constexpr bool has_angles = true;
  /// `kinematics`: whether to compute the tool axis and the branch (else only the angles).
  static std::optional<std::string> pose(const program::modal_state& m, source_step& s, std::string& warned,
                                         std::vector<std::string>& notes, bool kinematics) {
    if (m.tool_axis) {  // a tool-axis vector written in the program (G43.5 IJK, LN TX TY TZ)
      s.axis = *m.tool_axis;
      s.rotary_n = 0;
      return std::nullopt;
    }
    rotary_angles<From> angles{};
    s.rotary_n = rotary_count<From>;
    for (std::size_t i = 0; i < rotary_count<From>; ++i) {
      const char letter = to_char(From::rotary[i].letter);
      const auto v = m.value(letter);
      if (!v && warned.find(letter) == std::string::npos) {
        warned.push_back(letter);
        notes.push_back(std::string("rotary axis ") + letter + " has no value yet; taken as 0 (the zero pose)");
      }
      s.rotary_letters[i] = letter;
      s.rotary_deg[i] = v.value_or(0.0);
      angles[i] = to_radians(degrees{s.rotary_deg[i]});
    }
    if (!kinematics) return std::nullopt;
    s.axis = tool_axis<From>(angles);
    s.principal = on_principal_branch<From>(angles, s.axis);
    return std::nullopt;
  }
};

/// Source side of APT CL data: the tool axis is written (GOTO/x,y,z,i,j,k); +Z until the first.
struct cl_source {
  static constexpr bool needs_tcp = false;
  static constexpr bool has_angles = false;
  static std::optional<std::string> pose(const program::modal_state& m, source_step& s, std::string&,
                                         std::vector<std::string>&, bool) {
    s.axis = m.tool_axis.value_or(unit_z);
    if (!(norm(s.axis) > 0.5)) return std::string("tool-axis vector of zero length");
    return std::nullopt;
  }
};

inline vec3 plane_normal(program::arc_plane p) {
  return p == program::arc_plane::xy ? unit_z : (p == program::arc_plane::zx ? unit_y : unit_x);
}

/// The principal plane whose normal is ±`n`, and whether it is −, if `n` is a principal axis.
inline std::optional<std::pair<program::arc_plane, bool>> principal_plane(const vec3& n) {
  constexpr double tol = 1e-9;
  if (math::abs(math::abs(n.z) - 1.0) < tol) return std::pair{program::arc_plane::xy, n.z < 0};
  if (math::abs(math::abs(n.y) - 1.0) < tol) return std::pair{program::arc_plane::zx, n.y < 0};
  if (math::abs(math::abs(n.x) - 1.0) < tol) return std::pair{program::arc_plane::yz, n.x < 0};
  return std::nullopt;
}

inline std::string_view plane_name(program::arc_plane p) {
  return p == program::arc_plane::xy ? "XY (G17)" : (p == program::arc_plane::zx ? "ZX (G18)" : "YZ (G19)");
}

inline double component(const vec3& v, program::arc_plane p) {
  return p == program::arc_plane::xy ? v.z : (p == program::arc_plane::zx ? v.y : v.x);
}
inline void set_component(vec3& v, program::arc_plane p, double value) {
  (p == program::arc_plane::xy ? v.z : (p == program::arc_plane::zx ? v.y : v.x)) = value;
}

/// Length of the tool-tip path of an arc from `start` to `end` about `centre` (or of signed
/// radius `radius`), turning about +normal if `ccw`; helical rise included.
inline double arc_length(const source_step& s, const vec3& start, const vec3& end) {
  const vec3 n = plane_normal(s.plane);
  const double rise = dot(end - start, n);
  const vec3 a = (start - dot(start, n) * n), b = (end - dot(end, n) * n);
  double radius = 0.0, sweep = 0.0;
  if (s.centre_mm) {
    const vec3 c = *s.centre_mm - dot(*s.centre_mm, n) * n;
    radius = norm(a - c);
    sweep = std::atan2(dot(n, cross(a - c, b - c)), dot(a - c, b - c));  // ccw angle in (−π, π]
    if (s.motion == program::motion_kind::arc_cw) sweep = -sweep;
    if (sweep <= 0) sweep += 2.0 * pi;  // a full circle when start == end
  } else if (s.radius_mm) {
    radius = math::abs(*s.radius_mm);
    const double half = math::clamp(norm(b - a) / (2.0 * radius), 0.0, 1.0);
    sweep = 2.0 * std::asin(half);
    if (*s.radius_mm < 0) sweep = 2.0 * pi - sweep;
  }
  return std::sqrt(radius * sweep * radius * sweep + rise * rise);
}

inline program::diagnostic at(const program::block& b, std::string message) { return {b.where, std::move(message)}; }

/// The source side: walks the program's blocks in order with their modal state and turns each
/// into a step. Diagnostics go to `out` when given (the first pass), else nowhere (the second
/// pass, which sees the same blocks again).
template <class Source>
class source_walker {
 public:
  /// The step of block `b`; `kinematics`: whether to compute the tool axis and
  /// `source_step::principal` of a motion step (else only its angles).
  source_step next(const program::block& b, translation* out, bool kinematics) {
    auto warn = [&](program::diagnostic d) {
      if (out) out->warnings.push_back(std::move(d));
    };
    auto fail = [&](program::diagnostic d) {
      if (out) out->errors.push_back(std::move(d));
    };
    const program::modal_state before = m;
    m.apply(b);
    source_step s;
    if (b.machine_coordinates) {
      s.what = source_step::kind::passthrough;
      warn(at(b, "machine-coordinate move passed through unchanged, not through kinematics; "
                                   "the tool position after it is unknown"));
      return s;
    }
    if (b.passthrough) {
      s.what = source_step::kind::passthrough;
      warn(at(b, "block not understood: passed through unchanged"));
      return s;
    }
    if (!b.moves()) return s;  // copy
    s.what = source_step::kind::failed;
    if (Source::needs_tcp && !m.tcp) {
      fail(at(b, std::string(b.axes.has_rotary() || m.rotary_moved ? rotary_tcp_off_message
                                                                                   : tcp_off_message)));
      return s;
    }
    const auto kind = m.motion_of(b);
    if (!kind) warn(at(b, "no motion mode in effect; taken as linear (G1)"));
    s.motion = kind.value_or(program::motion_kind::linear);
    s.rapid = s.motion == program::motion_kind::rapid || b.feed_rapid;
    std::string missing;
    for (char letter : {'X', 'Y', 'Z'})
      if (!m.value(letter)) missing += letter;
    if (!missing.empty()) {
      fail(at(b, "the tool tip is not known: no value yet for " + missing +
                                     " (the first motion must give the full position)"));
      return s;
    }
    s.tip_mm = {*m.x_mm, *m.y_mm, *m.z_mm};
    if (before.x_mm && before.y_mm && before.z_mm) s.start_mm = vec3{*before.x_mm, *before.y_mm, *before.z_mm};
    std::vector<std::string> notes;
    if (auto error = Source::pose(m, s, warned, notes, kinematics)) {
      fail(at(b, *error));
      return s;
    }
    for (auto& note : notes) warn(at(b, std::move(note)));
    s.feed = m.feed;
    s.feed_mode = m.feed_mode;
    if (program::is_arc(s.motion)) {
      s.plane = b.arc ? b.arc->plane : m.plane.value_or(program::arc_plane::xy);
      s.radius_mm = b.arc ? b.arc->radius_mm : std::nullopt;
      if (!s.radius_mm) s.centre_mm = (b.arc && b.arc->centre_mm) ? b.arc->centre_mm : m.arc_centre_mm;
      const bool rotary_moves = b.axes.tool_axis.has_value() ||
                                (b.axes.a_deg && b.axes.a_deg != before.a_deg) ||
                                (b.axes.b_deg && b.axes.b_deg != before.b_deg) ||
                                (b.axes.c_deg && b.axes.c_deg != before.c_deg);
      if (rotary_moves) {
        fail(at(b, "circular move cannot be mapped: the rotary axes move during it"));
        return s;
      }
      if (!s.start_mm) {
        fail(at(b, "circular move cannot be mapped: its start point is not known"));
        return s;
      }
      if (!s.centre_mm && !s.radius_mm) {
        fail(at(b, "circular move cannot be mapped: no centre or radius"));
        return s;
      }
      if (s.centre_mm) set_component(*s.centre_mm, s.plane, component(*s.start_mm, s.plane));
    }
    s.what = source_step::kind::motion;
    return s;
  }

 private:
  program::modal_state m;
  std::string warned;
};

/// Maps the plane-selection words G17/G18/G19 kept in a block through the setup rotation.
inline std::optional<std::string> map_plane_words(program::block& b, const mat3& R) {
  for (auto& w : b.kept_words) {
    std::string upper;
    for (char c : w) upper.push_back(program::to_upper(c));
    if (upper != "G17" && upper != "G18" && upper != "G19") continue;
    const program::arc_plane p = upper == "G17"   ? program::arc_plane::xy
                                 : upper == "G18" ? program::arc_plane::zx
                                                  : program::arc_plane::yz;
    const auto mapped = principal_plane(R * plane_normal(p));
    if (!mapped) return "plane selection " + w + " cannot be mapped: plane " + std::string(plane_name(p)) +
                        " has no principal image on the target";
    w = mapped->first == program::arc_plane::xy ? "G17" : (mapped->first == program::arc_plane::zx ? "G18" : "G19");
  }
  return std::nullopt;
}

/// Makes `b` a block of dialect `to`: text kin5 did not interpret (`passthrough`) and words it
/// kept without interpreting (`kept_words`) mean something only in the source dialect `from`, so
/// they travel as a comment instead of being written as code.
inline void carry_over(program::block& b, program::dialect from, program::dialect to) {
  if (from == to) return;
  std::string note;
  if (b.passthrough) {
    note = b.text;  // the whole line, its own comment included
    b.passthrough = false;
    b.comment.reset();
  } else if (!b.kept_words.empty()) {
    note = std::string(program::name(from)) + ":";
    for (const auto& w : b.kept_words) note += " " + w;
  }
  b.kept_words.clear();
  if (!note.empty()) b.comment = b.comment ? *b.comment + " | " + note : note;
}

/// `b` as it goes into a program of another dialect (see `carry_over`).
inline program::block carried_over(program::block b, program::dialect from, program::dialect to) {
  carry_over(b, from, to);
  return b;
}

/// The target side for an NC machine To: branch choice over the program (first pass), then feed
/// and output blocks (second pass).
template <machine To>
class nc_target {
 public:
  static constexpr bool plans_with_tool_axis = true;  // `plan` needs it; `write` uses the planned angles
  nc_target(const rigid_transform& target_T_source, feed_policy feed, program::dialect from, program::dialect to,
            bool switch_on)
      : T(target_T_source), policy(feed), source_language(from), language(to), switch_tcp_on(switch_on) {}

  /// First pass: the step of every block, in order.
  void plan(const source_step& s) {
    if (s.what == source_step::kind::motion) planner.add(normalized(T.map_direction(s.axis)));
  }
  void finish_plan() { path = planner.finish(); }

  /// Second pass: block `b` (whose step is `s`) → `emit`; reports to `on_report`.
  template <class Emit, class Report>
  void write(const program::block& b, const source_step& s, translation& out, Emit&& emit, Report&& on_report) {
    const mat3& R = T.rotation;
    const rigid_transform& target_T_source = T;
    if (s.what == source_step::kind::failed) return;
    if (s.what == source_step::kind::passthrough) {
      emit(carried_over(b, source_language, language));
      ++out.passed_through;
      return;
    }
    program::block o = b;
    if (auto error = map_plane_words(o, R)) {
      out.errors.push_back(at(b, *error));
      return;
    }
    carry_over(o, source_language, language);
    if (b.feed_mode == program::feed_unit::inverse_time && !supports_inverse_time(language)) {
      out.errors.push_back(at(b, "inverse-time feed (G93) cannot be written in " + std::string(program::name(language))));
      return;
    }
    if (s.what == source_step::kind::copy) {
      if (b.arc && b.arc->centre_mm) {  // an arc centre on its own (Heidenhain CC)
        const auto mapped = principal_plane(R * plane_normal(b.arc->plane));
        if (!mapped) {
          out.errors.push_back(at(b, "circular move cannot be mapped: plane " + std::string(plane_name(b.arc->plane)) +
                                         " has no principal image on the target"));
          return;
        }
        o.arc->plane = mapped->first;
        o.arc->centre_mm = target_T_source.map_point(*b.arc->centre_mm);
        if (language != program::dialect::heidenhain) {  // G2/G3 carry their own centre: keep a note
          const vec3 c = *o.arc->centre_mm;
          if (!o.comment) o.comment = "circle centre X" + fixed(c.x, 3) + " Y" + fixed(c.y, 3) + " Z" + fixed(c.z, 3);
          o.arc.reset();
        }
      }
      if (policy == feed_policy::inverse_time && b.feed_mode != program::feed_unit::inverse_time) {
        o.feed.reset();
        o.feed_mode.reset();
      }
      if (switch_tcp_on && tcp_switched_on && b.program_end) o.tcp = false;
      emit(std::move(o));
      return;
    }

    // A motion block.
    const std::size_t j = m++;
    block_report report{b.where, matchability::direct, {}, {}, {}};
    if (!path.angles[j]) {
      report.match = matchability::unreachable;
      report.gap = path.gap[j];
      report.why = "tool axis " + fixed(to_degrees(path.gap[j]).value, 3) + "° outside the reach of " +
                   std::string(To::id);
      out.errors.push_back(at(b, std::string(To::id) + " cannot reach this block (" + angles_text(s) + "): " + report.why));
      on_report(std::move(report));
      return;
    }
    if (!s.principal) {
      report.match = matchability::other_branch;
      report.why = "the source pose is on the second solution branch of the source machine (K3); a closed-form "
                   "translation on the principal branch would turn the table 180° off (E6)";
    }
    on_report(block_report(report));
    const rotary_angles<To>& angles = *path.angles[j];
    const vec3 tip = target_T_source.map_point(s.tip_mm);
    std::array<double, 2> target_deg{};
    for (std::size_t i = 0; i < rotary_count<To>; ++i) target_deg[i] = to_degrees(angles[i]).value;

    o.text.clear();
    o.axes = {};
    if (switch_tcp_on && !tcp_switched_on) o.tcp = true, tcp_switched_on = true;
    if (program::is_arc(s.motion)) {
      const auto mapped = principal_plane(R * plane_normal(s.plane));
      if (!mapped) {
        out.errors.push_back(at(b, "circular move cannot be mapped: plane " + std::string(plane_name(s.plane)) +
                                       " maps to a plane that is not XY, ZX or YZ on the target"));
        return;
      }
      if (previous && path.angles[*previous] && rotary_step_cost<To>(*path.angles[*previous], angles) > 1e-9) {
        out.errors.push_back(at(b, "circular move cannot be mapped: the target's rotary axes would move during it"));
        return;
      }
      const auto [plane, flipped] = *mapped;
      const vec3 start = target_T_source.map_point(*s.start_mm);
      for (program::arc_plane axis : {program::arc_plane::yz, program::arc_plane::zx, program::arc_plane::xy}) {
        const double v = component(tip, axis);  // yz → x, zx → y, xy → z
        std::optional<double>& word = axis == program::arc_plane::yz ? o.axes.x_mm
                                      : axis == program::arc_plane::zx ? o.axes.y_mm
                                                                       : o.axes.z_mm;
        if (axis != plane || math::abs(v - component(start, axis)) > 1e-9) word = v;
      }
      o.motion = flipped ? (s.motion == program::motion_kind::arc_cw ? program::motion_kind::arc_ccw : program::motion_kind::arc_cw) : s.motion;
      program::arc_words arc{plane, std::nullopt, s.radius_mm};
      if (s.centre_mm) arc.centre_mm = target_T_source.map_point(*s.centre_mm);
      o.arc = arc;
    } else {
      o.axes.x_mm = tip.x, o.axes.y_mm = tip.y, o.axes.z_mm = tip.z;
      for (std::size_t i = 0; i < rotary_count<To>; ++i) rotary_word(o.axes, To::rotary[i].letter) = target_deg[i];
    }

    // Feed.
    if (s.rapid) {
      o.feed.reset();
    } else if (s.feed_mode == program::feed_unit::inverse_time) {
      // Already inverse time: the block time is kept by construction.
    } else if (policy == feed_policy::block_time && s.feed) {
      double l_s = 0.0, l_d = 0.0;
      if (previous) {
        const source_step& p = previous_step;
        std::array<double, 2> ds{}, dd{};
        for (std::size_t i = 0; i < s.rotary_n && i < p.rotary_n; ++i) ds[i] = s.rotary_deg[i] - p.rotary_deg[i];
        for (std::size_t i = 0; i < rotary_count<To>; ++i)
          dd[i] = target_deg[i] - to_degrees((*path.angles[*previous])[i]).value;
        l_s = block_length(s.tip_mm - p.tip_mm, std::span<const double>(ds.data(), s.rotary_n));
        l_d = block_length(tip - target_T_source.map_point(p.tip_mm), std::span<const double>(dd.data(), rotary_count<To>));
      }
      o.feed = block_time_feed(*s.feed, l_s, l_d);
    } else if (policy == feed_policy::inverse_time && s.feed) {
      if (!supports_inverse_time(language)) {
        if (!inverse_time_error)
          out.errors.push_back(at(b, "inverse-time feed (G93) cannot be written in " + std::string(program::name(language))));
        inverse_time_error = true;
      }
      double length = s.start_mm ? (program::is_arc(s.motion) ? arc_length(s, *s.start_mm, s.tip_mm) : norm(s.tip_mm - *s.start_mm))
                                 : 0.0;
      if (!(length > 0.0) && previous) {  // orientation only: the source's (K16) length in degrees
        const source_step& p = previous_step;
        std::array<double, 2> ds{};
        for (std::size_t i = 0; i < s.rotary_n && i < p.rotary_n; ++i) ds[i] = s.rotary_deg[i] - p.rotary_deg[i];
        length = block_length({}, std::span<const double>(ds.data(), s.rotary_n));
      }
      o.feed = inverse_time_feed(*s.feed, length);
      if (!o.feed)
        out.warnings.push_back(at(b, s.start_mm ? "zero-length move: no inverse-time F written"
                                                : "start point unknown, so is the block time: no inverse-time F written"));
      if (!output_inverse_time) o.feed_mode = program::feed_unit::inverse_time, output_inverse_time = true;
    }
    if (previous && path.branch[*previous] >= 0 && path.branch[j] >= 0 && path.branch[*previous] != path.branch[j] &&
        !path.pole[*previous] && !path.pole[j]) {
      const bool avoidable = (path.branches[*previous] & path.branches[j]) != 0;
      out.warnings.push_back(at(b, std::string(avoidable ? "solution branch switch (least total rotary travel)"
                                                         : "unavoidable solution branch switch") +
                                       " from branch " + std::to_string(path.branch[*previous]) + " to " +
                                       std::to_string(path.branch[j]) + " on " + std::string(To::id)));
    }
    previous = j;
    previous_step = s;
    emit(std::move(o));
  }

 private:
  rigid_transform T;  // target_T_source
  feed_policy policy;
  program::dialect source_language, language;
  bool switch_tcp_on;
  rotary_planner<To> planner;
  rotary_path<To> path;
  bool output_inverse_time = false, tcp_switched_on = false, inverse_time_error = false;
  std::optional<std::size_t> previous;  // motion index of the last written motion
  source_step previous_step;            // its step
  std::size_t m = 0;                    // motion index of the next motion block
};

/// The target side for APT CL data: GOTO/x,y,z,i,j,k per motion block (no planning).
class cl_target {
 public:
  static constexpr bool plans_with_tool_axis = false;  // `plan` is empty; `write` writes the axis
  explicit cl_target(program::dialect from) : source_language(from) {}

  void plan(const source_step&) {}
  void finish_plan() {}

  /// Second pass: block `b` (whose step is `s`) → `emit`; reports to `on_report`.
  template <class Emit, class Report>
  void write(const program::block& b, const source_step& s, translation& out, Emit&& emit, Report&& on_report) {
    if (s.what == source_step::kind::failed) return;
    if (s.what == source_step::kind::passthrough) {
      emit(carried_over(b, source_language, program::dialect::apt));
      ++out.passed_through;
      return;
    }
    program::block o = b;
    carry_over(o, source_language, program::dialect::apt);
    if (b.feed_mode == program::feed_unit::inverse_time) {
      out.errors.push_back(at(b, "inverse-time feed (G93) cannot be written as APT CL data"));
      return;
    }
    if (o.tcp) {  // CL data is tool-tip data: tracking is implied
      if (!o.comment) o.comment = *o.tcp ? "tool-tip tracking on" : "tool-tip tracking off";
      o.tcp.reset();
    }
    if (s.what == source_step::kind::copy) {
      o.arc.reset();
      emit(std::move(o));
      return;
    }
    block_report report{b.where, s.principal ? matchability::direct : matchability::other_branch, {}, {}, {}};
    if (!s.principal)
      report.why = "the source pose is on the second solution branch of the source machine (K3)";
    on_report(block_report(report));
    if (program::is_arc(s.motion)) {
      out.errors.push_back(at(b, "circular move cannot be written as GOTO points; kin5 does not linearise arcs"));
      return;
    }
    o.text.clear();
    o.axes = {};
    o.axes.x_mm = s.tip_mm.x, o.axes.y_mm = s.tip_mm.y, o.axes.z_mm = s.tip_mm.z;
    o.axes.tool_axis = s.axis;
    o.motion = s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
    if (s.rapid) o.feed.reset();
    emit(std::move(o));
  }

 private:
  program::dialect source_language;
};

inline program::diagnostic file_error(const std::string& file, std::string message) {
  return {program::source_location{file, 0, 0}, std::move(message)};
}

}  // namespace translate_detail

/// Which block reports a translation keeps (`translation::per_class` counts them all anyway).
enum class report_detail {
  every_block,      ///< one report per motion block
  exceptions_only,  ///< only blocks that are not `matchability::direct`: constant memory
};

/// A translation, reverse or post run in two passes over the blocks of one program, for
/// programs of any length: call `plan` with every block in file order, then `write` with the
/// same blocks in the same order. Each output block goes to the sink given to `write` as soon
/// as it is made; nothing is stored per block but the branch planner's candidates (tens of
/// bytes per motion block). Make one with `make_translator`, `make_reverse` or `make_post`.
///
/// The first pass finds the source's errors and the blocks the target cannot reach; the second
/// finds what can only be seen while writing (arcs the setup cannot map, feeds the dialect
/// cannot say). Either way, any error in `result()` means the output must not be used.
class block_translator {
 public:
  virtual ~block_translator() = default;
  /// First pass: the next block of the program.
  virtual void plan(const program::block& b) = 0;
  /// Second pass: the next block of the same program (after every `plan`); output to `emit`.
  virtual void write(const program::block& b, const program::block_sink& emit) = 0;
  /// Counts, reports, errors and warnings so far (`output` stays empty: blocks go to `emit`).
  translation& result() { return result_; }

 protected:
  translation result_;
};

/// Whether a `block_translator`'s second pass reads the source text of `b`: not for a block it
/// moves, whose text it replaces; so a `program::block_store` kept for that pass may drop it.
inline bool second_pass_reads_text(const program::block& b) {
  return !b.moves() || b.passthrough || b.machine_coordinates;
}

namespace translate_detail {

/// `block_translator` for one source side and one target side.
template <class Source, class Target>
class two_pass_translator final : public block_translator {
 public:
  /// `refusal`: a reason not to run at all (an error for the whole file); blocks are then only
  /// counted.
  two_pass_translator(Target target, const std::string& file, program::dialect output_language, report_detail detail,
                      std::optional<std::string> refusal = std::nullopt)
      : target_(std::move(target)), detail_(detail), refused_(refusal.has_value()) {
    result_.output.language = output_language;
    result_.output.file = file;
    if (refusal) result_.errors.push_back(file_error(file, std::move(*refusal)));
  }

  void plan(const program::block& b) override {
    ++result_.blocks_read;
    if (refused_) return;
    // The source kinematics (tool axis, branch) run once per block: in the pass that uses them.
    const source_step s = first_.next(b, &result_, Target::plans_with_tool_axis);
    if (Target::plans_with_tool_axis && s.what == source_step::kind::motion) principal_.push_back(s.principal);
    target_.plan(s);
  }

  void write(const program::block& b, const program::block_sink& emit) override {
    if (refused_) return;
    if (!planned_) target_.finish_plan(), planned_ = true;
    source_step s = second_.next(b, nullptr, !Target::plans_with_tool_axis);
    if (Target::plans_with_tool_axis && s.what == source_step::kind::motion) s.principal = principal_[motion_++];
    target_.write(
        b, s, result_,
        [&](program::block&& o) {
          ++result_.blocks_written;
          emit(std::move(o));
        },
        [&](block_report&& r) {
          ++result_.per_class[static_cast<std::size_t>(r.match)];
          if (detail_ == report_detail::every_block || r.match != matchability::direct) {
            r.source_angles = angles_text(s);
            result_.reports.push_back(std::move(r));
          }
        });
  }

 private:
  Target target_;
  report_detail detail_;
  bool refused_;
  bool planned_ = false;
  source_walker<Source> first_, second_;
  std::vector<bool> principal_;  // per motion block when the first pass classified it: on branch 0
  std::size_t motion_ = 0;       // motion blocks written so far
};

/// Why `translate` cannot run on a program in `source_language`, if it cannot.
inline std::optional<std::string> translate_refusal(program::dialect source_language, const translate_options& options) {
  if (source_language == program::dialect::apt) return "APT CL data names no machine axes: use post, not translate";
  if (options.output_dialect == program::dialect::apt) return "translate writes NC; for APT CL data use reverse";
  if (options.feed == feed_policy::inverse_time && !supports_inverse_time(options.output_dialect))
    return "inverse-time feed (G93) cannot be written in " + std::string(program::name(options.output_dialect));
  return std::nullopt;
}

/// Both passes of `t` over a whole program; the output program collects the emitted blocks.
inline translation run(block_translator& t, const program::program& in) {
  for (const program::block& b : in.blocks) t.plan(b);
  std::vector<program::block> output;
  const program::block_sink emit = [&](program::block&& o) { output.push_back(std::move(o)); };
  for (const program::block& b : in.blocks) t.write(b, emit);
  translation out = std::move(t.result());
  out.output.blocks = std::move(output);
  return out;
}

}  // namespace translate_detail

/// The two passes of `translate<From, To>` (see `block_translator`), for a program read in
/// `source_language` from `file`.
template <machine From, machine To>
std::unique_ptr<block_translator> make_translator(program::dialect source_language, const std::string& file,
                                                  const translate_options& options = {},
                                                  report_detail detail = report_detail::every_block) {
  using namespace translate_detail;
  return std::make_unique<two_pass_translator<nc_source<From>, nc_target<To>>>(
      nc_target<To>(options.setup.value_or(default_setup<From, To>()), options.feed, source_language,
                    options.output_dialect, false),
      file, options.output_dialect, detail, translate_refusal(source_language, options));
}

/// The two passes of `reverse<M>` (see `block_translator`).
template <machine M>
std::unique_ptr<block_translator> make_reverse(program::dialect source_language, const std::string& file,
                                               report_detail detail = report_detail::every_block) {
  using namespace translate_detail;
  return std::make_unique<two_pass_translator<nc_source<M>, cl_target>>(
      cl_target(source_language), file, program::dialect::apt, detail,
      source_language == program::dialect::apt ? std::optional<std::string>("the input is already APT CL data")
                                               : std::nullopt);
}

/// The two passes of `post<M>` (see `block_translator`).
template <machine M>
std::unique_ptr<block_translator> make_post(program::dialect source_language, program::dialect out_dialect,
                                            const std::string& file,
                                            report_detail detail = report_detail::every_block) {
  using namespace translate_detail;
  return std::make_unique<two_pass_translator<cl_source, nc_target<M>>>(
      nc_target<M>(rigid_transform::identity(), feed_policy::tcp, source_language, out_dialect, true), file,
      out_dialect, detail,
      out_dialect == program::dialect::apt
          ? std::optional<std::string>("post writes NC: choose siemens, heidenhain or iso")
          : std::nullopt);
}

/// Translates NC program `nc` of machine From into one for machine To (see the file comment).
/// The source must run with tool-tip tracking; `options.output_dialect` must be an NC dialect.
template <machine From, machine To>
translation translate(const program::program& nc, const translate_options& options = {}) {
  return translate_detail::run(*make_translator<From, To>(nc.language, nc.file, options), nc);
}

/// The inverse post: NC program `nc` of machine M → APT CL data, each motion block a
/// GOTO/x,y,z,i,j,k with the tool axis from `tool_axis<M>` (K1)/(G1); F kept (tool-tip feed).
/// Circular moves are errors (CL data here is GOTO points only).
template <machine M>
translation reverse(const program::program& nc) {
  return translate_detail::run(*make_reverse<M>(nc.language, nc.file), nc);
}

/// The post: APT CL data `cl` → NC for machine M in dialect `out_dialect`: `inverse<M>` of every
/// GOTO tool axis and the same whole-program branch choice as `translate`, F kept. Tool-tip
/// tracking is switched on in the first motion block (TRAORI / M128 / G43.4, as the writer
/// spells it) and off again in the program-end block.
template <machine M>
translation post(const program::program& cl, program::dialect out_dialect) {
  return translate_detail::run(*make_post<M>(cl.language, out_dialect, cl.file), cl);
}

namespace translate_detail {
inline std::string catalog_ids() {
  std::string ids;
  machines::for_each_machine([&]<class M>() { ids += (ids.empty() ? "" : ", ") + std::string(M::id); });
  return ids;
}

/// A `block_translator` that only counts blocks: for a machine id not in the catalog.
inline std::unique_ptr<block_translator> unknown_machine(const std::string& file, program::dialect language,
                                                         std::string_view id) {
  return std::make_unique<two_pass_translator<cl_source, cl_target>>(
      cl_target(language), file, language, report_detail::every_block,
      "unknown machine '" + std::string(id) + "'; known: " + catalog_ids());
}
}  // namespace translate_detail

/// `make_translator<From, To>` for catalog ids; for an unknown id, a translator whose result
/// holds that error.
inline std::unique_ptr<block_translator> make_translator(std::string_view from_id, std::string_view to_id,
                                                         program::dialect source_language, const std::string& file,
                                                         const translate_options& options,
                                                         report_detail detail = report_detail::every_block) {
  std::unique_ptr<block_translator> out;
  bool from_known = false;
  machines::for_each_machine([&]<class From>() {
    if (From::id != from_id) return;
    from_known = true;
    machines::for_each_machine([&]<class To>() {
      if (To::id == to_id) out = make_translator<From, To>(source_language, file, options, detail);
    });
  });
  if (out) return out;
  return translate_detail::unknown_machine(file, options.output_dialect, from_known ? to_id : from_id);
}

/// `make_reverse<M>` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_reverse(std::string_view machine_id, program::dialect source_language,
                                                      const std::string& file,
                                                      report_detail detail = report_detail::every_block) {
  std::unique_ptr<block_translator> out;
  machines::for_each_machine([&]<class M>() {
    if (M::id == machine_id) out = make_reverse<M>(source_language, file, detail);
  });
  if (out) return out;
  return translate_detail::unknown_machine(file, program::dialect::apt, machine_id);
}

/// `make_post<M>` for a catalog id; for an unknown id, a translator whose result holds that error.
inline std::unique_ptr<block_translator> make_post(std::string_view machine_id, program::dialect source_language,
                                                   program::dialect out_dialect, const std::string& file,
                                                   report_detail detail = report_detail::every_block) {
  std::unique_ptr<block_translator> out;
  machines::for_each_machine([&]<class M>() {
    if (M::id == machine_id) out = make_post<M>(source_language, out_dialect, file, detail);
  });
  if (out) return out;
  return translate_detail::unknown_machine(file, out_dialect, machine_id);
}

/// `translate<From, To>` for catalog ids; an error for an unknown id.
inline translation translate(std::string_view from_id, std::string_view to_id, const program::program& nc,
                             const translate_options& options) {
  return translate_detail::run(*make_translator(from_id, to_id, nc.language, nc.file, options), nc);
}

/// `reverse<M>` for a catalog id; an error for an unknown id.
inline translation reverse(std::string_view machine_id, const program::program& nc) {
  return translate_detail::run(*make_reverse(machine_id, nc.language, nc.file), nc);
}

/// `post<M>` for a catalog id; an error for an unknown id.
inline translation post(std::string_view machine_id, const program::program& cl, program::dialect out_dialect) {
  return translate_detail::run(*make_post(machine_id, cl.language, out_dialect, cl.file), cl);
}

}  // namespace kin5

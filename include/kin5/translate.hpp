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

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "branch.hpp"
#include "feed.hpp"
#include "inverse.hpp"
#include "machines.hpp"
#include "matchability.hpp"
#include "program/block.hpp"
#include "program/modal.hpp"
#include "program/text.hpp"
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
  bool ok() const { return errors.empty(); }
};

// ---------------------------------------------------------------------------------------------
// Whole-program branch choice.

/// Rotary travel from `from` to `to`, Σ|Δ| in radians; a continuous axis goes the short way
/// round (it is unwrapped next to the previous block, so that is the move it makes).
template <machine M>
constexpr double rotary_step_cost(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  double sum = 0.0;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const double d = to[i].value - from[i].value;
    sum += math::abs(M::rotary[i].travel.continuous ? math::wrap_pi(d) : d);
  }
  return sum;
}

/// Total rotary travel of a path of commanded angles, Σ over steps and axes of |Δ| (radians).
template <machine M>
constexpr double total_rotary_travel(std::span<const rotary_angles<M>> path) {
  double sum = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k)
    for (std::size_t i = 0; i < rotary_count<M>; ++i) sum += math::abs(path[k][i].value - path[k - 1][i].value);
  return sum;
}

/// One within-travel solution offered to the path planner.
template <machine M>
struct rotary_candidate {
  rotary_angles<M> angles{};  ///< continuous axes in (−180°, 180°]
  int branch = 0;             ///< (G3) branch; a pole counts as both
  bool pole = false;
};

/// The within-travel solutions of machine M for each tool axis (target frame), with the gap of
/// those that have none. At a pole (S2) the free angle of p is taken from the neighbouring
/// blocks (the nearest non-pole block before and after), so that staying costs nothing.
template <machine M>
std::vector<std::vector<rotary_candidate<M>>> rotary_candidates(std::span<const vec3> tool_axes,
                                                                std::vector<radians>* gaps = nullptr) {
  const std::size_t n = tool_axes.size();
  std::vector<std::vector<rotary_candidate<M>>> out(n);
  std::vector<bool> at_pole(n, false);
  if (gaps) gaps->assign(n, radians{0.0});
  auto add = [](std::vector<rotary_candidate<M>>& list, const inverse_result<M>& r, bool pole) {
    for (const auto& s : r) {
      if (!s.within_travel) continue;
      bool duplicate = false;
      for (const auto& c : list) {
        bool same = true;
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          same = same && math::abs(c.angles[i].value - s.angles[i].value) <= 1e-12;
        duplicate = duplicate || same;
      }
      if (!duplicate) list.push_back({s.angles, s.branch, pole});
    }
  };
  for (std::size_t k = 0; k < n; ++k) {
    const auto r = inverse<M>(tool_axes[k]);
    if (gaps && !r.reachable()) (*gaps)[k] = r.gap;
    at_pole[k] = r.status == reach_status::pole;
    if (!at_pole[k]) add(out[k], r, false);
  }
  // The nearest reachable non-pole block before and after each block (n: none), in O(n).
  std::vector<std::size_t> before(n, n), after(n, n);
  for (std::size_t k = 1; k < n; ++k) before[k] = (!at_pole[k - 1] && !out[k - 1].empty()) ? k - 1 : before[k - 1];
  for (std::size_t k = n; k-- > 1;) after[k - 1] = (!at_pole[k] && !out[k].empty()) ? k : after[k];
  for (std::size_t k = 0; k < n; ++k) {
    if (!at_pole[k]) continue;
    std::vector<radians> free_angles;
    for (std::size_t j : {before[k], after[k]})
      if (j < n)
        for (const auto& c : out[j]) free_angles.push_back(c.angles[0]);
    if (free_angles.empty()) free_angles.push_back(radians{0.0});
    for (radians p : free_angles) {
      inverse_options options{};
      options.pole = pole_policy::keep(p);
      add(out[k], inverse<M>(tool_axes[k], options), true);
    }
  }
  return out;
}

/// The chosen path: per tool axis the commanded angles (continuous axes unwrapped next to the
/// previous block), or nothing when the block is unreachable.
template <machine M>
struct rotary_path {
  std::vector<std::optional<rotary_angles<M>>> angles;
  std::vector<int> branch;         ///< branch of the chosen solution (−1: unreachable)
  std::vector<bool> pole;          ///< the chosen solution is at a pole
  std::vector<unsigned> branches;  ///< bit b set: some candidate on branch b (a pole sets both)
  std::vector<radians> gap;        ///< angle to the reach, for unreachable blocks
  double travel = 0.0;             ///< total rotary travel, radians
};

/// Chooses one within-travel solution per tool axis so that the total rotary travel Σ|Δ| over
/// the program is least, by dynamic programming over the blocks (exact, not greedy); ties go to
/// fewer blocks off branch 0, then to the solver's order. Unreachable blocks are skipped (the
/// path joins the blocks either side of them). Continuous axes are unwrapped to the 360°
/// multiple nearest the previous block; the first block keeps (−180°, 180°].
template <machine M>
rotary_path<M> plan_rotary_path(std::span<const vec3> tool_axes) {
  const std::size_t n = tool_axes.size();
  rotary_path<M> path;
  const auto candidates = rotary_candidates<M>(tool_axes, &path.gap);
  struct cell {
    double travel = 0.0;
    int off_principal = 0;
    std::size_t previous = 0;
  };
  constexpr double tie = 1e-9;  // radians of total travel that count as equal
  auto better = [](const cell& a, const cell& b) {
    if (a.travel < b.travel - tie) return true;
    if (a.travel > b.travel + tie) return false;
    return a.off_principal < b.off_principal;
  };
  std::vector<std::vector<cell>> table(n);
  std::vector<std::size_t> previous_block(n, n);
  std::size_t last = n;
  for (std::size_t k = 0; k < n; ++k) {
    const auto& here = candidates[k];
    if (here.empty()) continue;
    table[k].resize(here.size());
    for (std::size_t c = 0; c < here.size(); ++c) {
      const int off = here[c].branch != 0 && !here[c].pole ? 1 : 0;
      if (last == n) {
        table[k][c] = {0.0, off, 0};
        continue;
      }
      bool have = false;
      for (std::size_t s = 0; s < candidates[last].size(); ++s) {
        const cell option{table[last][s].travel + rotary_step_cost<M>(candidates[last][s].angles, here[c].angles),
                          table[last][s].off_principal + off, s};
        if (!have || better(option, table[k][c])) table[k][c] = option, have = true;
      }
    }
    previous_block[k] = last;
    last = k;
  }
  path.angles.assign(n, std::nullopt);
  path.branch.assign(n, -1);
  path.pole.assign(n, false);
  path.branches.assign(n, 0u);
  for (std::size_t k = 0; k < n; ++k)
    for (const auto& c : candidates[k]) path.branches[k] |= c.pole ? 3u : (1u << c.branch);
  if (last == n) return path;
  std::vector<std::size_t> choice(n, 0);
  std::size_t best = 0;
  for (std::size_t c = 1; c < table[last].size(); ++c)
    if (better(table[last][c], table[last][best])) best = c;
  for (std::size_t k = last;; k = previous_block[k]) {
    choice[k] = best;
    best = table[k][best].previous;
    if (previous_block[k] == n) break;
  }
  std::optional<rotary_angles<M>> before;
  for (std::size_t k = 0; k < n; ++k) {
    if (candidates[k].empty()) continue;
    const auto& c = candidates[k][choice[k]];
    rotary_angles<M> a = before ? unwrap_continuous<M>(c.angles, *before) : c.angles;
    if (before) path.travel += rotary_travel_between<M>(*before, a)[1];
    path.angles[k] = a;
    path.branch[k] = c.branch;
    path.pole[k] = c.pole;
    before = a;
  }
  return path;
}

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
  std::string angles_text;
  bool principal = true;
  program::motion_kind motion = program::motion_kind::linear;
  bool rapid = false;
  std::optional<double> feed;         ///< F in effect
  program::feed_unit feed_mode = program::feed_unit::per_minute;
  std::optional<vec3> start_mm;       ///< tip before the block, when known
  program::arc_plane plane = program::arc_plane::xy;
  std::optional<vec3> centre_mm;      ///< arc centre, in the plane of the start point
  std::optional<double> radius_mm;
};

/// Source side of an NC program of machine From: angles → tool axis by (G1).
template <machine From>
struct nc_source {
  static constexpr bool needs_tcp = true;
  static constexpr bool has_angles = true;
  static std::optional<std::string> pose(const program::modal_state& m, source_step& s, std::string& warned,
                                         std::vector<std::string>& notes) {
    if (m.tool_axis) {  // a tool-axis vector written in the program (G43.5 IJK, LN TX TY TZ)
      s.axis = *m.tool_axis;
      s.angles_text = "I=" + fixed(s.axis.x, 7) + " J=" + fixed(s.axis.y, 7) + " K=" + fixed(s.axis.z, 7);
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
      s.rotary_deg[i] = v.value_or(0.0);
      angles[i] = to_radians(degrees{s.rotary_deg[i]});
    }
    for (char letter : {'A', 'B', 'C'}) {
      const std::size_t i = rotary_index<From>(static_cast<axis_letter>(letter));
      if (i == rotary_count<From>) continue;
      if (!s.angles_text.empty()) s.angles_text += ' ';
      s.angles_text += std::string(1, letter) + "=" + fixed(s.rotary_deg[i], 3);
    }
    s.axis = tool_axis<From>(angles);
    s.principal = on_principal_branch<From>(angles);
    return std::nullopt;
  }
};

/// Source side of APT CL data: the tool axis is written (GOTO/x,y,z,i,j,k); +Z until the first.
struct cl_source {
  static constexpr bool needs_tcp = false;
  static constexpr bool has_angles = false;
  static std::optional<std::string> pose(const program::modal_state& m, source_step& s, std::string&,
                                         std::vector<std::string>&) {
    s.axis = m.tool_axis.value_or(unit_z);
    if (!(norm(s.axis) > 0.5)) return std::string("tool-axis vector of zero length");
    s.angles_text = "I=" + fixed(s.axis.x, 7) + " J=" + fixed(s.axis.y, 7) + " K=" + fixed(s.axis.z, 7);
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

/// The source side: walks the program with its modal state and turns each block into a step.
template <class Source>
std::vector<source_step> read_source(const program::program& in, translation& out) {
  std::vector<source_step> steps(in.blocks.size());
  program::modal_state m;
  std::string warned;
  for (std::size_t k = 0; k < in.blocks.size(); ++k) {
    const program::block& b = in.blocks[k];
    const program::modal_state before = m;
    m.apply(b);
    source_step& s = steps[k];
    if (b.machine_coordinates) {
      s.what = source_step::kind::passthrough;
      out.warnings.push_back(at(b, "machine-coordinate move passed through unchanged, not through kinematics; "
                                   "the tool position after it is unknown"));
      continue;
    }
    if (b.passthrough) {
      s.what = source_step::kind::passthrough;
      out.warnings.push_back(at(b, "block not understood: passed through unchanged"));
      continue;
    }
    if (!b.moves()) continue;  // copy
    s.what = source_step::kind::failed;
    if (Source::needs_tcp && !m.tcp) {
      out.errors.push_back(at(b, std::string(b.axes.has_rotary() || m.rotary_moved ? rotary_tcp_off_message
                                                                                   : tcp_off_message)));
      continue;
    }
    const auto kind = m.motion_of(b);
    if (!kind) out.warnings.push_back(at(b, "no motion mode in effect; taken as linear (G1)"));
    s.motion = kind.value_or(program::motion_kind::linear);
    s.rapid = s.motion == program::motion_kind::rapid || b.feed_rapid;
    std::string missing;
    for (char letter : {'X', 'Y', 'Z'})
      if (!m.value(letter)) missing += letter;
    if (!missing.empty()) {
      out.errors.push_back(at(b, "the tool tip is not known: no value yet for " + missing +
                                     " (the first motion must give the full position)"));
      continue;
    }
    s.tip_mm = {*m.x_mm, *m.y_mm, *m.z_mm};
    if (before.x_mm && before.y_mm && before.z_mm) s.start_mm = vec3{*before.x_mm, *before.y_mm, *before.z_mm};
    std::vector<std::string> notes;
    if (auto error = Source::pose(m, s, warned, notes)) {
      out.errors.push_back(at(b, *error));
      continue;
    }
    for (auto& note : notes) out.warnings.push_back(at(b, std::move(note)));
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
        out.errors.push_back(at(b, "circular move cannot be mapped: the rotary axes move during it"));
        continue;
      }
      if (!s.start_mm) {
        out.errors.push_back(at(b, "circular move cannot be mapped: its start point is not known"));
        continue;
      }
      if (!s.centre_mm && !s.radius_mm) {
        out.errors.push_back(at(b, "circular move cannot be mapped: no centre or radius"));
        continue;
      }
      if (s.centre_mm) set_component(*s.centre_mm, s.plane, component(*s.start_mm, s.plane));
    }
    s.what = source_step::kind::motion;
  }
  return steps;
}

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

/// A block as it goes into a program of another dialect: text kin5 did not interpret
/// (`passthrough`) and words it kept without interpreting (`kept_words`) mean something only in
/// the source dialect, so they travel as a comment instead of being written as code.
inline program::block carried_over(program::block b, program::dialect from, program::dialect to) {
  if (from == to) return b;
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
  return b;
}

/// The target side for an NC machine To: branch choice over the program, feed, output blocks.
template <machine To>
void write_nc(const program::program& in, const std::vector<source_step>& steps, const rigid_transform& target_T_source,
              feed_policy policy, program::dialect language, bool switch_tcp_on, translation& out) {
  const mat3& R = target_T_source.rotation;
  std::vector<std::size_t> motion_index;
  std::vector<vec3> axes;
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k].what == source_step::kind::motion) {
      motion_index.push_back(k);
      axes.push_back(normalized(target_T_source.map_direction(steps[k].axis)));
    }
  const rotary_path<To> path = plan_rotary_path<To>(axes);

  bool output_inverse_time = false, tcp_switched_on = false, inverse_time_error = false;
  std::optional<std::size_t> previous;  // index into motion_index of the last written motion
  std::size_t m = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const program::block& b = in.blocks[k];
    const source_step& s = steps[k];
    if (s.what == source_step::kind::failed) continue;
    if (s.what == source_step::kind::passthrough) {
      out.output.blocks.push_back(carried_over(b, in.language, language));
      ++out.passed_through;
      continue;
    }
    program::block o = b;
    if (auto error = map_plane_words(o, R)) {
      out.errors.push_back(at(b, *error));
      continue;
    }
    o = carried_over(std::move(o), in.language, language);
    if (b.feed_mode == program::feed_unit::inverse_time && !supports_inverse_time(language)) {
      out.errors.push_back(at(b, "inverse-time feed (G93) cannot be written in " + std::string(program::name(language))));
      continue;
    }
    if (s.what == source_step::kind::copy) {
      if (b.arc && b.arc->centre_mm) {  // an arc centre on its own (Heidenhain CC)
        const auto mapped = principal_plane(R * plane_normal(b.arc->plane));
        if (!mapped) {
          out.errors.push_back(at(b, "circular move cannot be mapped: plane " + std::string(plane_name(b.arc->plane)) +
                                         " has no principal image on the target"));
          continue;
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
      out.output.blocks.push_back(std::move(o));
      continue;
    }

    // A motion block.
    const std::size_t j = m++;
    block_report report{b.where, matchability::direct, {}, s.angles_text, {}};
    if (!path.angles[j]) {
      report.match = matchability::unreachable;
      report.gap = path.gap[j];
      report.why = "tool axis " + fixed(to_degrees(path.gap[j]).value, 3) + "° outside the reach of " +
                   std::string(To::id);
      out.errors.push_back(at(b, std::string(To::id) + " cannot reach this block (" + s.angles_text + "): " + report.why));
      out.reports.push_back(std::move(report));
      continue;
    }
    if (!s.principal) {
      report.match = matchability::other_branch;
      report.why = "the source pose is on the second solution branch of the source machine (K3); a closed-form "
                   "translation on the principal branch would turn the table 180° off (spec E6)";
    }
    out.reports.push_back(report);
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
        continue;
      }
      if (previous && path.angles[*previous] && rotary_step_cost<To>(*path.angles[*previous], angles) > 1e-9) {
        out.errors.push_back(at(b, "circular move cannot be mapped: the target's rotary axes would move during it"));
        continue;
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
        const source_step& p = steps[motion_index[*previous]];
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
        const source_step& p = steps[motion_index[*previous]];
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
    out.output.blocks.push_back(std::move(o));
  }
  out.blocks_written = out.output.blocks.size();
}

/// The target side for APT CL data: GOTO/x,y,z,i,j,k per motion block.
inline void write_cl(const program::program& in, const std::vector<source_step>& steps, translation& out) {
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const program::block& b = in.blocks[k];
    const source_step& s = steps[k];
    if (s.what == source_step::kind::failed) continue;
    if (s.what == source_step::kind::passthrough) {
      out.output.blocks.push_back(carried_over(b, in.language, program::dialect::apt));
      ++out.passed_through;
      continue;
    }
    program::block o = carried_over(b, in.language, program::dialect::apt);
    if (b.feed_mode == program::feed_unit::inverse_time) {
      out.errors.push_back(at(b, "inverse-time feed (G93) cannot be written as APT CL data"));
      continue;
    }
    if (o.tcp) {  // CL data is tool-tip data: tracking is implied
      if (!o.comment) o.comment = *o.tcp ? "tool-tip tracking on" : "tool-tip tracking off";
      o.tcp.reset();
    }
    if (s.what == source_step::kind::copy) {
      o.arc.reset();
      out.output.blocks.push_back(std::move(o));
      continue;
    }
    block_report report{b.where, s.principal ? matchability::direct : matchability::other_branch, {}, s.angles_text, {}};
    if (!s.principal)
      report.why = "the source pose is on the second solution branch of the source machine (K3)";
    out.reports.push_back(report);
    if (program::is_arc(s.motion)) {
      out.errors.push_back(at(b, "circular move cannot be written as GOTO points; kin5 does not linearise arcs"));
      continue;
    }
    o.text.clear();
    o.axes = {};
    o.axes.x_mm = s.tip_mm.x, o.axes.y_mm = s.tip_mm.y, o.axes.z_mm = s.tip_mm.z;
    o.axes.tool_axis = s.axis;
    o.motion = s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
    if (s.rapid) o.feed.reset();
    out.output.blocks.push_back(std::move(o));
  }
  out.blocks_written = out.output.blocks.size();
}

inline translation start(const program::program& in, program::dialect language) {
  translation out;
  out.blocks_read = in.blocks.size();
  out.output.language = language;
  out.output.file = in.file;
  return out;
}

inline program::diagnostic file_error(const program::program& in, std::string message) {
  return {program::source_location{in.file, 0, 0}, std::move(message)};
}

}  // namespace translate_detail

/// Translates NC program `nc` of machine From into one for machine To (see the file comment).
/// The source must run with tool-tip tracking; `options.output_dialect` must be an NC dialect.
template <machine From, machine To>
translation translate(const program::program& nc, const translate_options& options = {}) {
  translation out = translate_detail::start(nc, options.output_dialect);
  if (nc.language == program::dialect::apt) {
    out.errors.push_back(translate_detail::file_error(nc, "APT CL data names no machine axes: use post, not translate"));
    return out;
  }
  if (options.output_dialect == program::dialect::apt) {
    out.errors.push_back(translate_detail::file_error(nc, "translate writes NC; for APT CL data use reverse"));
    return out;
  }
  if (options.feed == feed_policy::inverse_time && !supports_inverse_time(options.output_dialect)) {
    out.errors.push_back(translate_detail::file_error(nc, "inverse-time feed (G93) cannot be written in " +
                                                    std::string(program::name(options.output_dialect))));
    return out;
  }
  const auto steps = translate_detail::read_source<translate_detail::nc_source<From>>(nc, out);
  translate_detail::write_nc<To>(nc, steps, options.setup.value_or(default_setup<From, To>()), options.feed,
                                                options.output_dialect, false, out);
  return out;
}

/// The inverse post: NC program `nc` of machine M → APT CL data, each motion block a
/// GOTO/x,y,z,i,j,k with the tool axis from `tool_axis<M>` (K1)/(G1); F kept (tool-tip feed).
/// Circular moves are errors (CL data here is GOTO points only).
template <machine M>
translation reverse(const program::program& nc) {
  translation out = translate_detail::start(nc, program::dialect::apt);
  if (nc.language == program::dialect::apt) {
    out.errors.push_back(translate_detail::file_error(nc, "the input is already APT CL data"));
    return out;
  }
  const auto steps = translate_detail::read_source<translate_detail::nc_source<M>>(nc, out);
  translate_detail::write_cl(nc, steps, out);
  return out;
}

/// The post: APT CL data `cl` → NC for machine M in dialect `out_dialect`: `inverse<M>` of every
/// GOTO tool axis and the same whole-program branch choice as `translate`, F kept. Tool-tip
/// tracking is switched on in the first motion block (TRAORI / M128 / G43.4, as the writer
/// spells it) and off again in the program-end block.
template <machine M>
translation post(const program::program& cl, program::dialect out_dialect) {
  translation out = translate_detail::start(cl, out_dialect);
  if (out_dialect == program::dialect::apt) {
    out.errors.push_back(translate_detail::file_error(cl, "post writes NC: choose siemens, heidenhain or iso"));
    return out;
  }
  const auto steps = translate_detail::read_source<translate_detail::cl_source>(cl, out);
  translate_detail::write_nc<M>(cl, steps, rigid_transform::identity(), feed_policy::tcp, out_dialect, true, out);
  return out;
}

namespace translate_detail {
inline std::string catalog_ids() {
  std::string ids;
  machines::for_each_machine([&]<class M>() { ids += (ids.empty() ? "" : ", ") + std::string(M::id); });
  return ids;
}
inline translation unknown_machine(const program::program& in, program::dialect language, std::string_view id) {
  translation out = start(in, language);
  out.errors.push_back(file_error(in, "unknown machine '" + std::string(id) + "'; known: " + catalog_ids()));
  return out;
}
}  // namespace translate_detail

/// `translate<From, To>` for catalog ids; an error for an unknown id.
inline translation translate(std::string_view from_id, std::string_view to_id, const program::program& nc,
                             const translate_options& options) {
  std::optional<translation> out;
  bool from_known = false;
  machines::for_each_machine([&]<class From>() {
    if (From::id != from_id) return;
    from_known = true;
    machines::for_each_machine([&]<class To>() {
      if (To::id == to_id) out = translate<From, To>(nc, options);
    });
  });
  if (out) return std::move(*out);
  return translate_detail::unknown_machine(nc, options.output_dialect, from_known ? to_id : from_id);
}

/// `reverse<M>` for a catalog id; an error for an unknown id.
inline translation reverse(std::string_view machine_id, const program::program& nc) {
  std::optional<translation> out;
  machines::for_each_machine([&]<class M>() {
    if (M::id == machine_id) out = reverse<M>(nc);
  });
  if (out) return std::move(*out);
  return translate_detail::unknown_machine(nc, program::dialect::apt, machine_id);
}

/// `post<M>` for a catalog id; an error for an unknown id.
inline translation post(std::string_view machine_id, const program::program& cl, program::dialect out_dialect) {
  std::optional<translation> out;
  machines::for_each_machine([&]<class M>() {
    if (M::id == machine_id) out = post<M>(cl, out_dialect);
  });
  if (out) return std::move(*out);
  return translate_detail::unknown_machine(cl, out_dialect, machine_id);
}

}  // namespace kin5

/// @file branch_plan.hpp
/// Whole-program branch choice: given the tool axis of every motion block (target frame), one
/// within-travel solution of `inverse<M>` per block such that the total rotary travel
///
///     J = Σ_blocks Σ_axes |Δangle|     (radians; a continuous axis the short way round)
///
/// is least, by dynamic programming over the blocks: exact, not greedy (`branch.hpp` picks the
/// nearest solution to one previous block; this may take a larger move now to avoid a branch
/// switch later). What the source says of a block comes first (`basic_block_source`): a sweep
/// of 180° or more is followed where the target can, and the source's own angles are kept where
/// they are the target's too. Ties go to fewer blocks off branch 0, then to the solver's order. Unreachable
/// blocks are skipped and reported with their gap; at a pole (S2), and within the pole zone of
/// one (`pole_zone` unless given), the free angle is the neighbours'. Fed one tool axis at a time (`rotary_planner`), it keeps only the candidates
/// (one or two per block) and a back pointer each; `plan_rotary_path` plans a whole list.
/// Needs only `inverse` and the standard library. `rotary_planner<M>` plans for machine type M,
/// `rotary_planner_values` for a `machine_model` known at run time (the same code).
/// @code
///   kin5::rotary_planner<kin5::machines::dmu_80p> planner;
///   for (const kin5::vec3& u_target : tool_axes) planner.add(u_target);
///   const auto path = planner.finish();  // path.angles[k]: block k's angles, or empty
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "branch.hpp"
#include "forward.hpp"
#include "inverse.hpp"

namespace kin5 {

/// Rotary travel of machine `m` from `from` to `to`, Σ|Δ| in radians; a continuous axis goes the
/// short way round (it is unwrapped next to the previous block, so that is the move it makes).
template <std::size_t N>
constexpr double rotary_step_cost(const machine_model& m, const std::array<radians, N>& from,
                                  const std::array<radians, N>& to) {
  double sum = 0.0;
  for (std::size_t i = 0; i < m.rotary_count && i < N; ++i) {
    const double d = to[i].value - from[i].value;
    sum += math::abs(m.rotary(i).travel.continuous ? math::wrap_pi(d) : d);
  }
  return sum;
}

/// `rotary_step_cost` for machine type M.
template <machine M>
constexpr double rotary_step_cost(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  return rotary_step_cost(M::model, from, to);
}

/// Total rotary travel of a path of commanded angles, Σ over steps and axes of |Δ| (radians).
template <machine M>
constexpr double total_rotary_travel(std::span<const rotary_angles<M>> path) {
  double sum = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k)
    for (std::size_t i = 0; i < rotary_count<M>; ++i) sum += math::abs(path[k][i].value - path[k - 1][i].value);
  return sum;
}

/// Tool axes this close to a pole of the machine (angle, radians) are planned as the pole itself,
/// where the free angle is kept from the neighbours. Otherwise the last digits of an axis
/// grazing the pole decide a half turn of the free axis: a source alternating ±1e-7° about the
/// pole turned C by 180° on every block. 1e-5 rad is about the rounding of an angle written with
/// 3 decimals (±0.0005° = 8.7e-6 rad): the written program cannot tell the axis from the pole,
/// and the tool axis moves by at most 1e-5 rad (0.001 mm at a 100 mm tool). It is fixed, not the
/// run's angle tolerance: a jitter of 1e-4° about the pole in a 7-decimal program is still not
/// worth a half turn of C per block.
inline constexpr radians pole_zone{1e-5};

/// The least angle (radians) within which a target's tool axis counts as following a source's
/// sweep (`basic_block_source::sweep`), when the planner's reach tolerance is smaller: about the
/// rounding of the sines and cosines along the way, 0.0001 mm at a 100 mm tool.
inline constexpr radians sweep_tolerance{1e-6};

/// What the source says of one block beyond its tool axis (`basic_rotary_planner::add`), N
/// angles. Under tool-tip tracking a control turns its rotary axes linearly from one block's
/// angles to the next, so the source's commanded angles say how the tool axis turns on the way,
/// not only where it ends.
template <std::size_t N>
struct basic_block_source {
  /// The source's commanded angles (radians, continuous axes as the source wrote them), given
  /// when they are a solution of the target within its travel (a target whose axes are the
  /// source's): the plan keeps them, and between two such blocks the source's own move.
  std::optional<std::array<radians, N>> angles;
  /// When a source axis turns by 180° or more from the previous block (the least move would
  /// take the other way round, or none for a full turn): the tool axis (target frame, unit) at
  /// s = j/n, j = 1 … n−1, of the source's move. The target's move into the block must pass
  /// within `sweep_tolerance` (or the reach tolerance) of each, its continuous axes turning as
  /// often as needed; where no move can, the block is marked (`basic_rotary_path::sweep_lost`).
  std::span<const vec3> sweep;
};

/// The chosen path: per tool axis the commanded angles (N of them, continuous axes unwrapped
/// next to the previous block), or nothing when the block is unreachable.
template <std::size_t N>
struct basic_rotary_path {
  std::vector<std::optional<std::array<radians, N>>> angles;
  std::vector<int> branch;         ///< branch of the chosen solution (−1: unreachable)
  std::vector<bool> pole;          ///< the chosen solution is at a pole
  std::vector<unsigned> branches;  ///< bit b set: some candidate on branch b (a pole sets both)
  std::vector<radians> gap;        ///< angle to the reach, for unreachable blocks
  /// The block's source sweep (`basic_block_source::sweep`) that no move of the target into it follows.
  std::vector<bool> sweep_lost;
  std::vector<bool> swept;   ///< the move into the block follows its source sweep
  std::vector<bool> source;  ///< the chosen solution is the source's own angles (`basic_block_source::angles`)
  double travel_rad = 0.0;         ///< total rotary travel
};

/// Whole-program branch choice, fed one tool axis at a time: among all within-travel solutions of
/// every block, the sequence that, in this order,
///
///  1. follows every source sweep it can (`basic_block_source::sweep`: fewest blocks whose
///     move takes another path of the tool axis than the source's),
///  2. keeps the source's own angles at most blocks (`basic_block_source::angles`: a target
///     whose axes are the source's runs the source's own moves, branch and sweeps),
///  3. has the least total rotary travel Σ|Δ| over the program,
///  4. has the fewest blocks off branch 0, then the solver's order,
///
/// by dynamic programming over the blocks (exact, not greedy). Unreachable blocks are skipped
/// (the path joins the blocks either side of them). At a pole (S2), or within the pole zone of
/// one, the free angle of p is taken from the nearest non-pole block before and after, so that
/// staying costs nothing; pole blocks wait for the next non-pole block.
///
/// Memory: the candidates of every block (one or two per block away from poles) and one back
/// pointer each; the DP itself keeps only the last reachable block's costs.
///
/// `basic_rotary_planner<N, Capacity>` plans for the machine value it is given (N angles,
/// `inverse` results of `Capacity`); `rotary_planner<M>` for machine type M;
/// `rotary_planner_values` for any machine known at run time.
template <std::size_t N, std::size_t Capacity>
class basic_rotary_planner {
 public:
  using angles_type = std::array<radians, N>;
  using result_type = basic_inverse_result<N, Capacity>;
  using block_source = basic_block_source<N>;

  /// `options`: the reach tolerance and travel slack of every `inverse` it solves (its pole
  /// rule is the planner's own); `pole_zone_rad`: tool axes this close to a pole are planned as
  /// the pole.
  explicit basic_rotary_planner(const machine_model& m, const inverse_options& options = {},
                                radians pole_zone_rad = pole_zone)
      : machine_(m), options_(options), pole_zone_(pole_zone_rad) {}

  /// Adds the tool axis (target frame, unit) of the next block, and what its source says of it.
  void add(const vec3& u_target, const block_source& source = {}) {
    const std::size_t k = count_++;
    if (pending_.empty() && first_.size() != k) throw std::logic_error("rotary_planner: blocks out of order");
    gap_.push_back(radians{0.0});
    const vec3 u = near_pole(u_target).value_or(u_target);
    const result_type& r = solve(scratch_, u, options_);
    if (!r.reachable() && !source.angles) gap_[k] = r.gap;
    if (r.status == reach_status::pole) {
      pending_.push_back({k, u, true, source.angles, {source.sweep.begin(), source.sweep.end()}});
      return;
    }
    if (!pending_.empty()) {  // blocks wait in order behind the pole blocks
      const bool reachable_here =
          source.angles || std::any_of(r.begin(), r.end(), [](const auto& s) { return s.within_travel; });
      if (!reachable_here) {
        pending_.push_back({k, u_target, false, std::nullopt, {source.sweep.begin(), source.sweep.end()}});
        return;
      }
      flush(&r);
    }
    begin_block();
    add_within_travel(r, false);
    add_source(source.angles, false);
    if (candidates_.size() > first_[k]) {
      step(k, source.sweep);
      anchor_ = k;
    }
  }

  /// The chosen path for every axis added (and clears the planner).
  basic_rotary_path<N> finish() {
    flush(nullptr);
    const std::size_t n = count_;
    first_.push_back(static_cast<std::uint32_t>(candidates_.size()));  // first_[n]: the end
    basic_rotary_path<N> path;
    path.gap = std::move(gap_);
    path.angles.assign(n, std::nullopt);
    path.branch.assign(n, -1);
    path.pole.assign(n, false);
    path.branches.assign(n, 0u);
    path.sweep_lost.assign(n, false);
    path.swept.assign(n, false);
    path.source.assign(n, false);
    for (std::size_t k = 0; k < n; ++k)
      for (std::uint32_t c = first_[k]; c < first_[k + 1]; ++c)
        path.branches[k] |= candidates_[c].pole ? 3u : (1u << candidates_[c].branch);
    if (!frontier_.empty()) {
      // Back pointers from the best last candidate name one candidate per reachable block.
      std::size_t best = 0;
      for (std::size_t c = 1; c < frontier_.size(); ++c)
        if (better(frontier_[c], frontier_[best])) best = c;
      std::uint32_t chosen = first_[last_] + static_cast<std::uint32_t>(best);
      std::vector<std::uint32_t> choice(n, none32);
      for (std::size_t k = n; k-- > 0;) {
        if (first_[k] == first_[k + 1]) continue;
        choice[k] = chosen;
        chosen = candidates_[chosen].previous;
      }
      std::optional<angles_type> before;
      const stored* chosen_before = nullptr;
      for (std::size_t k = 0; k < n; ++k) {
        if (choice[k] == none32) continue;
        const stored& c = candidates_[choice[k]];
        // The first block as solved (the source's angles as it wrote them); after another of the
        // source's angles, the source's own move, turns included; else the move chosen.
        angles_type a = c.angles;
        if (before && c.source && chosen_before->source) {
          for (std::size_t i = 0; i < N; ++i)
            if ((*before)[i].value != chosen_before->angles[i].value)
              a[i].value = (*before)[i].value + (c.angles[i].value - chosen_before->angles[i].value);
        } else if (before) {
          a = unwrap_continuous(machine_, c.angles, *before);
          for (std::size_t i = 0; i < N; ++i) a[i].value += 2.0 * pi * c.turns[i];
        }
        if (before) path.travel_rad += rotary_travel_between(*before, a)[1];
        path.angles[k] = a;
        path.branch[k] = c.branch;
        path.pole[k] = c.pole;
        path.sweep_lost[k] = c.sweep_lost;
        path.swept[k] = c.swept;
        path.source[k] = c.source;
        before = a;
        chosen_before = &c;
      }
    }
    *this = basic_rotary_planner{machine_, options_};
    return path;
  }

 private:
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  static constexpr std::uint32_t none32 = static_cast<std::uint32_t>(-1);
  struct stored {
    angles_type angles{};  ///< continuous axes in (−180°, 180°], or as the source wrote them
    std::uint32_t previous = none32;  ///< the best candidate of the previous reachable block
    std::int8_t branch = 0;           ///< (G3) branch; a pole counts as both
    bool pole : 1 = false;
    bool source : 1 = false;      ///< the source's own angles (`block_source::angles`)
    bool sweep_lost : 1 = false;  ///< the move from `previous` does not follow the block's sweep
    bool swept : 1 = false;       ///< the move from `previous` follows the block's sweep
    std::array<std::int8_t, N> turns{};  ///< full turns added to the least move from `previous`
  };
  struct cell {
    double travel_rad = 0.0;
    int off_principal = 0;
    int off_source = 0;   // blocks not on the source's own angles
    int sweeps_lost = 0;  // blocks whose move does not follow the source's sweep
  };
  struct waiting {
    std::size_t block;
    vec3 u_target;  // unit
    bool pole;
    std::optional<angles_type> source;
    std::vector<vec3> sweep;
  };
  /// The move from one candidate into the next: its rotary travel, the full turns added to the
  /// least move of each continuous axis, and whether it follows the block's sweep.
  struct move {
    double travel_rad = 0.0;
    std::array<std::int8_t, N> turns{};
    bool follows = true;
  };
  static constexpr double tie = 1e-9;  // radians of total travel that count as equal
  static bool better(const cell& a, const cell& b) {
    if (a.sweeps_lost != b.sweeps_lost) return a.sweeps_lost < b.sweeps_lost;
    if (a.off_source != b.off_source) return a.off_source < b.off_source;
    if (a.travel_rad < b.travel_rad - tie) return true;
    if (a.travel_rad > b.travel_rad + tie) return false;
    return a.off_principal < b.off_principal;
  }

  machine_model machine_;
  inverse_options options_;
  radians pole_zone_;
  result_type scratch_{}, pole_scratch_{};  // reused: no clearing of `Capacity` solutions per block
  std::size_t count_ = 0;                // blocks added
  std::vector<stored> candidates_;       // every block's candidates, in block order
  std::vector<std::uint32_t> first_;     // per block: its first candidate in candidates_
  std::vector<radians> gap_;             // per block
  std::vector<waiting> pending_;         // blocks from the first pole block not yet resolved
  std::vector<cell> frontier_;           // DP costs of the last reachable block's candidates
  std::vector<cell> next_;               // the step being computed
  std::size_t last_ = none;              // that block
  std::size_t anchor_ = none;            // the last reachable non-pole block

  /// The pole ±p of the machine that `u` lies within the pole zone of, when that pole is within travel.
  std::optional<vec3> near_pole(const vec3& u) const {
    if (N >= 2 && machine_.rotary_count == 2) {
      const vec3 p = machine_.orientation.p;
      for (const vec3& pole : {p, -p}) {
        // More than 60° away (on the far side, or cos² < 1/4) is far outside the pole zone: no
        // atan2 spent on it. A zero `u` passes on to `angle_between`.
        const double cos_scaled = dot(u, pole);
        if (!(cos_scaled >= 0.0 && 4.0 * cos_scaled * cos_scaled >= dot(u, u) * dot(pole, pole))) continue;
        if (angle_between(u, pole).value <= pole_zone_.value && inverse(machine_, pole, options_).reachable()) return pole;
      }
    }
    return std::nullopt;
  }

  /// The solutions of `u` written into `r`, reused from block to block (only its header reset).
  const result_type& solve(result_type& r, const vec3& u, const inverse_options& options) const {
    r.status = reach_status::unreachable;
    r.gap = radians{0.0};
    r.count = 0;
    inverse_into(machine_, u, options, r);
    return r;
  }

  /// Starts the candidate list of the next block (blocks are begun in order, each once).
  void begin_block() {
    if (candidates_.size() >= none32) throw std::length_error("kin5: program too long for the branch planner");
    first_.push_back(static_cast<std::uint32_t>(candidates_.size()));
  }

  /// Appends the within-travel solutions of `r` to the block begun last, without duplicates.
  void add_within_travel(const result_type& r, bool pole) {
    const std::size_t start = first_.back();
    for (const auto& s : r) {
      if (!s.within_travel) continue;
      bool duplicate = false;
      for (std::size_t c = start; c < candidates_.size(); ++c) {
        bool same = true;
        for (std::size_t i = 0; i < N; ++i)
          same = same && math::abs(candidates_[c].angles[i].value - s.angles[i].value) <= 1e-12;
        duplicate = duplicate || same;
      }
      if (!duplicate) {
        stored c{s.angles, none32, static_cast<std::int8_t>(s.branch)};
        c.pole = pole;
        candidates_.push_back(c);
      }
    }
  }

  /// Solutions this close on every axis (radians; continuous axes modulo a turn) are the same:
  /// the source's angles against the solver's, which agree to its rounding. Two solutions of one
  /// tool axis on other branches or shifts lie far apart.
  static constexpr double same_solution = 1e-4;

  /// The source's own angles (`block_source::angles`) as a candidate of the block begun last: the
  /// solution they match, else a candidate of their own (`pole`: on a pole block).
  void add_source(const std::optional<angles_type>& angles, bool pole) {
    if (!angles) return;
    for (std::size_t c = first_.back(); c < candidates_.size(); ++c) {
      bool same = true;
      for (std::size_t i = 0; i < machine_.rotary_count && i < N; ++i) {
        const double d = (*angles)[i].value - candidates_[c].angles[i].value;
        same = same && math::abs(machine_.rotary(i).travel.continuous ? math::wrap_pi(d) : d) <= same_solution;
      }
      if (same) {
        candidates_[c].angles = *angles;
        candidates_[c].source = true;
        return;
      }
    }
    stored c{*angles};
    c.pole = pole;
    c.source = true;
    candidates_.push_back(c);
  }

  /// The move from candidate `from` into candidate `to` of a block whose source sweeps as
  /// `sweep` says (empty: no sweep): between two of the source's own angles, its own move; else
  /// the least move, or with a sweep the least move (continuous axes turning whole turns more)
  /// whose tool axis passes near every sample, or, when none does, the least move, not following.
  move move_between(const stored& from, const stored& to, std::span<const vec3> sweep) const {
    move m;
    angles_type least{};
    for (std::size_t i = 0; i < machine_.rotary_count && i < N; ++i) {
      const double d = to.angles[i].value - from.angles[i].value;
      least[i] = radians{from.source && to.source ? d : machine_.rotary(i).travel.continuous ? math::wrap_pi(d) : d};
      m.travel_rad += math::abs(least[i].value);
    }
    if (sweep.empty() || (from.source && to.source)) return m;
    // Whole turns tried per continuous axis: as many as the samples tell apart (8 per half turn).
    const int most = static_cast<int>(std::min<std::size_t>(sweep.size() / 8 + 1, 127));
    std::array<int, N> range{};
    for (std::size_t i = 0; i < machine_.rotary_count && i < N; ++i)
      range[i] = machine_.rotary(i).travel.continuous ? most : 0;
    const double tolerance = std::max(options_.reach_tolerance.value, sweep_tolerance.value);
    std::optional<move> best;
    std::array<int, N> k{};
    for (std::size_t i = 0; i < N; ++i) k[i] = -range[i];
    for (;;) {
      move option;
      angles_type delta{};
      for (std::size_t i = 0; i < N; ++i) {
        delta[i] = radians{least[i].value + 2.0 * pi * k[i]};
        option.turns[i] = static_cast<std::int8_t>(k[i]);
        option.travel_rad += math::abs(delta[i].value);
      }
      if (!best || option.travel_rad < best->travel_rad - tie) {
        const double n = double(sweep.size() + 1);
        bool follows = true;
        for (std::size_t j = 0; follows && j < sweep.size(); ++j) {
          angles_type at = from.angles;
          for (std::size_t i = 0; i < N; ++i) at[i].value += double(j + 1) / n * delta[i].value;
          follows = angle_between(tool_axis(machine_, at), sweep[j]).value <= tolerance;
        }
        if (follows) best = option;
      }
      std::size_t i = 0;  // the next combination of turns
      while (i < N && k[i] == range[i]) k[i] = -range[i], ++i;
      if (i == N) break;
      ++k[i];
    }
    if (best) return *best;
    m.follows = false;
    return m;
  }

  /// One DP step: the cheapest way to each candidate of block k from the last reachable block,
  /// following the block's source `sweep` where it can: when that block is the one before (after
  /// an unreachable block, the move planned is not the source's, and that block is refused).
  void step(std::size_t k, std::span<const vec3> sweep) {
    if (last_ != none && last_ + 1 != k) sweep = {};
    const std::uint32_t begin = first_[k], end = static_cast<std::uint32_t>(candidates_.size());
    std::vector<cell>& next = next_;  // reused: no allocation per block
    next.assign(end - begin, cell{});
    for (std::uint32_t c = begin; c < end; ++c) {
      const int off = candidates_[c].branch != 0 && !candidates_[c].pole ? 1 : 0;
      const int off_source = candidates_[c].source ? 0 : 1;
      if (last_ == none) {
        next[c - begin] = {0.0, off, off_source, 0};
        continue;
      }
      bool have = false;
      for (std::size_t s = 0; s < frontier_.size(); ++s) {
        const std::uint32_t from = first_[last_] + static_cast<std::uint32_t>(s);
        const move m = move_between(candidates_[from], candidates_[c], sweep);
        const cell option{frontier_[s].travel_rad + m.travel_rad, frontier_[s].off_principal + off,
                          frontier_[s].off_source + off_source, frontier_[s].sweeps_lost + (m.follows ? 0 : 1)};
        if (!have || better(option, next[c - begin])) {
          next[c - begin] = option;
          candidates_[c].previous = from;
          candidates_[c].turns = m.turns;
          candidates_[c].sweep_lost = !m.follows;
          candidates_[c].swept = m.follows && !sweep.empty();
          have = true;
        }
      }
    }
    frontier_.swap(next);
    last_ = k;
  }

  /// Resolves the waiting blocks, given the solutions `after` of the next reachable non-pole
  /// block (none at the end of the program).
  void flush(const result_type* after) {
    if (pending_.empty()) return;
    std::vector<radians> free_angles;
    if (anchor_ != none) {
      const std::size_t end = anchor_ + 1 < first_.size() ? first_[anchor_ + 1] : candidates_.size();
      for (std::size_t c = first_[anchor_]; c < end; ++c) free_angles.push_back(candidates_[c].angles[0]);
    }
    if (after)
      for (const auto& s : *after)
        if (s.within_travel) free_angles.push_back(s.angles[0]);
    if (free_angles.empty()) free_angles.push_back(radians{0.0});
    const std::vector<waiting> waiting_blocks = std::move(pending_);
    pending_.clear();
    for (const waiting& w : waiting_blocks) {
      begin_block();
      if (w.pole) {
        for (radians p : free_angles) {
          inverse_options options = options_;
          options.pole = pole_policy::keep(p);
          add_within_travel(solve(pole_scratch_, w.u_target, options), true);
        }
      }
      add_source(w.source, w.pole);
      if (candidates_.size() > first_[w.block]) step(w.block, w.sweep);
    }
  }
};

/// The path a `rotary_planner<M>` chooses: N = `rotary_count<M>` angles per block.
template <machine M>
using rotary_path = basic_rotary_path<rotary_count<M>>;
/// The path of a machine known at run time: two angles per block (a 4-axis machine leaves
/// `[1]` at zero).
using rotary_path_values = basic_rotary_path<2>;

/// The planner for machine type M (results sized for M).
template <machine M>
class rotary_planner : public basic_rotary_planner<rotary_count<M>, max_solutions<M>()> {
 public:
  explicit rotary_planner(const inverse_options& options = {})
      : basic_rotary_planner<rotary_count<M>, max_solutions<M>()>(M::model, options) {}
};

/// The planner for a machine known at run time.
using rotary_planner_values = basic_rotary_planner<2, max_solutions_any>;

/// `rotary_planner<M>` over a whole list of tool axes (target frame).
template <machine M>
rotary_path<M> plan_rotary_path(std::span<const vec3> tool_axes) {
  rotary_planner<M> planner;
  for (const vec3& u : tool_axes) planner.add(u);
  return planner.finish();
}

/// `rotary_planner_values` of machine `m` over a whole list of tool axes (target frame).
inline rotary_path_values plan_rotary_path(const machine_model& m, std::span<const vec3> tool_axes) {
  rotary_planner_values planner(m);
  for (const vec3& u : tool_axes) planner.add(u);
  return planner.finish();
}

}  // namespace kin5

// The branch planner fed one tool axis at a time chooses exactly what a plain whole-list
// reference chooses: every block's candidates first, then the dynamic programme over them
// (poles, unreachable blocks and all).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kinematics.hpp>
#include <kin5/kinematics/branch_plan.hpp>

#include "angle_generators.hpp"

namespace {

using namespace kin5;

// ---- the reference: every block's candidates first, then the dynamic programme over them ----

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
std::vector<std::vector<rotary_candidate<M>>> reference_candidates(std::span<const vec3> tool_axes,
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

/// Chooses one within-travel solution per tool axis so that the total rotary travel Σ|Δ| over
/// the program is least, by dynamic programming over the blocks (exact, not greedy); ties go to
/// fewer blocks off branch 0, then to the solver's order. Unreachable blocks are skipped (the
/// path joins the blocks either side of them). Continuous axes are unwrapped to the 360°
/// multiple nearest the previous block; the first block keeps (−180°, 180°].
template <machine M>
rotary_path<M> reference_plan(std::span<const vec3> tool_axes) {
  const std::size_t n = tool_axes.size();
  rotary_path<M> path;
  const auto candidates = reference_candidates<M>(tool_axes, &path.gap);
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
    if (before) path.travel_rad += rotary_travel_between<M>(*before, a)[1];
    path.angles[k] = a;
    path.branch[k] = c.branch;
    path.pole[k] = c.pole;
    before = a;
  }
  return path;
}

// ---- generators ----------------------------------------------------------------------------

/// A tool axis for M of one of five kinds: in travel, anywhere on the sphere (often out of
/// reach), the zero pose's, or along ± the fixed axis (a pole (S2) where M can reach it).
template <machine M>
rc::Gen<vec3> mixed_axis() {
  return rc::gen::exec([]() -> vec3 {
    switch (*rc::gen::inRange(0, 5)) {
      case 0: return tool_axis<M>(*test::angles_within<M>(0.5));
      case 1: {
        const vec3 v{*test::uniform(-1, 1), *test::uniform(-1, 1), *test::uniform(-1, 1)};
        RC_PRE(norm(v) > 0.1);
        return normalized(v);
      }
      case 2: return tool_axis<M>(rotary_angles<M>{});
      case 3: return M::rotary[0].direction;
      default: return -1.0 * M::rotary[0].direction;
    }
  });
}

template <machine M>
void require_same_path(const rotary_path<M>& a, const rotary_path<M>& b) {
  RC_ASSERT(a.angles.size() == b.angles.size());
  for (std::size_t k = 0; k < a.angles.size(); ++k) {
    RC_ASSERT(a.angles[k].has_value() == b.angles[k].has_value());
    if (a.angles[k])
      for (std::size_t i = 0; i < rotary_count<M>; ++i) RC_ASSERT((*a.angles[k])[i].value == (*b.angles[k])[i].value);
    RC_ASSERT(a.branch[k] == b.branch[k]);
    RC_ASSERT(a.pole[k] == b.pole[k]);
    RC_ASSERT(a.branches[k] == b.branches[k]);
    RC_ASSERT(a.gap[k].value == b.gap[k].value);
  }
  RC_ASSERT(a.travel_rad == b.travel_rad);
}

}  // namespace

TEST_CASE("the streaming branch planner chooses exactly what the whole-list reference chooses") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string(M::id) + ": reachable, unreachable and pole blocks in any order", [] {
      const auto n = *rc::gen::inRange<std::size_t>(0, 25);
      std::vector<vec3> axes;
      for (std::size_t k = 0; k < n; ++k) axes.push_back(*mixed_axis<M>());
      std::size_t poles = 0;
      for (const vec3& u : axes) poles += inverse<M>(u).status == reach_status::pole ? 1 : 0;
      RC_CLASSIFY(poles > 0, "with pole blocks");
      const auto streamed = plan_rotary_path<M>(std::span<const vec3>(axes));
      const auto reference = reference_plan<M>(std::span<const vec3>(axes));
      require_same_path<M>(streamed, reference);
    });
  });
}

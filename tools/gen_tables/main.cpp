// kin5-gen-tables: matchability and reach tables for catalog machines, each value computed twice —
// by the closed form ((G5), docs/matchability.md) and numerically with Ipopt (kin5::reach) — side by side.
//
//   kin5-gen-tables reach                      reach cone of every machine about its fixed axis
//   kin5-gen-tables match --from A --to B      source carried-axis sweep → target reachability
//   --check DEG                                 exit 4 if the two ways disagree by more than DEG
#include <cmath>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include <kin5/kin5.hpp>
#include <kin5/reach.hpp>

namespace {

using namespace kin5;

double deg(radians r) { return to_degrees(r).value; }

// Largest disagreement between closed form and Ipopt seen in this run, degrees.
double worst_disagreement_deg = 0.0;
void record(double closed_deg, double numeric_deg) {
  worst_disagreement_deg = std::max(worst_disagreement_deg, std::abs(closed_deg - numeric_deg));
}

template <machine M>
std::string travel_text(const rotary_axis& a) {
  if (a.travel.continuous) return std::string(1, to_char(a.letter)) + " endless";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%c [%g, %g]", to_char(a.letter), a.travel.lower.value, a.travel.upper.value);
  return buf;
}

/// Closed-form range of ∠(p, u): (G5) narrowed to the carried axis' travel.
template <machine M>
std::array<double, 2> closed_form_cone() {
  if constexpr (rotary_count<M> == 1) {
    const double a = deg(angle_between(M::rotary[0].direction, M::tool_reference));
    return {a, a};
  } else {
    const auto image = kin5::detail::latitude_image(geometry<M>(), M::rotary[1]);
    return {image[0] * 180.0 / pi, image[1] * 180.0 / pi};
  }
}

void print_reach() {
  std::printf("| machine | travel | angle to fixed axis, closed form (deg) | Ipopt (deg) | max difference (deg) |\n");
  std::printf("|---|---|---|---|---|\n");
  machines::for_each_machine([]<class M>() {
    const auto closed = closed_form_cone<M>();
    const auto numeric = reach::angle_range_to<M>(M::rotary[0].direction);
    std::string travel;
    for (const auto& a : M::rotary) travel += (travel.empty() ? "" : ", ") + travel_text<M>(a);
    record(closed[0], deg(numeric.smallest));
    record(closed[1], deg(numeric.largest));
    const double diff = std::max(std::abs(closed[0] - deg(numeric.smallest)), std::abs(closed[1] - deg(numeric.largest)));
    std::printf("| `%s` | %s | [%.6f, %.6f] | [%.6f, %.6f] | %.1e |\n", std::string(M::id).c_str(), travel.c_str(),
                closed[0], closed[1], deg(numeric.smallest), deg(numeric.largest), diff);
  });
}

/// Region of a source pose on the target (docs/matchability.md, generalised): direct when the source angles
/// are on the source's principal branch, other branch when on its second one, or unreachable.
template <machine From>
const char* source_branch(const rotary_angles<From>& angles) {
  const auto result = inverse<From>(tool_axis<From>(angles));
  for (const auto& s : result) {
    bool same = true;
    for (std::size_t i = 0; i < rotary_count<From>; ++i)
      same = same && std::abs(math::wrap_pi(s.angles[i].value - angles[i].value)) < 1e-9;
    if (same) return s.branch == 0 ? "direct" : "other branch";
  }
  return "pole";
}

template <machine From, machine To>
void print_match(double step_deg, double fixed_axis_deg, const rigid_transform& target_T_source) {
  static_assert(rotary_count<From> == 2, "the sweep runs over the source's carried axis");
  const auto& swept = From::rotary[1];
  const double lo = swept.travel.continuous ? -180.0 : swept.travel.lower.value;
  const double hi = swept.travel.continuous ? 180.0 : swept.travel.upper.value;
  std::printf("Source `%s`, %c = %g deg fixed, %c swept; target `%s`.\n\n", std::string(From::id).c_str(),
              to_char(From::rotary[0].letter), fixed_axis_deg, to_char(swept.letter), std::string(To::id).c_str());
  std::printf("| %c (deg) | region | gap, closed form (deg) | gap, Ipopt (deg) |\n|---|---|---|---|\n", to_char(swept.letter));
  const int n = static_cast<int>(std::floor((hi - lo) / step_deg + 1e-9));
  for (int k = 0; k <= n; ++k) {
    const double q_deg = lo + k * step_deg;
    const rotary_angles<From> angles{to_radians(degrees{fixed_axis_deg}), to_radians(degrees{q_deg})};
    const vec3 u = target_T_source.map_direction(tool_axis<From>(angles));
    const auto closed = inverse<To>(u);
    const auto numeric = reach::nearest_reachable_axis<To>(u);
    const char* region = closed.reachable() ? source_branch<From>(angles) : "unreachable";
    record(deg(closed.gap), deg(numeric.gap));
    std::printf("| %.3f | %s | %.6f | %.6f |\n", q_deg, region, deg(closed.gap), deg(numeric.gap));
  }
}

// (K10): the SAJO 12000P → DMU 80P frame map; identity for any other pair.
template <machine From, machine To>
rigid_transform default_map() {
  if constexpr ((std::is_same_v<From, machines::sajo_12000p> && std::is_same_v<To, machines::dmu_80p>) ||
                (std::is_same_v<From, machines::dmu_80p> && std::is_same_v<To, machines::sajo_12000p>))
    return {mat3{{vec3{-1, 0, 0}, vec3{0, 0, 1}, vec3{0, 1, 0}}}, {}};
  else
    return {};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kin5-gen-tables: reach and matchability tables, closed form beside Ipopt"};
  app.require_subcommand(1);
  auto* reach_cmd = app.add_subcommand("reach", "reach cone of every catalog machine about its fixed axis");
  auto* match_cmd = app.add_subcommand("match", "sweep the source's carried axis and classify each pose on the target");
  std::string from = "sajo-12000p", to = "dmu-80p";
  double step = 5.0, fixed = 0.0;
  match_cmd->add_option("--from", from, "source machine id")->capture_default_str();
  match_cmd->add_option("--to", to, "target machine id")->capture_default_str();
  match_cmd->add_option("--step", step, "sweep step, degrees")->capture_default_str()->check(CLI::PositiveNumber);
  match_cmd->add_option("--fixed", fixed, "value of the source's fixed axis, degrees")->capture_default_str();
  double tolerance = -1.0;
  app.add_option("--check", tolerance,
                 "exit 4 if closed form and Ipopt differ by more than this many degrees anywhere");
  CLI11_PARSE(app, argc, argv);

  auto verdict = [&] {
    if (tolerance >= 0 && worst_disagreement_deg > tolerance) {
      std::fprintf(stderr, "kin5-gen-tables: closed form and Ipopt differ by %.3g deg (> %.3g)\n",
                   worst_disagreement_deg, tolerance);
      return 4;
    }
    return 0;
  };
  if (reach_cmd->parsed()) {
    print_reach();
    return verdict();
  }
  bool found = false;
  machines::for_each_machine([&]<class From>() {
    if constexpr (rotary_count<From> == 2) {
      machines::for_each_machine([&]<class To>() {
        if (From::id == from && To::id == to) {
          found = true;
          print_match<From, To>(step, fixed, default_map<From, To>());
        }
      });
    }
  });
  if (!found) {
    std::fprintf(stderr, "kin5-gen-tables: no two-rotary source '%s' or target '%s' in the catalog\n", from.c_str(), to.c_str());
    return 1;
  }
  return verdict();
}

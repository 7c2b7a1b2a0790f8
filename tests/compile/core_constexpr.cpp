// Compile-time proof of the core: <kin5/kin5.hpp> with the standard library alone, forward and
// inverse kinematics in constant expressions (Table 1 row 1 and golden values of
// docs/golden.md), the machine concept rejecting a degenerate machine (S1), and the constexpr maths against known constants.
#if __has_include(<Eigen/Core>)
#error "core_constexpr must build without Eigen on the include path"
#endif

#include <kin5/kin5.hpp>

namespace {

using namespace kin5;
using namespace kin5::literals;
using machines::dmu_80p;
using machines::sajo_12000p;

constexpr bool near(double a, double b, double tol) { return math::abs(a - b) <= tol; }
constexpr bool near(const vec3& a, const vec3& b, double tol) {
  return near(a.x, b.x, tol) && near(a.y, b.y, tol) && near(a.z, b.z, tol);
}
constexpr double deg(radians r) { return to_degrees(r).value; }

// --- constexpr maths against known constants --------------------------------------------
static_assert(near(math::sin(pi / 6), 0.5, 2.3e-16));
static_assert(near(math::cos(pi / 3), 0.5, 2.3e-16));
static_assert(math::sin(0.0) == 0.0 && math::cos(0.0) == 1.0);
static_assert(near(math::sqrt(2.0), 1.4142135623730951, 2.3e-16));
static_assert(math::sqrt(4.0) == 2.0);
static_assert(near(math::atan2(1.0, 1.0), 0.78539816339744831, 1.2e-16));
static_assert(math::atan2(0.0, -1.0) == pi && math::atan2(-1.0, 0.0) == -pi / 2);
static_assert(math::asin(1.0) == pi / 2 && math::acos(-1.0) == pi);
static_assert(near(math::acos(0.5), pi / 3, 3e-16));
static_assert(math::wrap_pi(-pi) == pi && math::wrap_pi(3 * pi) == pi);
static_assert(near(math::wrap_pi(7.0), 7.0 - 2 * pi, 1e-15));
static_assert(near(math::sin(1e6), -0.34999350217129294, 1e-9));  // huge argument, reduced

// --- forward kinematics (golden values, docs/golden.md) ----------------------------------
constexpr double h = 0.70710678118654752;
// rotary order is workpiece → tool: dmu-80p lists {C, B}; sajo lists {B, A}.
static_assert(near(tool_axis<dmu_80p>({to_radians(0_deg), to_radians(90_deg)}), vec3{h, 0.5, 0.5}, 1e-15));
static_assert(near(tool_axis<dmu_80p>({to_radians(0_deg), to_radians(180_deg)}), vec3{0, 1, 0}, 1e-15));
static_assert(near(tool_axis<dmu_80p>({to_radians(45_deg), to_radians(60_deg)}),
                   vec3{0.256236007, 0.609789397, 0.75}, 1e-9));
static_assert(near(tool_axis<sajo_12000p>({to_radians(30_deg), to_radians(-45_deg)}),
                   vec3{0.353553391, 0.707106781, 0.612372436}, 1e-9));
static_assert(near(tool_axis<machines::ac_trunnion>({to_radians(121_deg), to_radians(37_deg)}),
                   vec3{0.515856159, -0.309957651, 0.798635510}, 1e-9));

// --- Table 1 row 1 (docs/golden.md): sajo (A, B) = (−77.954°, 3.536°) → T·u_s → dmu-80p -------
constexpr vec3 u_s = tool_axis<sajo_12000p>({to_radians(3.536_deg), to_radians(-77.954_deg)});
constexpr vec3 u_d{-u_s.x, u_s.z, u_s.y};  // (K11): T = [[-1,0,0],[0,0,1],[0,1,0]]
constexpr auto row1 = inverse<dmu_80p>(u_d);
static_assert(row1.status == reach_status::reachable);
constexpr auto row1_angles = *row1.first_within_travel();
static_assert(near(deg(row1_angles[1]), 17.067290, 1e-5), "B_d of Table 1 row 1");
static_assert(near(deg(row1_angles[0]), 87.479443, 1e-5), "C_d of Table 1 row 1");
static_assert(near(tool_axis<dmu_80p>(row1_angles), u_d, 1e-14));

// The flip region (docs/golden.md): sajo (−100°, 20°) needs C_d = 284.980852° ≡ −75.019148°.
constexpr vec3 flip_s = tool_axis<sajo_12000p>({to_radians(20_deg), to_radians(-100_deg)});
constexpr auto flip = inverse<dmu_80p>(vec3{-flip_s.x, flip_s.z, flip_s.y});
static_assert(near(deg((*flip.first_within_travel())[1]), 14.160202, 1e-5));
static_assert(near(deg((*flip.first_within_travel())[0]), 284.980852 - 360.0, 1e-5));

// Unreachable (P7, P14): sajo A = +20° maps below the dmu-80p horizon, gap 20°.
constexpr vec3 up_s = tool_axis<sajo_12000p>({to_radians(10_deg), to_radians(20_deg)});
constexpr auto up = inverse<dmu_80p>(vec3{-up_s.x, up_s.z, up_s.y});
static_assert(up.status == reach_status::unreachable && near(deg(up.gap), 20.0, 1e-9));

// Liu 2010 golden value (docs/golden.md): u = (−1, 1, 1)/√3 → (B, C) = (81.100571°, 166.173952°).
constexpr auto s003 = inverse<machines::dmu_50v>(normalized(vec3{-1, 1, 1}));
static_assert(near(deg((*s003.first_within_travel())[1]), 81.100571, 1e-5));
static_assert(near(deg((*s003.first_within_travel())[0]), 166.173952, 1e-5));

// Branch choice in a constant expression.
static_assert(nearest_within_travel<dmu_80p>(row1, {to_radians(80_deg), to_radians(10_deg)}).has_value());

// --- the machine concept ------------------------------------------------------------------
static_assert(machine<dmu_80p> && machine<sajo_12000p> && machine<machines::a_rotary_4axis>);

/// S1: the carried axis is parallel to the fixed one, so it cannot change the tool direction.
inline constexpr machine_model q_parallel_p_model = machine_model::from(
    {.id = "q-parallel-p",
     .structure = "degenerate: two tables about +Z",
     .linear = cartesian_axes({-100, 100}, {-100, 100}, {-100, 100}),
     .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless()},
                rotary_axis{axis_letter::A, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless()}},
     .tool = {unit_x, 0.0}});
struct q_parallel_p : machine_type<q_parallel_p_model> {};
static_assert(machine_description<q_parallel_p> && !machine<q_parallel_p>);

/// S1: the carried axis is parallel to the tool.
inline constexpr machine_model q_parallel_t_model = machine_model::from(
    {.id = "q-parallel-t",
     .structure = "degenerate: head about the tool axis",
     .linear = cartesian_axes({-100, 100}, {-100, 100}, {-100, 100}),
     .rotary = {rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless()},
                rotary_axis{axis_letter::C, mount::head, unit_z, angle_sense::tool_relative, rotary_travel::endless()}}});
struct q_parallel_t : machine_type<q_parallel_t_model> {};
static_assert(!machine<q_parallel_t>);

/// Not a unit direction.
inline constexpr machine_model long_axis_model = machine_model::from(
    {.id = "long-axis",
     .structure = "invalid: direction of length 2",
     .linear = cartesian_axes({-100, 100}, {-100, 100}, {-100, 100}),
     .rotary = {rotary_axis{axis_letter::C, mount::table, vec3{0, 0, 2}, angle_sense::tool_relative, rotary_travel::endless()},
                rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative, rotary_travel::endless()}}});
struct long_axis : machine_type<long_axis_model> {};
static_assert(!machine<long_axis>);

// --- the machine value: each rule, and the whole chain at compile time (G6), (G7) ----------
constexpr machine_geometry valid = machines::ac_trunnion::model.geometry;
constexpr bool breaks(machine_rules::rule r, machine_geometry g) { return !machine_rules::holds(r, g); }
static_assert(machine_rules::check(valid).ok());
static_assert([] { auto g = valid; g.rotary[0].letter = axis_letter::none; return breaks(machine_rules::rule::rotary_count, g); }());
static_assert([] { auto g = valid; g.rotary[1].letter = axis_letter::C; return breaks(machine_rules::rule::rotary_letters, g); }());
static_assert([] { auto g = valid; g.linear[1].letter = axis_letter::Z; return breaks(machine_rules::rule::linear_letters, g); }());
static_assert([] { auto g = valid; g.linear[2].direction = unit_x; return breaks(machine_rules::rule::linear_independent, g); }());
static_assert([] { auto g = valid; g.linear[0].travel = {5, -5}; return breaks(machine_rules::rule::travel_order, g); }());
static_assert([] { auto g = valid; g.rotary[1].travel = rotary_travel::between({-600.0}, {600.0}); return breaks(machine_rules::rule::travel_order, g); }());
static_assert([] { auto g = valid; g.tool.pivot_length_mm = -1; return breaks(machine_rules::rule::finite, g); }());
static_assert([] { auto g = valid; g.tool.reference = unit_x; return breaks(machine_rules::rule::moves_the_tool, g); }());

// ac-trunnion: both table axes through (0, 0, −200). A = 90° tilts the part so that the tip at
// the reference point lies at (0, 200, −200) in the part, and the tool along +Y (K18).
constexpr tool_pose tilted = forward<machines::ac_trunnion>({{0, 0, 0}, {radians{0}, to_radians(90_deg)}});
static_assert(near(tilted.tip_mm, vec3{0, 200, -200}, 1e-9) && near(tilted.axis, vec3{0, 1, 0}, 1e-15));
// (G7): the pose inverse lists those axis values again, within travel.
constexpr auto back = inverse<machines::ac_trunnion>(tilted, run_inputs{});
static_assert(back.reachable() && near(back.first_within_travel()->xyz_mm, vec3{0, 0, 0}, 1e-9));
// The value API in a constant expression: the same model, read as a value.
static_assert(inverse(machines::ac_trunnion::model, tilted, run_inputs{}).size() == back.size());

}  // namespace

int main() { return 0; }

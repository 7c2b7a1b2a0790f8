// Golden values for LinuxCNC's xyzac-trt and xyzbc-trt simulation machines, computed by
// linuxcnc_trt_golden.py from LinuxCNC's published kinematics equations alone (its output pasted
// below): joint values X Y Z, tilt (A or B), C, tool length → tool tip in the work frame and tool
// axis. kin5's forward must give the tip and axis; its pose inverse must list the joints.
#include <cmath>
#include <string_view>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>

namespace {

using namespace kin5;

struct golden_case {
  std::string_view machine;
  vec3 joints_mm;
  double tilt_deg, c_deg, tool_length_mm;
  vec3 tip_mm, axis;
};

// python3 tests/property/core/linuxcnc_trt_golden.py
constexpr golden_case cases[] = {
    {"xyzac-trt", {12.5, -30, 40}, 30, 45, 0, {2.9689503215712776, -14.708719208092411, 60.98076211353316}, {0.35355339059327368, 0.35355339059327373, 0.86602540378443871}},
    {"xyzac-trt", {-150, 80, -60}, -100, 170, 55, {170.76116408660133, -104.61911290955382, 90.794487389098776}, {-0.1710100716628343, 0.9698463103929541, -0.1736481776669303}},
    {"xyzac-trt", {0, 0, 0}, 50, -90, 25, {19.667307702895016, -1.2042752713098232e-15, 2.8233225233506829}, {-0.76604444311897801, 4.6906693763513654e-17, 0.64278760968653936}},
    {"xyzac-trt", {199, -99, 119}, -45.5, 300, 10, {215.56472194605362, 105.32905689413015, -5.4867862836623686}, {0.61769300822818229, -0.35662522457709084, 0.7009092642998509}},
    {"xyzac-trt", {35.25, 60.5, -100}, 0, 12, 80, {47.058360220341086, 51.849042743069226, -180}, {0, 0, 1}},
    {"xyzbc-trt", {12.5, -30, 40}, 30, 45, 0, {-34.898671381844103, -7.5277354893487463, 48.881397208144122}, {-0.35355339059327373, 0.35355339059327368, 0.86602540378443871}},
    {"xyzbc-trt", {-150, 80, -60}, -100, 170, 55, {108.34133099672553, -62.130629170270552, 130.38982565828007}, {-0.9698463103929541, -0.1710100716628343, -0.1736481776669303}},
    {"xyzbc-trt", {0, 0, 0}, 50, -90, 25, {3.1607927221981998e-17, 0.51619662492056761, -6.1069872344858354}, {-4.6906693763513654e-17, -0.76604444311897801, 0.64278760968653936}},
    {"xyzbc-trt", {199, -99, 119}, -45.5, 300, 10, {196.70760726305238, 142.70757001491137, -84.289099591584261}, {0.35662522457709084, 0.61769300822818229, 0.7009092642998509}},
    {"xyzbc-trt", {-35.25, 60.5, -100}, -7, -135, 80, {-3.7160084342580291, -81.843912089314216, -176.91160753388965}, {-0.086174639140531833, 0.086174639140531847, 0.99254615164132198}},
};

double distance(const vec3& a, const vec3& b) { return std::sqrt(squared_norm(a - b)); }

template <machine M>
void check(const golden_case& g) {
  INFO(g.machine << " joints (" << g.joints_mm.x << ", " << g.joints_mm.y << ", " << g.joints_mm.z << "), tilt "
                 << g.tilt_deg << ", C " << g.c_deg << ", tool " << g.tool_length_mm);
  const run_inputs in{g.tool_length_mm, {}};
  // Chain order is C (inner table), then the tilting table.
  const axis_position<M> q{g.joints_mm, {to_radians(degrees{g.c_deg}), to_radians(degrees{g.tilt_deg})}};
  const tool_pose pose = forward<M>(q, in);
  CHECK(distance(pose.tip_mm, g.tip_mm) < 1e-9);
  CHECK(distance(pose.axis, g.axis) < 1e-12);
  bool listed = false;
  // At a pole (tilt 0) C is free: keep the golden row's C, as a program keeps the previous one.
  inverse_options keep_c{};
  keep_c.pole = pole_policy::keep(q.rotary[0]);
  for (const auto& s : inverse<M>(tool_pose{g.tip_mm, g.axis}, in, keep_c)) {
    const bool same = distance(s.joints.xyz_mm, g.joints_mm) < 1e-8 &&
                      std::abs(std::remainder(s.joints.rotary[0].value - q.rotary[0].value, 2 * pi)) < 1e-9 &&
                      std::abs(s.joints.rotary[1].value - q.rotary[1].value) < 1e-9;
    if (same) CHECK(s.within_travel);
    listed = listed || same;
  }
  CHECK(listed);
}

}  // namespace

TEST_CASE("LinuxCNC xyzac-trt and xyzbc-trt: published kinematics equations", "[core][chain][golden]") {
  for (const golden_case& g : cases) {
    if (g.machine == machines::xyzac_trt::id) check<machines::xyzac_trt>(g);
    else check<machines::xyzbc_trt>(g);
  }
}

// The controller-grade calls of the kinematics core, as a realtime controller makes them:
// compiled by controller_core.cmake with -fno-exceptions -fno-rtti, which then checks that the
// object needs no symbol of the C++ library. Each call is noexcept (asserted here), allocates
// nothing (no allocation function is referenced) and throws nothing.
#include <utility>

#include <kin5/kinematics.hpp>

#include "linuxcnc_machine.hpp"

#ifdef KIN5_CONTROLLER_NEGATIVE
#include <string>
#endif

namespace {
constexpr kin5::axis_values q0{};
constexpr kin5::tool_pose pose0{};
kin5::inverse_values orientation_out;
kin5::pose_values pose_out;
static_assert(noexcept(kin5::forward(std::declval<const kin5::machine_model&>(), q0)));
static_assert(noexcept(kin5::inverse(std::declval<const kin5::machine_model&>(), kin5::unit_z)));
static_assert(noexcept(kin5::inverse(std::declval<const kin5::machine_model&>(), pose0, kin5::run_inputs{})));
static_assert(noexcept(kin5::inverse_into(std::declval<const kin5::machine_model&>(), kin5::unit_z, {}, orientation_out)));
static_assert(noexcept(kin5::inverse_into(std::declval<const kin5::machine_model&>(), pose0, {}, {}, pose_out)));
static_assert(noexcept(kin5::linear_axes_for(std::declval<const kin5::machine_model&>(), q0.rotary, kin5::vec3{}, {})));
static_assert(noexcept(kin5::machine_model::from({})));
static_assert(noexcept(kin5::machines::find_machine("")));
}  // namespace

extern "C" {

// Joints (mm, radians) → tool tip and axis, for a machine named at run time.
int controller_forward(const char* id, const double* joints, double tool_length_mm, double* tip_axis) {
  const kin5::machine_model* m = kin5::machines::find_machine(id);
  if (!m) return -1;
  const kin5::axis_values q{{joints[0], joints[1], joints[2]}, {kin5::radians{joints[3]}, kin5::radians{joints[4]}}};
  const kin5::tool_pose p = kin5::forward(*m, q, {.tool_length_mm = tool_length_mm});
  const double v[6]{p.tip_mm.x, p.tip_mm.y, p.tip_mm.z, p.axis.x, p.axis.y, p.axis.z};
  for (int i = 0; i < 6; ++i) tip_axis[i] = v[i];
  return 0;
}

// Tool tip and axis → every joint solution (the pose inverse), the first within travel written.
int controller_inverse(const char* id, const double* tip_axis, double tool_length_mm, double* joints) {
  const kin5::machine_model* m = kin5::machines::find_machine(id);
  if (!m) return -1;
  const kin5::tool_pose target{{tip_axis[0], tip_axis[1], tip_axis[2]}, {tip_axis[3], tip_axis[4], tip_axis[5]}};
  kin5::pose_values out{};
  kin5::inverse_into(*m, target, {.tool_length_mm = tool_length_mm}, {}, out);
  for (const auto& s : out)
    if (s.within_travel) {
      const double v[5]{s.joints.xyz_mm.x, s.joints.xyz_mm.y, s.joints.xyz_mm.z, s.joints.rotary[0].value,
                        s.joints.rotary[1].value};
      for (int i = 0; i < 5; ++i) joints[i] = v[i];
      return static_cast<int>(out.size());
    }
  return 0;
}

// What kin5kins calls: LinuxCNC's tool-centre world from joints and back, geometry from pins.
int controller_linuxcnc(const char* id, const double* pins, const double* joints, double* world, double* back) {
  const auto* e = kin5::linuxcnc::find_entry(id);
  if (!e) return -1;
  kin5::linuxcnc::pin_values p = kin5::linuxcnc::initial_pins(*e);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] += pins[i];
  const kin5::machine_model m = kin5::linuxcnc::with_pins(*e, p);
  kin5::linuxcnc::joint_values j{};
  for (std::size_t k = 0; k < e->joints.size(); ++k) j[k] = joints[k];
  kin5::linuxcnc::world_values w{};
  if (!kin5::linuxcnc::tcp_forward(*e, m, p, j, w)) return -1;
  for (std::size_t i = 0; i < w.size(); ++i) world[i] = w[i];
  kin5::linuxcnc::joint_values out{};
  if (!kin5::linuxcnc::tcp_inverse(*e, m, p, w, out)) return -1;
  kin5::linuxcnc::identity_forward(*e, out, w);
  kin5::linuxcnc::identity_inverse(*e, w, out);
  for (std::size_t k = 0; k < e->joints.size(); ++k) back[k] = out[k];
  return 0;
}

#ifdef KIN5_CONTROLLER_NEGATIVE
// The check's own negative control: a use of the C++ library that the check must find.
int controller_negative(const char* id) { return static_cast<int>(std::string(id).size()); }
#endif
}

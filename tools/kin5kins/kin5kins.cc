// kin5kins: kin5's kinematics as a LinuxCNC kinematics module (docs/embedding.md).
//
//   loadrt kin5kins machine=xyzac-trt [sparm=identityfirst]
//
// Switchable as LinuxCNC's own table-rotary-tilting modules are: type 0 is kin5's tool-centre
// kinematics of the machine and type 1 identity (the other way round with sparm=identityfirst).
// The geometry pins have the names and meaning of LinuxCNC's module for the same machine
// (linuxcnc_machine.hpp). Built with LinuxCNC's realtime flags and -fno-exceptions -fno-rtti:
// the kinematics calls are kin5's noexcept core and need nothing of the C++ library.

#include "hal.h"
#include "posemath.h"
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
extern "C" {  // these two declare C functions without saying so to C++
#include "emcpos.h"
#include "kinematics.h"
}

#include "linuxcnc_machine.hpp"

namespace {

namespace lc = kin5::linuxcnc;

struct hal_pins {
  hal_float_t* geometry[lc::pin_count];
  hal_bit_t* is_type[3];
};

hal_pins* pins = nullptr;
const lc::machine_entry* entry = nullptr;
const kin5::machine_model* base = nullptr;
int comp_id = -1;
int switch_type = 0;   // LinuxCNC's switchkins_type
int tcp_type = 0;      // the type number of the tool-centre kinematics (0, or 1 with identityfirst)

lc::pin_values read_pins() {
  lc::pin_values v{};
  for (std::size_t i = 0; i < lc::pin_count; ++i) v[i] = pins->geometry[i] ? *pins->geometry[i] : 0.0;
  return v;
}

void set_type_pins() {
  for (int t = 0; t < 3; ++t) *pins->is_type[t] = (t == switch_type);
}

}  // namespace

extern "C" {

char* machine = nullptr;
RTAPI_MP_STRING(machine, "kin5 catalog id of the machine: xyzac-trt or xyzbc-trt");
char* sparm = nullptr;
RTAPI_MP_STRING(sparm, "identityfirst: switchkins type 0 is identity, 1 the machine's kinematics");

int kinematicsSwitchable() { return 1; }

int kinematicsSwitch(int new_type) {
  if (new_type != 0 && new_type != 1) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: kinematics type %d does not exist; kin5kins has types 0 and 1\n",
                    new_type);
    return -1;
  }
  switch_type = new_type;
  set_type_pins();
  return 0;
}

KINEMATICS_TYPE kinematicsType() { return KINEMATICS_BOTH; }

int kinematicsForward(const double* joint, EmcPose* world, const KINEMATICS_FORWARD_FLAGS*,
                      KINEMATICS_INVERSE_FLAGS*) {
  const lc::joint_values j{joint[0], joint[1], joint[2], joint[3], joint[4]};
  lc::world_position w{};
  if (switch_type == tcp_type) {
    const lc::pin_values p = read_pins();
    const kin5::machine_model m = lc::with_pins(*base, *entry, p);
    if (!lc::tcp_forward(m, j, p[static_cast<std::size_t>(lc::pin::tool_offset)], w)) return -1;
  } else {
    lc::identity_forward(*base, j, w);
  }
  world->tran.x = w.xyz_mm.x;
  world->tran.y = w.xyz_mm.y;
  world->tran.z = w.xyz_mm.z;
  world->a = w.abc_deg[0];
  world->b = w.abc_deg[1];
  world->c = w.abc_deg[2];
  world->u = world->v = world->w = 0.0;
  return 0;
}

int kinematicsInverse(const EmcPose* world, double* joint, const KINEMATICS_INVERSE_FLAGS*,
                      KINEMATICS_FORWARD_FLAGS*) {
  const lc::world_position w{{world->tran.x, world->tran.y, world->tran.z}, {world->a, world->b, world->c}};
  lc::joint_values j{};
  if (switch_type == tcp_type) {
    const lc::pin_values p = read_pins();
    const kin5::machine_model m = lc::with_pins(*base, *entry, p);
    if (!lc::tcp_inverse(m, w, p[static_cast<std::size_t>(lc::pin::tool_offset)], j)) return -1;
  } else {
    lc::identity_inverse(*base, w, j);
  }
  for (std::size_t i = 0; i < j.size(); ++i) joint[i] = j[i];
  return 0;
}

EXPORT_SYMBOL(kinematicsSwitchable);
EXPORT_SYMBOL(kinematicsSwitch);
EXPORT_SYMBOL(kinematicsType);
EXPORT_SYMBOL(kinematicsForward);
EXPORT_SYMBOL(kinematicsInverse);
MODULE_LICENSE("GPL");

int rtapi_app_main(void) {
  if (!machine || !(entry = lc::find_entry(machine)) || !(base = kin5::machines::find_machine(entry->id))) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: machine=%s is not a machine kin5kins serves; give machine=xyzac-trt or "
                    "machine=xyzbc-trt\n", machine ? machine : "(not given)");
    return -EINVAL;
  }
  if (sparm && !strstr(sparm, "identityfirst")) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: sparm=%s is not understood; the one sparm is identityfirst\n", sparm);
    return -EINVAL;
  }
  tcp_type = sparm ? 1 : 0;
  comp_id = hal_init("kin5kins");
  if (comp_id < 0) return comp_id;
  pins = static_cast<hal_pins*>(hal_malloc(sizeof(hal_pins)));
  if (!pins) {
    hal_exit(comp_id);
    return -ENOMEM;
  }
  int res = 0;
  for (std::size_t i = 0; i < lc::pin_count; ++i) {
    pins->geometry[i] = nullptr;
    if (entry->reads[i])
      res += hal_pin_float_newf(HAL_IN, &pins->geometry[i], comp_id, "kin5kins.%s", lc::pin_name(static_cast<lc::pin>(i)));
  }
  // Unprefixed, as LinuxCNC's switchable modules name them.
  for (int t = 0; t < 3; ++t) res += hal_pin_bit_newf(HAL_OUT, &pins->is_type[t], comp_id, "kinstype.is-%d", t);
  if (res) {
    hal_exit(comp_id);
    return -EINVAL;
  }
  switch_type = 0;
  set_type_pins();
  rtapi_print("kin5kins: machine %.*s (as %.*s), joints %.*s, switchkins type 0 is %s\n",
              static_cast<int>(entry->id.size()), entry->id.data(), static_cast<int>(entry->linuxcnc_kins.size()),
              entry->linuxcnc_kins.data(), static_cast<int>(entry->joints.size()), entry->joints.data(),
              tcp_type == 0 ? "the machine's kinematics" : "identity");
  hal_ready(comp_id);
  return 0;
}

void rtapi_app_exit(void) { hal_exit(comp_id); }

}  // extern "C"

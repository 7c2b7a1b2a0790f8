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
  hal_float_t* geometry[lc::max_pins];
  hal_bit_t* is_type[3];
};

hal_pins* pins = nullptr;
const lc::machine_entry* entry = nullptr;
int comp_id = -1;
int switch_type = 0;  // LinuxCNC's switchkins_type
int tcp_type = 0;     // the type number of the tool-centre kinematics (0, or 1 when identity is first)

lc::pin_values read_pins() {
  lc::pin_values v{};
  for (std::size_t i = 0; i < lc::max_pins; ++i) v[i] = pins->geometry[i] ? *pins->geometry[i] : 0.0;
  return v;
}

void set_type_pins() {
  for (int t = 0; t < entry->type_pins; ++t) *pins->is_type[t] = (t == switch_type);
}

}  // namespace

extern "C" {

char* machine = nullptr;
RTAPI_MP_STRING(machine, "the machine: xyzac-trt, xyzbc-trt, xyzab-tdr or bridgemill");
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
  lc::joint_values j{};
  for (std::size_t k = 0; k < entry->joints.size(); ++k) j[k] = joint[k];
  lc::world_values w{};
  if (switch_type == tcp_type) {
    const lc::pin_values p = read_pins();
    if (!lc::tcp_forward(*entry, lc::with_pins(*entry, p), p, j, w)) return -1;
  } else {
    lc::identity_forward(*entry, j, w);
  }
  world->tran.x = w[0];
  world->tran.y = w[1];
  world->tran.z = w[2];
  world->a = w[3];
  world->b = w[4];
  world->c = w[5];
  world->u = w[6];
  world->v = w[7];
  world->w = w[8];
  return 0;
}

int kinematicsInverse(const EmcPose* world, double* joint, const KINEMATICS_INVERSE_FLAGS*,
                      KINEMATICS_FORWARD_FLAGS*) {
  const lc::world_values w{world->tran.x, world->tran.y, world->tran.z, world->a, world->b,
                           world->c,      world->u,      world->v,      world->w};
  lc::joint_values j{};
  if (switch_type == tcp_type) {
    const lc::pin_values p = read_pins();
    if (!lc::tcp_inverse(*entry, lc::with_pins(*entry, p), p, w, j)) return -1;
  } else {
    lc::identity_inverse(*entry, w, j);
  }
  for (std::size_t k = 0; k < entry->joints.size(); ++k) joint[k] = j[k];
  return 0;
}

EXPORT_SYMBOL(kinematicsSwitchable);
EXPORT_SYMBOL(kinematicsSwitch);
EXPORT_SYMBOL(kinematicsType);
EXPORT_SYMBOL(kinematicsForward);
EXPORT_SYMBOL(kinematicsInverse);
MODULE_LICENSE("GPL");

int rtapi_app_main(void) {
  if (!machine || !(entry = lc::find_entry(machine))) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: machine=%s is not a machine kin5kins serves; give machine=xyzac-trt, "
                    "xyzbc-trt, xyzab-tdr or bridgemill\n", machine ? machine : "(not given)");
    return -EINVAL;
  }
  if (sparm && !strstr(sparm, "identityfirst")) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: sparm=%s is not understood; the one sparm is identityfirst\n", sparm);
    return -EINVAL;
  }
  tcp_type = (entry->identity_first || sparm) ? 1 : 0;
  comp_id = hal_init("kin5kins");
  if (comp_id < 0) return comp_id;
  pins = static_cast<hal_pins*>(hal_malloc(sizeof(hal_pins)));
  if (!pins) {
    hal_exit(comp_id);
    return -ENOMEM;
  }
  int res = 0;
  for (std::size_t i = 0; i < lc::max_pins; ++i) {
    pins->geometry[i] = nullptr;
    const lc::pin_spec& spec = entry->pins[i];
    if (spec.role == lc::pin_role::none) continue;
    res += hal_pin_float_newf(HAL_IN, &pins->geometry[i], comp_id, "kin5kins.%.*s", static_cast<int>(spec.name.size()),
                              spec.name.data());
    if (pins->geometry[i]) *pins->geometry[i] = spec.initial;
  }
  // Unprefixed, as LinuxCNC's switchable modules name them.
  for (int t = 0; t < entry->type_pins; ++t)
    res += hal_pin_bit_newf(HAL_OUT, &pins->is_type[t], comp_id, "kinstype.is-%d", t);
  if (res) {
    rtapi_print_msg(RTAPI_MSG_ERR, "kin5kins: cannot create its pins; is another kinematics module loaded (its "
                    "kinstype.is-N pins have the same names)?\n");
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

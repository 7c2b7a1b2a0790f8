// kins_probe: calls a LinuxCNC kinematics module's entry points directly, inside a HAL session
// (run it under halrun with loadusr -w), and writes what they return; or compares two such
// outputs. Used by linuxcnc_kins.sh to hold kin5kins to LinuxCNC's own modules.
//
//   kins_probe run MODULE.so PREFIX PINS SEED GEOMETRIES POSES OUT [PARAM=VALUE...] [--offset PIN=MM]
//   kins_probe compare A B TOLERANCE
//
// `run` loads MODULE.so into this process (its HAL and RTAPI calls resolve to the user-space HAL
// library), sets its module parameters, starts it, links its geometry pins PREFIX.<pin> (PINS:
// comma-separated) to pins of its own, and for GEOMETRIES random geometries drawn from SEED
// writes, for each kinematics type (0 and 1), the forward kinematics of POSES random joint
// vectors and the inverse of as many random world positions, as `%.17g` numbers. The same SEED
// gives the same geometries and inputs for every module. `--offset PIN=MM` adds MM to one pin
// (the negative control). `compare` exits 1 and names the first line where A and B differ by
// more than TOLERANCE.

#include <dlfcn.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

extern "C" {
#include "emcmotcfg.h"
#include "hal.h"
}
#include "posemath.h"
extern "C" {
#include "emcpos.h"
#include "kinematics.h"
}

namespace {

// splitmix64: the same numbers on every platform.
struct random_source {
  std::uint64_t state;
  double uniform(double lo, double hi) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  return out;
}

int fail(const std::string& message) {
  std::cerr << "kins_probe: " << message << '\n';
  return 2;
}

template <class T>
T symbol(void* module, const char* name) {
  return reinterpret_cast<T>(dlsym(module, name));
}

int run(int argc, char** argv) {
  if (argc < 9) return fail("run needs MODULE PREFIX PINS SEED GEOMETRIES POSES OUT");
  const std::string path = argv[2], prefix = argv[3];
  const std::vector<std::string> pin_names = split(argv[4], ',');
  const std::uint64_t seed = std::strtoull(argv[5], nullptr, 10);
  const int geometries = std::atoi(argv[6]), poses = std::atoi(argv[7]);
  std::ofstream out(argv[8]);
  std::string offset_pin;
  double offset_mm = 0.0;

  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) return fail(std::string("cannot load ") + path + ": " + dlerror());
  for (int i = 9; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--offset" && i + 1 < argc) {
      const auto kv = split(argv[++i], '=');
      offset_pin = kv.at(0);
      offset_mm = std::strtod(kv.at(1).c_str(), nullptr);
      continue;
    }
    const auto eq = arg.find('=');
    if (eq == std::string::npos) return fail("not PARAM=VALUE: " + arg);
    const std::string name = arg.substr(0, eq);
    auto** address = symbol<char***>(module, ("rtapi_info_address_" + name).c_str());
    auto* type = symbol<const char**>(module, ("rtapi_info_type_" + name).c_str());
    if (!address || !type || std::strcmp(*type, "s") != 0) return fail("no string parameter " + name + " in " + path);
    **address = strdup(arg.substr(eq + 1).c_str());
  }
  auto app_main = symbol<int (*)()>(module, "rtapi_app_main");
  auto app_exit = symbol<void (*)()>(module, "rtapi_app_exit");
  auto forward = symbol<decltype(&kinematicsForward)>(module, "kinematicsForward");
  auto inverse = symbol<decltype(&kinematicsInverse)>(module, "kinematicsInverse");
  auto kins_switch = symbol<decltype(&kinematicsSwitch)>(module, "kinematicsSwitch");
  auto kins_type = symbol<decltype(&kinematicsType)>(module, "kinematicsType");
  if (!app_main || !app_exit || !forward || !inverse || !kins_switch || !kins_type)
    return fail(path + " lacks an entry point");

  const int probe = hal_init("kins-probe");
  if (probe < 0) return fail("hal_init failed (run under halrun)");
  if (app_main() != 0) {
    hal_exit(probe);
    return fail(path + ": rtapi_app_main failed");
  }
  // As motion does first: xyzab_tdr_kins creates its pins only then.
  if (kins_type() != KINEMATICS_BOTH) return fail(path + ": kinematicsType is not KINEMATICS_BOTH");
  auto** values = static_cast<hal_float_t**>(hal_malloc(static_cast<long>(sizeof(hal_float_t*) * pin_names.size())));
  int res = 0;
  for (std::size_t i = 0; i < pin_names.size(); ++i) {
    const std::string own = "kins-probe." + pin_names[i], signal = "kins-probe-" + pin_names[i];
    res += hal_pin_float_newf(HAL_OUT, &values[i], probe, "%s", own.c_str());
    res += hal_signal_new(signal.c_str(), HAL_FLOAT);
    res += hal_link(own.c_str(), signal.c_str());
    res += hal_link((prefix + "." + pin_names[i]).c_str(), signal.c_str());
  }
  hal_ready(probe);
  if (res != 0) {
    app_exit();
    hal_exit(probe);
    return fail("cannot link the pins " + prefix + ".{" + argv[4] + "}");
  }

  random_source rng{seed};
  out.precision(17);
  int status = 0;
  for (int g = 0; g < geometries && status == 0; ++g) {
    for (std::size_t i = 0; i < pin_names.size(); ++i) {
      const std::string& name = pin_names[i];
      *values[i] = name.rfind("tool-offset", 0) == 0 ? rng.uniform(0.0, 250.0)
                   : name == "pivot-length"          ? rng.uniform(50.0, 400.0)
                                                     : rng.uniform(-300.0, 300.0);
      if (pin_names[i] == offset_pin) *values[i] += offset_mm;
    }
    const random_source inputs = rng;
    for (int type = 0; type < 2 && status == 0; ++type) {
      if (kins_switch(type) != 0) status = fail("kinematicsSwitch(" + std::to_string(type) + ") failed");
      random_source r = inputs;
      for (int k = 0; k < poses && status == 0; ++k) {
        double joints[EMCMOT_MAX_JOINTS] = {};
        for (int j = 0; j < 3; ++j) joints[j] = r.uniform(-500.0, 500.0);
        joints[3] = r.uniform(-120.0, 120.0);
        joints[4] = r.uniform(-720.0, 720.0);
        joints[5] = r.uniform(-50.0, 50.0);  // W of XYZBCW; no joint of the 5-joint machines
        EmcPose world{};
        KINEMATICS_FORWARD_FLAGS fflags = 0;
        KINEMATICS_INVERSE_FLAGS iflags = 0;
        if (forward(joints, &world, &fflags, &iflags) != 0) status = fail("kinematicsForward failed");
        out << "g" << g << " t" << type << " fwd " << world.tran.x << ' ' << world.tran.y << ' ' << world.tran.z << ' '
            << world.a << ' ' << world.b << ' ' << world.c << ' ' << world.u << ' ' << world.v << ' ' << world.w
            << '\n';
        EmcPose target{};
        target.tran.x = r.uniform(-500.0, 500.0);
        target.tran.y = r.uniform(-500.0, 500.0);
        target.tran.z = r.uniform(-500.0, 500.0);
        target.a = r.uniform(-120.0, 120.0);
        target.b = r.uniform(-120.0, 120.0);
        target.c = r.uniform(-720.0, 720.0);
        target.w = r.uniform(-50.0, 50.0);  // a coordinate only of the machines with a W joint
        double back[EMCMOT_MAX_JOINTS] = {};
        if (inverse(&target, back, &iflags, &fflags) != 0) status = fail("kinematicsInverse failed");
        out << "g" << g << " t" << type << " inv";
        for (int j = 0; j < 6; ++j) out << ' ' << back[j];
        out << '\n';
      }
    }
  }
  app_exit();
  hal_exit(probe);
  dlclose(module);
  return status;
}

int compare(int argc, char** argv) {
  if (argc < 5) return fail("compare needs A B TOLERANCE");
  std::ifstream a(argv[2]), b(argv[3]);
  const double tolerance = std::strtod(argv[4], nullptr);
  std::string la, lb;
  long line = 0, values = 0;
  while (true) {
    const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    ++line;
    if (!more_a && !more_b) break;
    if (more_a != more_b) {
      std::cout << "line " << line << ": one output ends first\n";
      return 1;
    }
    std::istringstream sa(la), sb(lb);
    std::string g, t, kind, g2, t2, kind2;
    sa >> g >> t >> kind;
    sb >> g2 >> t2 >> kind2;
    if (g != g2 || t != t2 || kind != kind2) {
      std::cout << "line " << line << ": " << la << " | " << lb << '\n';
      return 1;
    }
    for (double x, y; sa >> x;) {
      if (!(sb >> y) || !(std::fabs(x - y) <= tolerance)) {
        std::cout << "line " << line << " differs beyond " << tolerance << ":\n  " << la << "\n  " << lb << '\n';
        return 1;
      }
      ++values;
    }
  }
  if (values == 0) {
    std::cout << "no values compared\n";
    return 1;
  }
  std::cout << values << " values on " << line - 1 << " lines agree within " << tolerance << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "run") return run(argc, argv);
  if (mode == "compare") return compare(argc, argv);
  return fail("usage: kins_probe run ... | compare A B TOLERANCE");
}

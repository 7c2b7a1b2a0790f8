// A consumer of kin5::kin5: prints the dmu-80p tool axis at B = 90°, C = 0 (docs/golden.md).
#include <cstdio>

#include <kin5/kin5.hpp>

int main() {
  using kin5::machines::dmu_80p;
  const kin5::vec3 u = kin5::tool_axis<dmu_80p>({kin5::radians{0.0}, kin5::to_radians(kin5::degrees{90.0})});
  std::printf("dmu-80p tool axis: %.6f %.6f %.6f\n", u.x, u.y, u.z);
  return 0;
}

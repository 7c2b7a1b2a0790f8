// A consumer of kin5::reach: the angles the dmu-80p tool axis can make with +Z, found by Ipopt
// over the travel; (G5) with ∠(p,q) = ∠(q,t) = 45° gives exactly 0° to 90°.
#include <cstdio>

#include <kin5/machines/dmu_80p.hpp>
#include <kin5/reach.hpp>

int main() {
  const auto range = kin5::reach::angle_range_to<kin5::machines::dmu_80p>(kin5::unit_z);
  std::printf("dmu-80p reach about Z: %.3f to %.3f degrees\n", kin5::to_degrees(range.smallest).value + 0.0,
              kin5::to_degrees(range.largest).value + 0.0);
  return range.converged ? 0 : 1;
}

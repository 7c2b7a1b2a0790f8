/// @file eigen.hpp
/// Eigen interop (`kin5::eigen`, target `kin5::eigen`): conversions between kin5's vec3, mat3 and
/// rigid_transform and Eigen's Vector3d, Matrix3d and Isometry3d; and an independent oracle for
/// the tool axis, built as a plain chain of homogeneous transforms of the physical machine.
///
/// The oracle reads only the machine's data (axis side, direction, sense, order) and never calls
/// kin5's rotate, solver or tool_axis. Each rotary axis turns physically by φ: a head axis by its
/// commanded angle; a table axis by its commanded angle when `sense == physical`, by minus it
/// when `sense == tool_relative` (ISO tool-relative, docs/theory.md). The head chain ram → outer head →
/// inner head gives the tool direction in the machine frame; the table chain bed → outer table →
/// inner table gives `machine_T_part`; the tool axis in the workpiece frame is
/// `(machine_T_part)⁻¹ · machine tool direction`. It must agree with (G1) (law P2).
/// @code
///   using kin5::machines::dmu_80p;
///   Eigen::Vector3d u = kin5::eigen::chain_tool_axis<dmu_80p>({kin5::to_radians(kin5::degrees{90}), kin5::radians{0}});
///   // u ≈ (1/√2, 1/2, 1/2)   (docs/golden.md)
/// @endcode
#pragma once

#include <cstddef>

#include <Eigen/Geometry>

#include "kinematics/forward.hpp"
#include "kinematics/machine.hpp"
#include "core/rigid.hpp"
#include "core/vec.hpp"

namespace kin5::eigen {

/// kin5 → Eigen, component by component.
inline Eigen::Vector3d to_eigen(const vec3& v) { return {v.x, v.y, v.z}; }
/// kin5 → Eigen; `mat3` is stored by rows.
inline Eigen::Matrix3d to_eigen(const mat3& m) {
  Eigen::Matrix3d out;
  for (int i = 0; i < 3; ++i) out.row(i) = to_eigen(m.row[static_cast<std::size_t>(i)]).transpose();
  return out;
}
/// kin5 → Eigen: `a_T_b` as an Isometry3d mapping frame-b coordinates to frame a (mm).
inline Eigen::Isometry3d to_eigen(const rigid_transform& a_T_b) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = to_eigen(a_T_b.rotation);
  out.translation() = to_eigen(a_T_b.translation_mm);
  return out;
}

/// Eigen → kin5.
inline vec3 to_kin5(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
/// Eigen → kin5.
inline mat3 to_kin5(const Eigen::Matrix3d& m) {
  return {{vec3{m(0, 0), m(0, 1), m(0, 2)}, vec3{m(1, 0), m(1, 1), m(1, 2)}, vec3{m(2, 0), m(2, 1), m(2, 2)}}};
}
/// Eigen → kin5: the linear part must be a proper rotation (it is copied, not orthonormalised).
inline rigid_transform to_kin5(const Eigen::Isometry3d& a_T_b) {
  return {to_kin5(Eigen::Matrix3d(a_T_b.linear())), to_kin5(Eigen::Vector3d(a_T_b.translation()))};
}

/// φ, the physical right-handed rotation of rotary axis `i` of M about its direction, radians,
/// for the commanded value `commanded` (docs/theory.md: a table turned by φ turns the tool by −φ
/// relative to the part).
template <machine M>
double physical_angle(std::size_t i, radians commanded) {
  const rotary_axis& a = M::rotary[i];
  if (a.side == mount::head) return commanded.value;
  return a.sense == angle_sense::physical ? commanded.value : -commanded.value;
}

/// machine_T_part: the table chain bed → outer table → … → inner table → part. Tables are listed
/// first in `M::rotary` (workpiece → tool order), innermost first, so the product runs backwards.
/// Axes pass through the origin; at the zero pose the part frame is the machine frame.
template <machine M>
Eigen::Isometry3d machine_T_part(const rotary_angles<M>& commanded) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  for (std::size_t k = rotary_count<M>; k-- > 0;) {
    if (M::rotary[k].side != mount::table) continue;
    out = out * Eigen::AngleAxisd(physical_angle<M>(k, commanded[k]), to_eigen(M::rotary[k].direction));
  }
  return out;
}

/// machine_T_spindle: the head chain ram → outer head → … → inner head → spindle. Heads follow
/// the tables in `M::rotary`, outermost (on the ram) first.
template <machine M>
Eigen::Isometry3d machine_T_spindle(const rotary_angles<M>& commanded) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  for (std::size_t k = 0; k < rotary_count<M>; ++k) {
    if (M::rotary[k].side != mount::head) continue;
    out = out * Eigen::AngleAxisd(physical_angle<M>(k, commanded[k]), to_eigen(M::rotary[k].direction));
  }
  return out;
}

/// The unit tool axis in the workpiece frame from the physical chain:
/// `(machine_T_part)⁻¹ · machine_T_spindle · t`. Oracle for `kin5::tool_axis<M>` (law P2).
template <machine M>
Eigen::Vector3d chain_tool_axis(const rotary_angles<M>& commanded) {
  const Eigen::Vector3d machine_tool = machine_T_spindle<M>(commanded).linear() * to_eigen(M::tool_reference);
  return machine_T_part<M>(commanded).linear().transpose() * machine_tool;
}

/// wp_T_spindle through the chain: orientation `(machine_T_part)⁻¹ · machine_T_spindle`, origin
/// at the tool tip. Under tool-tip tracking the programmed XYZ is the tip in the part frame; the
/// controller puts it at `machine_T_part · xyz_mm` in the machine frame, which maps back here.
template <machine M>
Eigen::Isometry3d chain_wp_T_spindle(const axis_position<M>& position) {
  const Eigen::Isometry3d machine_T_part_now = machine_T_part<M>(position.rotary);
  const Eigen::Vector3d machine_tip_mm = machine_T_part_now * to_eigen(position.xyz_mm);
  Eigen::Isometry3d machine_T_tool = machine_T_spindle<M>(position.rotary);
  machine_T_tool.translation() = machine_tip_mm;
  return machine_T_part_now.inverse() * machine_T_tool;
}

}  // namespace kin5::eigen

/// @file eigen.hpp
/// Eigen interop (`kin5::eigen`, target `kin5::eigen`): conversions between kin5's vec3, mat3 and
/// rigid_transform and Eigen's Vector3d, Matrix3d and Isometry3d; and an independent oracle for
/// the whole machine, built as a plain chain of homogeneous transforms of the physical machine.
///
/// The oracle reads only the machine's data (axis side, point, direction, sense, order, pivot
/// length) and never calls kin5's rotate, solver, tool_axis or forward. Each slide translates its
/// side (the spindle by +x·d, the table by −x·d); each rotary axis turns physically by φ about
/// its line: a head axis by its commanded angle; a table axis by its commanded angle when
/// `sense == physical`, by minus it when `sense == tool_relative` (ISO tool-relative). The head
/// chain bed → slides → outer head → inner head gives machine_T_spindle; the table chain
/// bed → slides → outer table → inner table → work offset gives machine_T_work; the tool tip,
/// −(L + ℓ)t in the spindle frame, and the tool axis t are mapped by
/// `(machine_T_work)⁻¹ · machine_T_spindle`. It must agree with (G1) and (G6).
/// @code
///   Eigen::Vector3d u = kin5::eigen::chain_tool_axis<kin5::machines::dmu_80p>({kin5::radians{0},
///                                                                           kin5::to_radians(kin5::degrees{90})});
///   // u ≈ (1/√2, 1/2, 1/2)   (K5)
/// @endcode
#pragma once

#include <cstddef>

#include <Eigen/Geometry>

#include "core/rigid.hpp"
#include "core/vec.hpp"
#include "kinematics/forward.hpp"
#include "kinematics/machine.hpp"

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

/// φ, the physical right-handed rotation of rotary axis `a`, radians, for the commanded value
/// (a table turned by φ turns the tool by −φ relative to the part).
inline double physical_angle(const rotary_axis& a, radians commanded) {
  if (a.side == mount::head) return commanded.value;
  return a.sense == angle_sense::physical ? commanded.value : -commanded.value;
}

/// The rigid motion of turning by φ about the line of `a`: Translation(c) · R(n, φ) · Translation(−c).
inline Eigen::Isometry3d turn_about_line(const rotary_axis& a, double phi) {
  const Eigen::Vector3d c = to_eigen(a.point_mm);
  return Eigen::Translation3d(c) * Eigen::AngleAxisd(phi, to_eigen(a.direction)) * Eigen::Translation3d(-c);
}

/// Σ x·d over the linear axes on `side`, mm.
inline Eigen::Vector3d slide_sum(const machine_model& m, const vec3& xyz_mm, mount side) {
  const double x[3] = {xyz_mm.x, xyz_mm.y, xyz_mm.z};
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 3; ++i)
    if (m.linear(i).side == side) out += x[i] * to_eigen(m.linear(i).direction);
  return out;
}

/// machine_T_work: table slides (−x·d), then the tables from the outermost (last table in chain
/// order) to the innermost (first), then the work offset.
template <std::size_t N>
Eigen::Isometry3d machine_T_work(const machine_model& m, const basic_axis_position<N>& q,
                                 const rigid_transform& work_offset = {}) {
  Eigen::Isometry3d out(Eigen::Translation3d(-slide_sum(m, q.xyz_mm, mount::table)));
  for (std::size_t k = m.rotary_count; k-- > 0;)
    if (m.rotary(k).side == mount::table) out = out * turn_about_line(m.rotary(k), physical_angle(m.rotary(k), q.rotary[k]));
  return out * to_eigen(work_offset);
}

/// machine_T_spindle: head slides (+x·d), then the heads from the outermost (first head in chain
/// order) to the innermost.
template <std::size_t N>
Eigen::Isometry3d machine_T_spindle(const machine_model& m, const basic_axis_position<N>& q) {
  Eigen::Isometry3d out(Eigen::Translation3d(slide_sum(m, q.xyz_mm, mount::head)));
  for (std::size_t k = 0; k < m.rotary_count; ++k)
    if (m.rotary(k).side == mount::head) out = out * turn_about_line(m.rotary(k), physical_angle(m.rotary(k), q.rotary[k]));
  return out;
}

/// work_T_tool through the chain: orientation `(machine_T_work)⁻¹ · machine_T_spindle`, origin at
/// the tool tip. Oracle for `kin5::forward` (G6): `translation()` is the tip, `linear() · t` the
/// tool axis.
template <std::size_t N>
Eigen::Isometry3d chain_work_T_tool(const machine_model& m, const basic_axis_position<N>& q, const run_inputs& in = {}) {
  const Eigen::Vector3d t = to_eigen(m.tool_reference());
  Eigen::Isometry3d spindle_T_tool(Eigen::Translation3d(-(m.geometry.tool.pivot_length_mm + in.tool_length_mm) * t));
  return machine_T_work(m, q, in.work_offset).inverse() * machine_T_spindle(m, q) * spindle_T_tool;
}

/// The unit tool axis in the workpiece frame (work offset identity) from the physical chain.
/// Oracle for `kin5::tool_axis` (G1).
template <std::size_t N>
Eigen::Vector3d chain_tool_axis(const machine_model& m, const std::array<radians, N>& commanded) {
  basic_axis_position<N> q{};
  q.rotary = commanded;
  return chain_work_T_tool(m, q).linear() * to_eigen(m.tool_reference());
}

/// `chain_tool_axis` for machine type M.
template <machine M>
Eigen::Vector3d chain_tool_axis(const rotary_angles<M>& commanded) {
  return chain_tool_axis(M::model, commanded);
}

/// `chain_work_T_tool` for machine type M.
template <machine M>
Eigen::Isometry3d chain_work_T_tool(const axis_position<M>& q, const run_inputs& in = {}) {
  return chain_work_T_tool(M::model, q, in);
}

}  // namespace kin5::eigen

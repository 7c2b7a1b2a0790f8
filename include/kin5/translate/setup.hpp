/// @file setup.hpp
/// The setup transform `target_T_source`: the fixed rigid map from the source machine's
/// workpiece frame to the target machine's, applied to every tool tip (rotation + translation,
/// millimetres) and tool axis (rotation only) before the target's inverse kinematics.
///
/// For SAJO 12000P ↔ DMU 80P it is the paper's correspondence (K10)/(K11) = [000:15-17],
///
///     T = [[−1,0,0],[0,0,1],[0,1,0]],   (x_d, y_d, z_d) = (−x_s, z_s, y_s),   u_d = T u_s,
///
/// a proper rotation with T = Tᵀ = T⁻¹, so the same matrix serves both directions (P10). For
/// every other pair of machines the default is the identity: the part sits the same way on both.
/// Another setup is passed in `translate_options::setup`; its rotation must be proper
/// (`is_proper_rotation`: R Rᵀ = I and det R = +1), or tips and axes would not stay rigid.
/// @code
///   constexpr auto d_T_s = kin5::default_setup<kin5::machines::sajo_12000p, kin5::machines::dmu_80p>();
///   // d_T_s.map_point({-34.983, 9.1, 118.526}) == {34.983, 118.526, 9.1}
///   static_assert(kin5::is_proper_rotation(d_T_s.rotation));
/// @endcode
#pragma once

#include <cstddef>
#include <string_view>

#include "../core/math.hpp"
#include "../core/vec.hpp"
#include "../kinematics/machine.hpp"
#include "../machines/dmu_80p.hpp"
#include "../machines/sajo_12000p.hpp"
#include "../core/rigid.hpp"

namespace kin5 {

/// (K10) = [000:15-17]: the map between the SAJO 12000P and DMU 80P workpiece frames. The same
/// transform serves dmu_T_sajo and sajo_T_dmu, since T is its own inverse.
inline constexpr rigid_transform sajo_12000p_dmu_80p_setup{
    mat3{{vec3{-1.0, 0.0, 0.0}, vec3{0.0, 0.0, 1.0}, vec3{0.0, 1.0, 0.0}}}, vec3{}};

/// The default `target_T_source` for machines with catalog ids `from_id` → `to_id`: (K10) for
/// sajo-12000p ↔ dmu-80p (either direction), the identity otherwise.
constexpr rigid_transform default_setup(std::string_view from_id, std::string_view to_id) {
  constexpr std::string_view sajo = machines::sajo_12000p::id, dmu = machines::dmu_80p::id;
  const bool paper_pair = (from_id == sajo && to_id == dmu) || (from_id == dmu && to_id == sajo);
  return paper_pair ? sajo_12000p_dmu_80p_setup : rigid_transform::identity();
}

/// How far `r` is from a proper rotation: the largest of |det r − 1| and, per row i, the length
/// of row i of r rᵀ minus row i of the identity. 0 for an exact rotation.
constexpr double rotation_defect(const mat3& r) {
  const mat3 should_be_identity = r * r.transposed();
  double worst = math::abs(determinant(r) - 1.0);
  for (std::size_t i = 0; i < 3; ++i) {
    const double off = norm(should_be_identity.row[i] - mat3::identity().row[i]);
    worst = off > worst ? off : worst;
  }
  return worst;
}

/// Whether `r` is a proper rotation (R Rᵀ = I and det R = +1) to `tolerance`: what a setup
/// rotation must be.
constexpr bool is_proper_rotation(const mat3& r, double tolerance = 1e-9) { return rotation_defect(r) <= tolerance; }

/// The default `target_T_source` from machine From to machine To (see the file comment).
template <machine From, machine To>
constexpr rigid_transform default_setup() {
  return default_setup(From::id, To::id);
}

}  // namespace kin5

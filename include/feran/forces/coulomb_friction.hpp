#pragma once
/// @file
/// Coulomb friction between rotating parts (paper eqs. 12–14), regularised.

#include <optional>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// Dry friction between node a and node b (or the rotating frame's axis): a force of
/// magnitude F_ct0 opposing the relative lateral velocity seen in the frame rotating
/// with the shaft, s = ṙ − jΩr (r = v + j·w, relative), and a moment of magnitude
/// F_cr0 opposing the relative tilt velocity likewise (tilt pair (rz, −ry), which
/// turns with the shaft as (v, w) does). Regularised as F = −F_c0·s/√(|s|² + ε²):
/// exact Coulomb friction for |s| ≫ ε, viscous with c = F_c0/ε near s = 0.
/// Theory: docs/theory/coulomb_friction.md.
struct CoulombFriction {
  Index node_a = 0;
  std::optional<Index> node_b;  ///< empty: the rotating frame's axis
  Real force_amplitude = 0.0;   ///< F_ct0 [N]
  Real moment_amplitude = 0.0;  ///< F_cr0 [N m]
  Real epsilon_t = 1e-4;        ///< regularisation velocity, translation [m/s]
  Real epsilon_r = 1e-3;        ///< regularisation angular velocity, rotation [rad/s]

  std::string_view kind() const { return "coulomb_friction"; }
  std::vector<Index> nodes() const;
  /// v, w, ry, rz of node a, then of node b when there is one.
  std::vector<Index> dofs() const;
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const;
};

}  // namespace feran

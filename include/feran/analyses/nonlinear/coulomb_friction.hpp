#pragma once
/// @file
/// Coulomb friction between rotating parts (paper eqs. 12–14), regularised.

#include <optional>
#include <string_view>
#include <vector>

#include <feran/analyses/nonlinear/nonlinear_force.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Dry friction between node a and node b (or the rotating frame's axis): a force of
/// magnitude F_ct0 opposing the relative lateral velocity seen in the frame rotating
/// with the shaft, s = ṙ − jΩr (r = v + j·w, relative), and a moment of magnitude
/// F_cr0 opposing the relative tilt velocity likewise (tilt pair (rz, −ry), which
/// turns with the shaft as (v, w) does). Regularised as F = −F_c0·s/√(|s|² + ε²):
/// exact Coulomb friction for |s| ≫ ε, viscous with c = F_c0/ε near s = 0.
/// Theory: docs/theory/coulomb_friction.md.
class CoulombFrictionForce {
 public:
  explicit CoulombFrictionForce(const CoulombFriction& data);

  /// v, w, ry, rz of node a, then of node b when there is one.
  std::vector<Index> dofs() const;
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const;
  std::string_view kind() const { return "coulomb_friction"; }

 private:
  CoulombFriction data_;
};

}  // namespace feran

#pragma once
/// @file
/// Rolling-element bearings: the Hertzian contact force of each ball or roller, summed
/// over the elements as the cage turns, on the journal's position relative to the
/// housing. Theory: docs/theory/rolling_bearings.md.

#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// Geometry and contact law of a rolling-element bearing.
struct RollingBearingGeometry {
  int elements = 0;             ///< number Z of balls or rollers
  Real element_diameter = 0.0;  ///< d [m]
  Real pitch_diameter = 0.0;    ///< D_p [m]
  Real contact_angle = 0.0;     ///< α [rad]
  Real clearance = 0.0;         ///< radial clearance c_r [m] (≥ 0)
  /// Hertz constant K of one element's load–deflection law Q = K·δⁿ [N/mⁿ].
  Real hertz_constant = 0.0;
  bool roller = false;  ///< n = 10/9 (line contact) instead of 3/2 (point contact)

  Real exponent() const { return roller ? 10.0 / 9.0 : 1.5; }
  /// The cage's angular speed over the shaft's (inner race turning, outer at rest):
  /// (1 − (d/D_p)·cos α)/2.
  Real cage_ratio() const;
  /// The ball-pass frequency of the outer race over the shaft speed: Z·cage_ratio().
  Real ball_pass_ratio() const { return elements * cage_ratio(); }
};

/// The angular position of element @p j when the shaft has turned by @p shaft_angle:
/// cage_ratio()·φ + 2πj/Z, from +y towards +z.
Real element_angle(const RollingBearingGeometry& g, int j, Real shaft_angle);

/// The contact loads Q_j ≥ 0 [N] of the elements at relative displacement @p x = (y, z)
/// and shaft angle @p shaft_angle: Q_j = K·δ_jⁿ with δ_j = (x·e_j)·cos α − c_r where
/// positive, e_j = (cos θ_j, sin θ_j).
std::vector<Real> element_loads(const RollingBearingGeometry& g, const Eigen::Vector2d& x, Real shaft_angle);

/// A rolling-element bearing between a journal node and the ground or a housing node:
/// a nonlinear force on v and w of each, with the cage's varying compliance.
struct RollingBearing {
  Index node_a = 0;             ///< the journal (inner race)
  std::optional<Index> node_b;  ///< the housing (outer race); empty: the ground
  RollingBearingGeometry geometry;

  std::string_view kind() const { return "rolling_bearing"; }
  /// The radial internal clearance (ability clearance(), model/force.hpp; 0: none).
  Real clearance() const { return geometry.clearance; }
  std::vector<Index> nodes() const;
  /// v, w of the journal, then of the housing when there is one.
  std::vector<Index> dofs() const;
  /// −Σ_j Q_j·cos α·e_j on the journal (its opposite on the housing), with the cage at
  /// the angle of @p s; the Jacobian Σ n·K·δ_jⁿ⁻¹·cos²α·e_j·e_jᵀ (no velocity terms).
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const;
  /// It carries the rotor (the ability of model/force.hpp).
  bool supports() const { return true; }
  /// Its operating state: max_element_load_n, loaded_elements, and for balls
  /// max_contact_stress_pa, Hertz's p_max = 3Q/(2πa²) of the most loaded element with
  /// the contact of a sphere on a plane of steel (E = 210 GPa, ν = 0.3) whose radius
  /// gives the bearing's Hertz constant K = (4/3)E*√R (docs/theory/rolling_bearings.md);
  /// NaN for rollers, whose line contact needs the roller's length.
  std::vector<OperatingValue> operating_data(const MotionState& s, const Vector& x, const Vector& v) const;
};

}  // namespace feran

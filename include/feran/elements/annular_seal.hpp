#pragma once
/// @file
/// Plain annular liquid seals (pump wear rings, balance pistons, interstage
/// bushings): the short-seal bulk-flow model of Black and Childs, giving the seal's
/// direct and cross-coupled stiffness and damping and its added mass over speed.
/// Theory: docs/theory/annular_seal.md.

#include <optional>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>

namespace feran {

/// Geometry, liquid and operating condition of a plain annular seal.
struct AnnularSealGeometry {
  Real radius = 0.0;         ///< radius R of the rotor's land [m]
  Real length = 0.0;         ///< axial length L [m]
  Real clearance = 0.0;      ///< radial clearance C [m]
  Real pressure_drop = 0.0;  ///< ΔP across the seal [Pa]
  Real density = 0.0;        ///< ρ of the liquid [kg/m³]
  Real viscosity = 0.0;      ///< dynamic viscosity μ [Pa s]
  Real entrance_loss = 0.1;  ///< entrance loss coefficient ξ
  /// The Fanning friction factor of each wall, f = n·Re^m with Re = 2·C·V/ν for the
  /// flow's speed V relative to the wall (Hirs' bulk-flow law; Blasius' n = 0.079,
  /// m = −0.25 for smooth walls, as Childs and Yamada use it).
  Real friction_n = 0.079;
  Real friction_m = -0.25;
};

/// The seal's state and coefficients at one speed: the force on the rotor for a
/// small motion (y, z) of its centre is
///   f_y = −(K y + k z + C ẏ + c ż + M ÿ),  f_z = −(K z − k y + C ż − c ẏ + M z̈),
/// the fluid's swirl being half the rotor's surface speed (Black's model).
struct AnnularSealCoefficients {
  Real K = 0.0;               ///< direct stiffness [N/m] (the Lomakin effect; negative at high speed)
  Real k = 0.0;               ///< cross-coupled stiffness [N/m]
  Real C = 0.0;               ///< direct damping [N s/m]
  Real c = 0.0;               ///< cross-coupled damping [N s/m]
  Real M = 0.0;               ///< added mass [kg]
  Real axial_velocity = 0.0;  ///< mean axial velocity V of the leakage [m/s]
  Real leakage = 0.0;         ///< volume flow 2πRCV [m³/s]
  Real reynolds = 0.0;        ///< axial Reynolds number 2CV/ν
  Real friction = 0.0;        ///< λ: friction loss per unit L/C, in velocity heads ρV²
  Real sigma = 0.0;           ///< σ = λL/C
};

/// The seal's leakage and coefficients at @p speed [rad/s] (docs/theory/annular_seal.md).
/// Throws Error for a geometry that is not positive or finite.
AnnularSealCoefficients annular_seal_coefficients(const AnnularSealGeometry& g, Real speed);

/// A plain annular seal between a rotating node (its rotor land) and a non-rotating
/// node or the ground (its stator), acting on the lateral motion (y, z) of the one
/// relative to the other. Its matrices depend on speed; its added mass too, which a
/// run-up (constant mass matrix) cannot take.
class AnnularSeal {
 public:
  AnnularSeal(Index node_a, std::optional<Index> node_b, AnnularSealGeometry geometry);

  LocalMatrices local_matrices(const OperatingPoint& op) const;
  std::string_view kind() const { return "annular_seal"; }
  bool speed_dependent() const { return true; }
  std::vector<Index> dofs() const;
  Connection connection() const { return {node_a_, node_b_}; }
  /// What it transmits at @p speed: K, C and the added mass M (ability, model/element.hpp).
  Transmission transmission(Real speed) const;
  const AnnularSealGeometry& geometry() const { return geometry_; }

 private:
  Index node_a_;
  std::optional<Index> node_b_;
  AnnularSealGeometry geometry_;
};

}  // namespace feran

#pragma once
/// @file
/// Isotropic linear-elastic material.

#include <string>

#include <feran/core/types.hpp>

namespace feran {

/// Isotropic material. Units: E and G in Pa, rho in kg/m³.
struct Material {
  std::string name;
  Real E = 0.0;    ///< Young's modulus [Pa]
  Real G = 0.0;    ///< shear modulus [Pa]
  Real rho = 0.0;  ///< density [kg/m³]
  /// Hysteretic loss factor η of the material: adds j·η·K of its shafts to the
  /// dynamic stiffness in harmonic (steady-state) analyses.
  Real loss_factor = 0.0;

  /// Poisson's ratio ν = E/(2G) − 1.
  Real poisson() const { return E / (2.0 * G) - 1.0; }
  bool operator==(const Material&) const = default;
};

}  // namespace feran

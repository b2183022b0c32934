#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/annular_seals.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[annular_seals]]: a plain annular liquid seal (wear ring, balance piston, bushing).
struct AnnularSealSpec {
  std::string name;
  NodeRef node;               ///< the rotor's land
  std::optional<NodeRef> to;  ///< the stator; not given (or "ground"): the ground
  Real diameter = 0.0;        ///< 2R [m]
  Real length = 0.0;          ///< L [m]
  Real clearance = 0.0;       ///< radial clearance C [m]
  Real pressure_drop = 0.0;   ///< ΔP [Pa]
  Real density = 0.0;         ///< ρ [kg/m³]
  Real viscosity = 0.0;       ///< μ [Pa s]
  Real entrance_loss = 0.1;   ///< ξ
  Real friction_n = 0.079;    ///< n of f = n·Re^m
  Real friction_m = -0.25;    ///< m of f = n·Re^m
  bool operator==(const AnnularSealSpec&) const = default;
};

}  // namespace feran

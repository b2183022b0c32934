#pragma once
/// @file
/// A point unbalance (paper eq. 5).

#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// Mass @p mass at radius @p radius, turning with the rotor: the force
/// F_y + i·F_z = m·r·(Ω² − i·Ω')·e^{i(φ + phase)} at the node, φ the rotation angle,
/// and the moment of that force about the node through the axial lever @p lever
/// (M_y = −l·F_z, M_z = l·F_y). In a steady state Ω' = 0 and φ = Ωt.
struct Unbalance {
  Index node = 0;
  Real mass = 0.0;    ///< [kg]
  Real radius = 0.0;  ///< [m]
  Real phase = 0.0;   ///< [rad], measured from +y towards +z at t = 0
  Real lever = 0.0;   ///< axial distance from the node to the unbalance plane [m]

  std::string_view kind() const { return "unbalance"; }
  std::vector<Index> nodes() const { return {node}; }
  /// Synchronous only: in a frequency sweep an unbalance acts at Ω, not at ω.
  void add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const;
  void add_transient(const MotionState& s, Vector& f) const;
  /// m·e²: the inertia of the eccentric mass about the axis (ability, model/force.hpp).
  Real synchronous_inertia() const { return mass * radius * radius; }
};

}  // namespace feran

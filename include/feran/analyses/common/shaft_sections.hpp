#pragma once
/// @file
/// Internal forces and stresses of shaft elements at their ends.

#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// A place along a shaft where forces and stresses are reported: one end of a shaft
/// element.
struct ShaftStation {
  Index element = 0;  ///< index into Model::elements
  int end = 0;        ///< 0 at node_a (start), 1 at node_b (end)
  Index node = 0;     ///< the node at that end
  Real x = 0;         ///< axial position [m]
};

/// Section resultants acting on the face with outward normal +x (exerted by the part
/// at larger x on the part at smaller x): axial force N (tension positive), shear
/// forces Vy, Vz, torque T, bending moments My, Mz. Complex amplitudes (harmonic
/// analyses) or real values stored as complex (static analysis).
struct SectionForces {
  Complex N, Vy, Vz, T, My, Mz;
};

/// Peak stresses over a period at the section [Pa].
struct SectionStress {
  Real axial = 0;    ///< |N|/A
  Real bending = 0;  ///< M_peak·r_o/I, M_peak the largest |(My, Mz)| over a period
  Real torsion = 0;  ///< |T|·r_o/J
  Real shear = 0;    ///< transverse shear at the neutral axis: k·V_peak/A
  /// Equivalent (von Mises) stress, combined conservatively at one point:
  /// √((axial + bending)² + 3·(torsion + shear)²).
  Real von_mises = 0;
};

/// Both ends of every element of @p model that is a shaft segment, in element order.
std::vector<ShaftStation> shaft_stations(const Model& model);

/// The 12 DOF values of @p segment (node a then node b) taken from all unconstrained DOFs.
ComplexVector element_values(const ShaftSegment& segment, const ComplexVector& q_full);

/// Section forces at @p end of a shaft element from its end forces @p f (12 values:
/// the forces the two nodes exert on the element, node a then node b). For
/// equilibrium-consistent results f is the element's dynamic stiffness times its
/// displacements minus the loads distributed over it (gravity, …).
SectionForces section_forces(const ComplexVector& f, int end);

/// Peak stresses of a circular section under @p f.
SectionStress section_stress(const CircularSection& section, const SectionForces& f);

}  // namespace feran

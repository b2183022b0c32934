#pragma once
/// @file
/// Static analysis: deflection, spring and support forces, shaft internal forces and
/// stresses under gravity and static point loads: K·q = f, or with nonlinear supports
/// (fluid-film bearings) the equilibrium of analyses/static/equilibrium.hpp.

#include <vector>

#include <Eigen/Core>

#include <feran/analyses/common/shaft_sections.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/modal/stability.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

struct StaticOptions {
  /// Gravitational acceleration vector (x, y, z) [m/s²]; zero for none.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  /// Speed at which speed-dependent spring coefficients and nonlinear supports are
  /// evaluated [rad/s] (with supports, the equilibrium includes the circulatory Ω·K_i).
  Real speed = 0.0;
  bool loads = true;  ///< include Model::static_loads
  /// Decide whether the equilibrium is stable (StaticResult::stability); false leaves
  /// it unknown ("not asked"), as --no-stability does.
  bool stability = true;
};

/// Six real components indexed by Dof (forces [N], moments [N m]).
using NodeValues = std::array<Real, dofs_per_node>;

struct StaticResult {
  Vector q;  ///< displacements of all unconstrained DOFs (global_dof order)
  /// Force each spring–damper transmits to its second node or ground: K·(q_a − q_b).
  std::vector<std::pair<Index, NodeValues>> springs;  ///< (element, force)
  /// Force each nonlinear support (fluid-film bearing) transmits to its housing or the
  /// ground at the equilibrium, in the journal's DOF directions.
  std::vector<std::pair<Index, NodeValues>> supports;  ///< (force, force)
  /// Each support's operating state at the equilibrium (Force::operating_data(): a
  /// journal bearing's eccentricity ratio, film thickness, …), in the order of supports.
  std::vector<std::vector<OperatingValue>> support_data;
  /// Force transmitted to the supports at fixed DOFs, per node with fixed DOFs.
  std::vector<std::pair<Index, NodeValues>> reactions;  ///< (node, force)
  std::vector<ShaftStation> stations;
  std::vector<SectionForces> section_forces;  ///< real values (imaginary parts zero)
  std::vector<SectionStress> stresses;
  NodeValues total_load{};  ///< sum of the applied forces (moments about the origin) [N], [N m]
  /// Whether the rotor stays at this equilibrium when disturbed: the stability of the
  /// motion about it at the analysis' speed (analyses/modal/stability.hpp). An
  /// unstable equilibrium (oil whirl above the threshold, a divergence) is one the
  /// rotor does not stay at: the doors print it flagged, with the reason.
  StabilityPoint stability;
  SolverInfo info;
};

/// Runs the static analysis. Throws feran::Error when the load drives a free motion
/// (a rigid-body motion allowed by free_motions that the load does not leave alone),
/// or when the model has nonlinear supports and @p options.speed is not above 0.
/// An equilibrium not found is reported in info with the last iterate in q.
StaticResult run_static(const Model& model, const StaticOptions& options);

}  // namespace feran

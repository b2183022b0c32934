#pragma once
/// @file
/// The operating state of a model's supports over the points of an analysis — the
/// numbers a bearing engineer checks first (Force::operating_data(): a journal
/// bearing's eccentricity ratio, attitude angle, minimum film thickness, Sommerfeld
/// number, friction torque and power loss; a rolling bearing's most loaded element):
/// at the static equilibrium at each speed of a Campbell diagram or a response, in the
/// motion at each output time of a run-up.

#include <string>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// One support's operating state at each point of an analysis.
struct OperatingSeries {
  Index force = 0;                        ///< index into Model::forces
  std::vector<std::string> quantities;    ///< names carrying their unit ("min_film_thickness_m")
  std::vector<std::vector<Real>> values;  ///< [point][quantity]; NaN where the theory gives none

  /// The values of quantity @p name over the points (empty when the support has none).
  std::vector<Real> series(std::string_view name) const;
  /// Appends one point; throws Error when @p data names other quantities than before.
  void append(const std::vector<OperatingValue>& data);
};

/// One empty series per support of @p model (Force::supports(), in Model::forces
/// order), with its quantities' names: those of its state at rest in its centre (a
/// support reports the same quantities in every state).
std::vector<OperatingSeries> operating_series(const Model& model);

/// Appends to @p series (operating_series() of a model) the supports' state at the
/// static equilibrium at @p speed [rad/s] about which @p linear = linearised(model)
/// linearises them (the equilibria the linear analyses solved, not solved again).
/// Nothing for a support that needs speed at @p speed 0: its row is NaN then.
void append_at_equilibrium(std::vector<OperatingSeries>& series, const Model& linear, Real speed);

/// Appends the supports' state in the motion @p x, @p v (all unconstrained DOFs,
/// global_dof order) at @p state: a run-up's output time. A support that cannot be
/// evaluated there (its journal at the wall) gets a row of NaN.
void append_in_motion(std::vector<OperatingSeries>& series, const Model& model, const MotionState& state,
                      const Vector& x, const Vector& v);

}  // namespace feran

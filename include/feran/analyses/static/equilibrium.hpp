#pragma once
/// @file
/// The static equilibrium of a rotor running at a constant speed on bearings whose
/// force is nonlinear (forces with the ability supports(), model/force.hpp):
///
///   (K + Ω·K_i)·q − f_s(q) = f,
///
/// f the gravity and static loads, f_s the supports' forces at rest relative to their
/// housings (q' = 0), solved by Newton's method with a backtracking line search; and
/// the linearised model about it, on which the linear analyses run. Theory:
/// docs/theory/fluid_film_bearings.md.

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <feran/analyses/common/solver_info.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// The load vector over all unconstrained DOFs (global_dof order): gravity
/// @p gravity [m/s²] as M·(rigid translation by g), which carries the moments of offset
/// masses and consistent shaft masses, plus the static loads when @p loads.
Vector static_load_vector(const Model& model, const Eigen::Vector3d& gravity, bool loads);

/// Throws Error, naming the motions, when the load @p f (reduced) does work along the
/// free motions @p free (an M-orthonormal basis, stiffness_null_space()): a static
/// solution exists only when the load leaves them alone.
void require_unloaded_free_motions(const Model& model, const Assembler& assembler, const Matrix& free, const Vector& f);

/// True when some force of @p model carries the rotor (supports()).
bool has_supports(const Model& model);

/// True when some support of @p model carries load only while the rotor turns (an oil
/// film, Force::needs_speed()): analyses of it need a speed above 0.
bool needs_speed(const Model& model);

/// Throws Error, naming the support, when some of @p forces supports the rotor and
/// @p speed is not above 0: at rest an oil film carries no load and has no stiffness.
void require_running(const std::vector<Force>& forces, Real speed);

struct EquilibriumOptions {
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< [m/s²]
  bool loads = true;                                  ///< include the static loads
  Real tolerance = 1e-10;   ///< on ‖residual‖ relative to ‖f‖ + the supports' largest force
  int max_iterations = 60;  ///< Newton steps
  /// Frequency [rad/s] at which frequency-dependent coefficients are taken: 0 for a
  /// static deflection; empty: synchronous (ω = Ω), as a run-up integrates them.
  std::optional<Real> frequency = 0.0;
};

/// The equilibrium at one speed.
struct Equilibrium {
  Vector q;              ///< displacements of all unconstrained DOFs (global_dof order)
  Real residual = 0.0;   ///< relative residual reached
  Index iterations = 0;  ///< Newton steps taken
  SolverInfo info;       ///< not_converged or numerical_failure with the reason
};

/// Solves the equilibrium of @p model (assembled as @p assembler) at @p speed
/// [rad/s] from q = 0. Newton steps are cut back until the residual decreases and no
/// support is driven to its limit (a journal to its bearing wall: the force there
/// throws Error, and the step is halved). Throws Error when a support carries load at
/// rest (speed 0: an oil film has no stiffness then).
Equilibrium solve_equilibrium(const Model& model, const Assembler& assembler, Real speed,
                              const EquilibriumOptions& options);

/// The equilibria of one model over speeds, solved when first asked for and kept
/// (each from q = 0, so that the result at a speed does not depend on which speeds
/// were asked for before, or on threads). Safe to share between threads.
class EquilibriumPath {
 public:
  EquilibriumPath(Model model, EquilibriumOptions options);
  /// The equilibrium at @p speed; throws Error when it cannot be found (naming the
  /// speed and why).
  const Vector& at(Real speed) const;
  const Model& model() const { return model_; }

 private:
  Model model_;
  EquilibriumOptions options_;
  Assembler assembler_;
  mutable std::mutex mutex_;
  mutable std::map<Real, Vector> solved_;
};

/// A copy of @p model in which every force that carries the rotor is replaced by an
/// element of kind "linearised_support" at the end of the element list (the other
/// elements keep their indices): at each speed its stiffness and damping are the
/// tangent −∂f/∂x and −∂f/∂x' of the force about the equilibrium under the model's
/// gravity (Model::gravity) and static loads (zero at rest: analyses call
/// require_running() first); it reports what it transmits as a connecting element.
/// @p model itself when nothing carries the rotor. Analyses that report per element
/// index into @p model, whose elements keep their indices here.
Model linearised(const Model& model);

/// The same about the equilibria under @p about's gravity and loads (a static
/// analysis' own, which may differ from the model's).
Model linearised(const Model& model, const EquilibriumOptions& about);

/// The index in @p model.forces of the support that element @p element of
/// linearised(@p model) stands for (an index past @p model's own elements: the k-th
/// such element is the k-th force that supports()); empty for @p model's own elements.
std::optional<std::size_t> linearised_support_force(const Model& model, Index element);

/// The user's name of element @p element of linearised(@p model): its label, or the
/// label of the support it stands for, else "element N", or for a support its kind
/// and its number among the forces ("fluid film bearing 3").
std::string linearised_element_name(const Model& model, Index element);

}  // namespace feran

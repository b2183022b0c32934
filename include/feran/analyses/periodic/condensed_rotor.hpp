#pragma once
/// @file
/// A feran model condensed for harmonic balance and Floquet analysis: the
/// Craig–Bampton reduction (Craig & Bampton 1968) that keeps the DOFs of the nonlinear
/// forces and of the loads as they are — the nonlinear forces then act on a few
/// physical coordinates, and the AFT's cost grows with them, not with the mesh — and
/// represents the rest of the rotor by its static response to those DOFs (constraint
/// modes) and its lowest modes with them held (fixed-interface modes), plus the static
/// deflection under gravity and the static loads with them held. The linear part at a
/// speed is the model's own matrices projected (gyroscopics, speed-dependent supports,
/// internal damping and added masses at that speed); with every interior mode kept
/// the condensation is exact. Theory: docs/theory/harmonic_balance.md ("The rotor").

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <feran/analyses/periodic/harmonic_balance.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

struct CondensationOptions {
  /// Fixed-interface modes kept (the lowest with lateral motion); more than the
  /// interior has: all of them (exact).
  Index modes = 12;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< [m/s²]
  bool static_loads = true;                           ///< the model's static loads act
  /// The unbalances and synchronous harmonic forces act (at the rotor speed): forced
  /// orbits. Without them the orbits are self-excited or none.
  bool unbalance = true;
  /// The speed [rad/s] at which the constraint and fixed-interface modes are computed
  /// (speed-dependent supports enter the basis at it; the projected matrices are
  /// always those at the speed asked for).
  Real reference_speed = 0.0;
};

/// The condensed model. Coordinates η: the kept DOFs first (reduced model DOFs, in
/// increasing order), then the modal coordinates; the model's reduced DOFs are
/// q = Φ·η.
class CondensedRotor {
 public:
  /// Throws Error, with the reason, for what the periodic analysis cannot take:
  /// frequency-dependent supports (tables by frequency), hysteretic loss factors
  /// (defined for harmonic motion only), harmonic forces with a frequency of their own,
  /// a model larger than the dense eigensolver of the reduction takes.
  CondensedRotor(const Model& model, std::shared_ptr<const Assembler> assembler, const CondensationOptions& options);
  /// @p model on the basis of @p basis_of (its options too): a model that differs from
  /// that one's in numbers only (a parameter of a branch), projected on the same
  /// coordinates, so that a branch's unknowns keep their meaning as the parameter
  /// moves. Throws Error when the DOFs or where the forces and loads act differ.
  CondensedRotor(const Model& model, std::shared_ptr<const Assembler> assembler, const CondensedRotor& basis_of);

  /// Coordinates n_η.
  Index size() const { return basis_.cols(); }
  /// The kept physical DOFs (reduced model DOFs), the first coordinates.
  const std::vector<Index>& kept() const { return kept_; }
  /// Interior modes kept.
  Index modes() const { return modes_; }
  /// Φ, reduced model DOFs × n_η.
  const Matrix& basis() const { return basis_; }
  /// The coordinates the nonlinear forces act on (the system's force_dofs).
  const std::vector<Index>& force_coordinates() const { return force_coordinates_; }
  /// True when loads act at the rotor speed (unbalances, synchronous harmonic forces):
  /// the orbit's base frequency is then the speed.
  bool forced() const { return forced_; }
  /// True when the model has nonlinear forces.
  bool nonlinear() const { return !forces_.empty(); }

  /// The system at rotor speed @p speed for orbits of base frequency @p omega with the
  /// harmonics of @p fourier: M, C(Ω), K(Ω) projected; the constant loads as the mean,
  /// the loads at the speed as harmonic 1 (forced() requires ω = Ω; throws otherwise;
  /// with harmonic 0 alone they are left out: the static equilibrium); the nonlinear
  /// forces on force_coordinates() at rotation angle Ω·t. The system's force refers to
  /// this object, which must outlive it.
  PeriodicSystem at(Real speed, Real omega, const FourierBasis& fourier) const;

  /// All unconstrained DOFs (global_dof order) from coordinates @p eta.
  Vector expand(const Vector& eta) const;
  /// The coordinates of the static equilibrium at @p speed [rad/s] as the static
  /// analysis solves it on the whole model (its Newton steps cut back at the
  /// supports' limits, from rest), fitted to the basis by least squares: where the
  /// balance's own Newton steps cannot start from rest (a support without stiffness
  /// there: rolling elements in their clearance). Throws Error when it is not found.
  Vector static_equilibrium(Real speed) const;
  /// The model the rotor was condensed from.
  const Model& model() const { return model_; }
  const Assembler& assembler() const { return *assembler_; }

 private:
  void collect();  // the checks, the nonlinear forces, the kept DOFs, the constant load
  void reduce();   // the Craig–Bampton basis

  const Model& model_;
  std::shared_ptr<const Assembler> assembler_;
  CondensationOptions options_;
  std::vector<Index> kept_;
  Index modes_ = 0;
  Matrix basis_;
  std::vector<Force> forces_;      // the nonlinear forces
  std::vector<Matrix> selectors_;  // per force: its local DOFs from force_coordinates()
  std::vector<Index> force_coordinates_;
  Vector constant_load_;  // reduced DOFs
  bool forced_ = false;
};

}  // namespace feran

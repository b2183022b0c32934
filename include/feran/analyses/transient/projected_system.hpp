#pragma once
/// @file
/// A second-order system restricted to a subspace: x = Φ·η (Galerkin projection). It
/// knows nothing about rotors; run_transient uses it with a basis of undamped modes
/// (modal_basis.hpp) so that explicit integrators are not held to the step that the
/// highest finite-element modes allow.

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <feran/integrators/second_order_system.hpp>

namespace feran {

/// Φᵀ·M·Φ·η'' = Φᵀ·r(t, Φη, Φη'). The full system's forces — nonlinear and
/// speed-dependent ones included — are evaluated at Φη and projected, so the
/// projection is exact when the motion lies in span(Φ); with Φ = identity it is the
/// full system.
class ProjectedSystem final : public SecondOrderSystem {
 public:
  /// @p full must outlive this object; @p basis is n × m with linearly independent
  /// columns.
  ProjectedSystem(SecondOrderSystem& full, Matrix basis);

  Index size() const override { return basis_.cols(); }
  void rhs(Real t, const Vector& x, const Vector& v, Vector& r) override;
  void mass_times(const Vector& u, Vector& y) const override { y = mass_ * u; }
  void solve_mass(const Vector& r, Vector& a) override { a = mass_llt_.solve(r); }
  void set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) override;
  void stiffness_times(const Vector& u, Vector& y) const override { y = stiffness_ * u; }
  void damping_times(const Vector& u, Vector& y) const override { y = damping_ * u; }
  bool factor_tangent(Real c_x, Real c_v, Real c_a) override;
  void solve_tangent(const Vector& rhs, Vector& delta) override { delta = lu_.solve(rhs); }
  /// From the projected pencil: the Jacobian at rest (t = 0, η = η' = 0) symmetrised,
  /// its largest generalised eigenvalue against Φᵀ·M·Φ, plus 10 %. It sets the
  /// Jacobian (of this and the full system) to that one at rest.
  Real highest_frequency() override;

  /// Φ (n × m).
  const Matrix& basis() const { return basis_; }
  /// Φ·η.
  Vector expand(const Vector& reduced) const { return basis_ * reduced; }

 private:
  /// Φᵀ·A·Φ for A = K_T (stiffness) or D_T, through the full system's products.
  Matrix project(bool stiffness) const;

  SecondOrderSystem& full_;
  Matrix basis_;
  Matrix mass_, stiffness_, damping_;
  Eigen::LLT<Matrix> mass_llt_;
  Eigen::FullPivLU<Matrix> lu_;
  Vector x_full_, v_full_, r_full_;
};

}  // namespace feran

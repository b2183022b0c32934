#pragma once
/// @file
/// A feran model as a SecondOrderSystem for the time integrators.

#include <memory>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <feran/analyses/transient/second_order_system.hpp>
#include <feran/analyses/transient/speed_profile.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// M q'' = f(t) + f_nl(t, q, q', Ω) − (C(Ω) + C_i + Ω G) q' − (K(Ω) + Ω K_i) q in
/// reduced coordinates, with Ω = Ω(t) from a speed profile. f(t) holds the
/// unbalances, m·r·(Ω² − jΩ')·e^{j(φ + phase)} with φ = ∫Ω dt (plus their lever
/// moments), the model's harmonic forces at the angle φ, and optionally a constant
/// load (gravity, the static loads). Speed-dependent coefficients follow Ω(t).
class RotorSystem final : public SecondOrderSystem {
 public:
  /// @p model must outlive the system. @p constant_load: over all unconstrained DOFs
  /// (global_dof order), or empty.
  RotorSystem(const Model& model, SpeedProfile profile, Vector constant_load = {});

  Index size() const override { return M_.rows(); }
  void rhs(Real t, const Vector& x, const Vector& v, Vector& r) override;
  void mass_times(const Vector& u, Vector& y) const override { y.noalias() = M_ * u; }
  void solve_mass(const Vector& r, Vector& a) override { a = mass_.solve(r); }
  void set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) override;
  void stiffness_times(const Vector& u, Vector& y) const override { y.noalias() = KT_ * u; }
  void damping_times(const Vector& u, Vector& y) const override { y.noalias() = DT_ * u; }
  bool factor_tangent(Real c_x, Real c_v, Real c_a) override;
  void solve_tangent(const Vector& rhs, Vector& delta) override { delta = lu_.solve(rhs); }
  /// Without nonlinear forces the system is linear in (x, v), and the Jacobian is
  /// exact at every time whose speed equals the speed it was set at.
  bool tangent_exact_at(Real t) const override {
    return forces_.empty() && profile_.speed(t) == jacobian_speed_;
  }
  Real highest_frequency() override;

  const DofMap& dof_map() const { return assembler_.dof_map(); }
  const Assembler& assembler() const { return assembler_; }
  const SpeedProfile& profile() const { return profile_; }
  /// Displacements (or velocities) of all unconstrained DOFs.
  Vector expand(const Vector& reduced) const { return assembler_.dof_map().expand(reduced); }

 private:
  /// Nonlinear force @p i at the state; an Error it throws is rethrown naming the force.
  NonlinearForceValue evaluate(std::size_t i, const MotionState& state, const Vector& x, const Vector& v) const;
  void update_speed(Real speed);
  void external_forces(Real t, Vector& f_full) const;

  const Model& model_;
  Assembler assembler_;
  SpeedProfile profile_;
  Vector constant_load_;  // over all unconstrained DOFs; empty: none
  SparseMatrix M_, C_, K_, G_, Ci_, Ki_;  // speed-independent parts
  SparseMatrix Cc_;                       // C_ + Ci_
  Vector work_;                           // rhs() scratch
  SystemMatrices variable_;               // speed-dependent parts at cached_speed_
  Real cached_speed_;
  Eigen::SimplicialLDLT<SparseMatrix> mass_;
  std::vector<Force> forces_;  ///< the model's nonlinear forces
  std::vector<SparseMatrix> selectors_;  // per force: rows of T for its DOFs
  SparseMatrix DT_, KT_;
  Real jacobian_speed_;  // the speed of DT_, KT_ (NaN before the first)
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  Index pattern_nonzeros_ = -1;
  Vector f_full_;
};

}  // namespace feran

#pragma once
/// @file
/// The problem seen by the time integrators: M·a = r(t, x, v). It knows nothing about
/// rotors; analyses/transient/rotor_system.hpp implements it for a feran model.

#include <feran/core/types.hpp>

namespace feran {

/// A point of a trajectory: time, displacement, velocity, acceleration.
struct State {
  Real t = 0.0;
  Vector x, v, a;
};

/// The state at time @p t between two states @p a and @p b (a.t ≤ t ≤ b.t) by cubic
/// Hermite interpolation of their displacements and velocities: fourth-order accurate,
/// so sampling a trajectory adds no error beyond the integrators' own.
void interpolate(const State& a, const State& b, Real t, Vector& x, Vector& v);

/// A second-order system M·x'' = r(t, x, v) with constant, symmetric positive
/// definite M. Its Jacobian approximation (set_jacobian) is
///   K_T ≈ −∂r/∂x,  D_T ≈ −∂r/∂v,
/// and the tangent operations use the approximation last set. Implementations own
/// their factorisations; the integrators only call these functions.
class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  /// Number of unknowns n.
  virtual Index size() const = 0;
  /// r(t, x, v), the right-hand side of M·a = r (external, damping, elastic and
  /// nonlinear forces).
  virtual void rhs(Real t, const Vector& x, const Vector& v, Vector& r) = 0;
  /// y = M·u.
  virtual void mass_times(const Vector& u, Vector& y) const = 0;
  /// Solves M·a = r.
  virtual void solve_mass(const Vector& r, Vector& a) = 0;

  /// Sets the Jacobian approximation at (t, x, v). With @p exact the tangents of the
  /// nonlinear forces are included; without, only the linear part (still a valid
  /// approximation for W-methods, whose order does not depend on it).
  virtual void set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) = 0;
  /// y = K_T·u for the Jacobian last set.
  virtual void stiffness_times(const Vector& u, Vector& y) const = 0;
  /// y = D_T·u for the Jacobian last set.
  virtual void damping_times(const Vector& u, Vector& y) const = 0;
  /// Factorises S = c_a·M + c_v·D_T + c_x·K_T for the Jacobian last set. Returns
  /// false when S is singular.
  virtual bool factor_tangent(Real c_x, Real c_v, Real c_a) = 0;
  /// Solves S·δ = rhs with the last factorisation.
  virtual void solve_tangent(const Vector& rhs, Vector& delta) = 0;
  /// True when r is affine in (x, v) and the Jacobian last set is its exact Jacobian
  /// at time @p t: then one Newton step with a factorisation of it solves an
  /// implicit stage at t exactly (up to round-off), and a second step only confirms.
  /// The default, false, is always safe.
  virtual bool tangent_exact_at(Real t) const {
    static_cast<void>(t);
    return false;
  }

  /// True when setting the Jacobian at a step's predicted state and factorising it
  /// costs about one Newton iteration (a banded factorisation): an implicit step then
  /// starts from a fresh tangent instead of one kept from an earlier state and speed
  /// (on a speed ramp the kept tangent's speed-dependent terms lag behind, and a
  /// nonlinear force's Jacobian belongs to another state). For a linear system the
  /// fresh tangent is exact, and one solve ends the step. The default, false, keeps the
  /// tangent while Newton's iteration contracts.
  virtual bool refresh_pays_at(Real t) const {
    static_cast<void>(t);
    return false;
  }

  /// An estimate, from above, of the highest undamped natural frequency [rad/s]
  /// (for the stability limit of explicit methods).
  virtual Real highest_frequency() = 0;
};

}  // namespace feran

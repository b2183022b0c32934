// A linear rotor on a speed ramp: its tangent is refreshed at every step (banded,
// about one iteration's cost), so each step takes one exact solve, where a tangent
// kept from an earlier speed iterates; both give the same trajectory to the Newton
// tolerance.
#include <gtest/gtest.h>

#include <vector>

#include <feran/integrators/newmark.hpp>
#include <feran/analyses/transient/rotor_system.hpp>

#include "test_models.hpp"

namespace feran {
namespace {

// The rotor system as it was before refreshing paid: the same in every respect but
// refresh_pays_at(), which is false.
class KeptTangent final : public SecondOrderSystem {
 public:
  explicit KeptTangent(RotorSystem& s) : s_(s) {}
  Index size() const override { return s_.size(); }
  void rhs(Real t, const Vector& x, const Vector& v, Vector& r) override { s_.rhs(t, x, v, r); }
  void mass_times(const Vector& u, Vector& y) const override { s_.mass_times(u, y); }
  void solve_mass(const Vector& r, Vector& a) override { s_.solve_mass(r, a); }
  void set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) override { s_.set_jacobian(t, x, v, exact); }
  void stiffness_times(const Vector& u, Vector& y) const override { s_.stiffness_times(u, y); }
  void damping_times(const Vector& u, Vector& y) const override { s_.damping_times(u, y); }
  bool factor_tangent(Real c_x, Real c_v, Real c_a) override { return s_.factor_tangent(c_x, c_v, c_a); }
  void solve_tangent(const Vector& r, Vector& d) override { s_.solve_tangent(r, d); }
  bool tangent_exact_at(Real t) const override { return s_.tangent_exact_at(t); }
  Real highest_frequency() override { return s_.highest_frequency(); }

 private:
  RotorSystem& s_;
};

TEST(RampTangent, OneExactSolvePerStepAndTheKeptTangentsTrajectory) {
  const Model model = test::friswell_5_9_1(24);
  const SpeedProfile ramp = SpeedProfile::ramp(0.0, 4000.0 * 2.0 * pi / 60.0, 0.05);
  RotorSystem refreshed(model, ramp), plain(model, ramp);
  KeptTangent kept(plain);
  State a, b;
  a.x = Vector::Zero(refreshed.size());
  for (Index i = 0; i < a.x.size(); ++i)
    a.x(i) = 1e-5 * std::sin(0.3 * static_cast<Real>(i));  // a bent, whirling start
  a.v = 50.0 * a.x.reverse();
  b = a;
  Newmark ia{IntegratorSettings{}}, ib{IntegratorSettings{}};
  ASSERT_TRUE(ia.start(refreshed, a).ok);
  ASSERT_TRUE(ib.start(kept, b).ok);
  Index iterations_a = 0, iterations_b = 0, factorisations_a = 0;
  Real difference = 0.0, amplitude = 0.0, budget = 0.0;
  for (int k = 0; k < 500; ++k) {
    const Vector before = a.x;
    const StepReport ra = ia.step(refreshed, a, 1e-4);
    // Each run's step is solved to the Newton tolerance, 1e-10 of its increment.
    budget += 2.0 * IntegratorSettings{}.newton_tol * (a.x - before).norm();
    const StepReport rb = ib.step(kept, b, 1e-4);
    ASSERT_TRUE(ra.ok && rb.ok) << ra.message << rb.message;
    iterations_a += ra.iterations;
    iterations_b += rb.iterations;
    factorisations_a += ra.factorizations;
    difference = std::max(difference, (a.x - b.x).norm());
    amplitude = std::max(amplitude, a.x.norm());
  }
  EXPECT_TRUE(refreshed.refresh_pays_at(0.0));  // banded: a straight shaft line
  EXPECT_EQ(iterations_a, 500);                 // one solve a step
  EXPECT_EQ(factorisations_a, 500);
  EXPECT_GT(iterations_b, 1000);  // the kept tangent iterates (measured 6.0 a step)
  // Both runs solve each step to the Newton tolerance: they differ by at most the sum
  // of the steps' tolerances (the stable dynamics carry an error along, not grow it).
  EXPECT_LT(difference, budget);  // measured 0.75 % of it, 8e-10 of the amplitude
}

TEST(RampTangent, EachSolveIsTheTangentsAtItsOwnSpeedAtAnySpacing) {
  // The tangents of the steps to come are factorised four at a time (at the spacing
  // of the last two factorisations) and a step solves with the one at its speed: at
  // regular times (lanes used), irregular ones (lanes missed, then single ones for a
  // while) and regular ones again, every solve satisfies S(Ω(t))·δ = r to round-off,
  // S = c_a·M + c_v·D_T + c_x·K_T set at that time (the products checked).
  const Model model = test::friswell_5_9_1(24);
  RotorSystem sys(model, SpeedProfile::ramp(0.0, 800.0, 1.0));
  const Index n = sys.size();
  const Vector x = Vector::Zero(n), v = Vector::Zero(n), r = Vector::LinSpaced(n, -1.0, 2.0);
  const Real dt = 1e-4, c_v = 2.0 / dt, c_a = 4.0 / (dt * dt);
  std::vector<Real> times;
  for (int k = 0; k < 12; ++k) times.push_back(0.2 + k * dt);                    // regular
  for (int k = 0; k < 24; ++k) times.push_back(0.3 + k * dt * (1.0 + (k % 3)));  // irregular
  for (int k = 0; k < 40; ++k) times.push_back(0.4 + k * dt);                    // regular again
  Vector delta, Md, Dd, Kd;
  for (const Real t : times) {
    sys.set_jacobian(t, x, v, true);
    ASSERT_TRUE(sys.factor_tangent(1.0, c_v, c_a)) << "t = " << t;
    sys.solve_tangent(r, delta);
    sys.mass_times(delta, Md);
    sys.damping_times(delta, Dd);
    sys.stiffness_times(delta, Kd);
    const Vector residual = c_a * Md + c_v * Dd + Kd - r;
    // The tangent is dominated by c_a·M (well conditioned): a backward-stable solve
    // leaves a residual of a few ε of ‖S‖·‖δ‖ ≈ ‖r‖; the tangent of the step before
    // (0.08 rad/s off) leaves 1.2e-6 of ‖r‖ (measured: a lane picked wrongly).
    EXPECT_LT(residual.norm(), 1e-12 * r.norm()) << "t = " << t;
  }
}

}  // namespace
}  // namespace feran

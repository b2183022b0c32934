// Harmonic-balance orbits of oil whip against run-ups of the same rotor: the rigid
// rotor of Friswell et al. (2010), Example 5.5.1, in two short bearings (525 N each),
// whose Hopf point at 863.345 rad/s is subcritical (tests/unit/analyses/periodic).
// Each run-up integrates the nonlinear film forces in time (trapezoidal rule, 10 µs:
// the whirl's period of about 15 ms is resolved to a phase error near 1e-5 per
// period) at constant speed; an orbit's size is half the left journal's peak-to-peak
// displacement (in y or z, the larger), sampled every 0.1 ms (≈ 150 samples per
// period: the sampled extremes are within 2e-4 of the true ones).
// - At 950 rad/s, above the threshold, the equilibrium is unstable: a run-up started
//   at it with a disturbance of a nanometre ends on the large whip orbit, whose size
//   it matches (measured 3e-5).
// - At 850 rad/s, between the fold (807.6 rad/s) and the threshold, three steady
//   states coexist: the stable equilibrium, an unstable small orbit and the stable
//   large orbit. A run-up started at 90 % of the large orbit returns to it (measured
//   4e-4); one started on the small orbit stays on it for a period (it is a solution:
//   measured 2e-4), and ones started 2 % outside and inside it leave it, as its
//   multiplier above 1 says they must: after 2 s the one outside is within 5 % of the
//   large orbit (measured 1 %), the one inside below 60 % of the small one (measured
//   45 %) on its way to the equilibrium.
// - Hill's largest multiplier at every orbit of the branch against the monodromy's
//   (exponential integrator, the phase projected out): within 1e-9 + 0.1 × the orbit's
//   truncation estimate, and the same verdict.
// The sizes are asserted to 2e-3 (the issue asks 1 %): the sampling's 2e-4, the
// run-ups' distance from their limit after 120 periods at the multipliers found
// (≈ 4e-4), and the harmonic truncation at H = 8 (the orbit sizes change by 3e-6
// relative from H = 8 to H = 16).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <feran/analyses/periodic/floquet.hpp>
#include <feran/analyses/periodic/orbits.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>

#include "test_models.hpp"

namespace feran::test_whip_orbits {
namespace {

constexpr Index journal = 1;  // node "left"

struct Whirl {
  Model model = test::rigid_rotor_in_journal_bearings(525.0 / 9.81, FilmTheory::short_bearing);
  CondensedRotor rotor{
      model,
      nullptr,
      {.modes = 12, .gravity = model.gravity, .static_loads = true, .unbalance = false, .reference_speed = 500.0}};
  OrbitSettings settings;
  OrbitBranch branch;

  Whirl() {
    settings.continuation.p_min = 600.0;
    settings.continuation.p_max = 1100.0;
    const OrbitBranch eq = equilibrium_branch(rotor, settings);
    settings.fourier = {.harmonics = 8, .samples = 64};
    settings.continuation.max_points = 80;
    branch = hopf_branch(rotor, eq.bifurcations.at(0), settings);
  }
};

const Whirl& whirl() {
  static const Whirl w;
  return w;
}

// An orbit's size: half the journal's peak-to-peak displacement in y and in z (the
// larger), which needs no mean position; here over 720 phases.
Real half_range(const std::vector<Real>& y, const std::vector<Real>& z) {
  const auto [ylo, yhi] = std::minmax_element(y.begin(), y.end());
  const auto [zlo, zhi] = std::minmax_element(z.begin(), z.end());
  return 0.5 * std::max(*yhi - *ylo, *zhi - *zlo);
}

Real orbit_size(const Whirl& w, const SteadyState& o) {
  Vector x, v;
  std::vector<Real> y, z;
  for (int j = 0; j < 720; ++j) {
    orbit_state(w.rotor, o, w.settings.fourier, 2 * pi * j / 720.0, x, v);
    y.push_back(x(global_dof(journal, Dof::v)));
    z.push_back(x(global_dof(journal, Dof::w)));
  }
  return half_range(y, z);
}

// The run at constant @p speed from (x0, v0) for @p duration: the journal's largest
// size over the window [from, to].
Real run_size(const Whirl& w, Real speed, const Vector& x0, const Vector& v0, Real duration, Real from, Real to) {
  TransientOptions options;
  options.profile = SpeedProfile::constant(speed);
  options.duration = duration;
  options.integrator = "trapezoidal";
  options.settings.dt = 1e-5;
  options.output_interval = 1e-4;
  options.probes = {journal};
  options.gravity = w.model.gravity;
  options.initial_displacement = x0;
  options.initial_velocity = v0;
  const TransientResult r = run_transient(w.model, options);
  EXPECT_TRUE(r.info.converged()) << r.info.message;
  std::vector<Real> y, z;
  for (const TransientSample& s : r.samples)
    if (s.t >= from && s.t <= to) {
      y.push_back(s.probes[0][1]);
      z.push_back(s.probes[0][2]);
    }
  return half_range(y, z);
}

TEST(WhipOrbits, AboveTheThresholdTheRunupReachesTheWhipOrbit) {
  const Whirl& w = whirl();
  const std::vector<SteadyState> at = states_at(w.rotor, w.branch, 950.0, w.settings);
  ASSERT_EQ(at.size(), 1U);
  ASSERT_TRUE(at[0].stable);
  const Real expected = orbit_size(w, at[0]);
  // From the equilibrium, disturbed by a nanometre.
  const FourierBasis mean{.harmonics = 0, .samples = 1};
  SteadyState eq = at[0];
  eq.X = at[0].X.head(w.rotor.size());
  eq.frequency = 0.0;
  Vector x0, v0;
  orbit_state(w.rotor, eq, mean, 0.0, x0, v0);
  x0(global_dof(0, Dof::v)) += 1e-9;
  const Real size = run_size(w, 950.0, x0, v0, 3.0, 2.8, 3.0);
  std::printf("950 rad/s: orbit %.6e m, run-up %.6e m\n", expected, size);
  EXPECT_NEAR(size, expected, 2e-3 * expected);
}

TEST(WhipOrbits, BetweenFoldAndThresholdTheLargeOrbitIsReachedAndTheSmallOneLeft) {
  const Whirl& w = whirl();
  std::vector<SteadyState> at = states_at(w.rotor, w.branch, 850.0, w.settings);
  ASSERT_EQ(at.size(), 2U);
  std::sort(at.begin(), at.end(),
            [&](const SteadyState& a, const SteadyState& b) { return orbit_size(w, a) < orbit_size(w, b); });
  const SteadyState &small = at[0], &large = at[1];
  EXPECT_FALSE(small.stable);
  EXPECT_TRUE(large.stable);
  const Real small_size = orbit_size(w, small), large_size = orbit_size(w, large);
  Vector x0, v0;
  // 90 % of the large orbit about its mean.
  orbit_state(w.rotor, large, w.settings.fourier, 0.0, x0, v0);
  const Vector mean = w.rotor.expand(large.X.head(w.rotor.size()));
  const Real reached = run_size(w, 850.0, mean + 0.9 * (x0 - mean), 0.9 * v0, 2.0, 1.8, 2.0);
  std::printf("850 rad/s: large orbit %.6e m, run-up %.6e m\n", large_size, reached);
  EXPECT_NEAR(reached, large_size, 2e-3 * large_size);
  // On the small orbit, and 2 % outside and inside it.
  orbit_state(w.rotor, small, w.settings.fourier, 0.0, x0, v0);
  const Real period = 2 * pi / small.frequency;
  const Real first = run_size(w, 850.0, x0, v0, period, 0.0, period);
  const Vector centre = w.rotor.expand(small.X.head(w.rotor.size()));
  const Real outward = run_size(w, 850.0, centre + 1.02 * (x0 - centre), 1.02 * v0, 2.0, 1.8, 2.0);
  const Real inward = run_size(w, 850.0, centre + 0.98 * (x0 - centre), 0.98 * v0, 2.0, 1.8, 2.0);
  std::printf("850 rad/s: small orbit %.6e m, first period %.6e m; from 2 %% out %.6e m, from 2 %% in %.6e m\n",
              small_size, first, outward, inward);
  EXPECT_NEAR(first, small_size, 2e-3 * small_size);
  EXPECT_NEAR(outward, large_size, 0.05 * large_size);  // out, nearly at the whip orbit after 2 s
  EXPECT_LT(inward, 0.6 * small_size);                  // in, towards the equilibrium
}

// The multiplier that decides the small orbit's stability at 850 rad/s against the
// growth of a run-up's departure from it: started 0.1 % outside the orbit, the run's
// size per period (half its peak-to-peak over each period of the orbit) departs from
// the orbit's by a factor μ per period while the departure is small; a least-squares
// line through ln|size_k − size| over the periods where the departure is between
// 0.2 % and 2 % of the size gives ln μ. Hill's largest multiplier agrees to 2 % in
// ln μ (measured 1.0 %: the departure's second-order growth, which gave 3.6 % with a
// window up to 10 %, and the per-period sampling).
TEST(WhipOrbits, HillsMultiplierIsTheRunupsGrowthPerPeriod) {
  const Whirl& w = whirl();
  std::vector<SteadyState> at = states_at(w.rotor, w.branch, 850.0, w.settings);
  ASSERT_EQ(at.size(), 2U);
  const SteadyState& small = orbit_size(w, at[0]) < orbit_size(w, at[1]) ? at[0] : at[1];
  ASSERT_FALSE(small.stable);
  const Real size = orbit_size(w, small), period = 2 * pi / small.frequency;
  Vector x0, v0;
  orbit_state(w.rotor, small, w.settings.fourier, 0.0, x0, v0);
  const Vector centre = w.rotor.expand(small.X.head(w.rotor.size()));
  TransientOptions options;
  options.profile = SpeedProfile::constant(850.0);
  options.duration = 150 * period;
  options.integrator = "trapezoidal";
  options.settings.dt = period / 2000;
  options.output_interval = period / 400;
  options.probes = {journal};
  options.gravity = w.model.gravity;
  options.initial_displacement = centre + 1.001 * (x0 - centre);
  options.initial_velocity = 1.001 * v0;
  const TransientResult r = run_transient(w.model, options);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  std::vector<std::vector<Real>> y(150), z(150);
  for (const TransientSample& s : r.samples) {
    const auto k = static_cast<std::size_t>(s.t / period);
    if (k < y.size()) {
      y[k].push_back(s.probes[0][1]);
      z[k].push_back(s.probes[0][2]);
    }
  }
  Real sk = 0, sy = 0, skk = 0, sky = 0, n = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (y[k].size() < 100) continue;
    const Real departure = std::abs(half_range(y[k], z[k]) - size);
    if (departure < 2e-3 * size || departure > 2e-2 * size) continue;
    const Real kk = static_cast<Real>(k), yy = std::log(departure);
    sk += kk, sy += yy, skk += kk * kk, sky += kk * yy, n += 1;
  }
  ASSERT_GT(n, 10);
  const Real measured = (n * sky - sk * sy) / (n * skk - sk * sk);
  const Real hill = std::log(small.floquet.largest);
  std::printf("ln mu per period: Hill %.6f, run-up %.6f (%g periods)\n", hill, measured, n);
  EXPECT_NEAR(measured, hill, 0.02 * hill);
}

// Hill's multipliers along the whole branch against the monodromy's: the linearised
// equations integrated over one period by the exponential integrator (the film's
// stiffness leaves the Runge–Kutta check of the unit tests unstable below ~4000 steps
// per period), with the phase's multiplier projected out. The two methods converge to
// the same multipliers as the harmonics grow; at H = 8 they differ by an amount the
// orbit's truncation estimate bounds: measured 1e-12 where the estimate is 1e-12, and
// at most 0.035 × the estimate (3.3e-4 at the fold, estimate 9.5e-3). Asserted:
// |Hill − monodromy| ≤ 1e-9 + 0.1 × estimate + the monodromy's own error (1024 against
// 2048 steps, measured at most 4.4e-7, asserted below 1e-5), and the same verdict.
TEST(WhipOrbits, HillsMultipliersAgreeWithTheMonodromyAlongTheBranch) {
  const Whirl& w = whirl();
  ASSERT_GT(w.branch.orbits.size(), 10U);
  for (std::size_t i = 1; i < w.branch.orbits.size(); ++i) {
    const SteadyState& o = w.branch.orbits[i];
    const PeriodicSystem sys = w.rotor.at(o.speed, o.frequency, w.settings.fourier);
    const Real coarse =
        monodromy_floquet(w.settings.fourier, sys, o.frequency, o.X, 1024, true, MonodromyScheme::exponential).largest;
    const Real fine =
        monodromy_floquet(w.settings.fourier, sys, o.frequency, o.X, 2048, true, MonodromyScheme::exponential).largest;
    std::printf("%3zu %.3f rad/s: Hill %.10f, monodromy %.10f (1024 steps: %.10f), truncation %.2e\n", i, o.speed,
                o.floquet.largest, fine, coarse, o.truncation);
    EXPECT_LT(std::abs(coarse - fine), 1e-5) << i;
    EXPECT_LE(std::abs(o.floquet.largest - fine), 1e-9 + 0.1 * o.truncation + std::abs(coarse - fine)) << i;
    EXPECT_EQ(o.stable, fine <= 1.0 + w.settings.stability_tolerance) << i;
  }
}

}  // namespace
}  // namespace feran::test_whip_orbits

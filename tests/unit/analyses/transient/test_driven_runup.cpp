// Torque-driven run-ups: a Jeffcott rotor (disk of mass M on an isotropic spring k with
// damping c, unbalance m_u·e) on a DC motor T = T_s(1 − Ω/Ω₀).
//
// At a steady speed Ω the disk whirls in a circle of radius r = m_u e Ω²/|k − MΩ² + icΩ|,
// and the unbalance's reaction torque on the drive, m_u e·(ÿ cos φ − ẍ sin φ), averages
// to the power the damper dissipates over Ω: cΩr². The steady speeds are the roots of
// the torque balance T_s(1 − Ω/Ω₀) = cΩ·(m_u e Ω²)²/((k − MΩ²)² + (cΩ)²); the drag is
// sharply peaked at the critical speed √(k/M), so a weak motor is captured below it (the
// Sommerfeld effect) while a strong one passes (Kononenko 1969; Balthazar et al. 2003,
// Meccanica 38:613–621). As the drive's inertia grows without bound with T/J fixed,
// the run becomes the prescribed ramp Ω₀ + (T/J)t: the speed's deviation, and with it
// the orbit's, falls as 1/J.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/elements/rigid_body.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/forces/fluid_film_bearing.hpp>
#include <feran/forces/unbalance.hpp>

namespace feran::test_driven_runup {
namespace {

constexpr Real M = 10.0, k = 4e6, zeta = 0.02, mu = 0.2, e = 0.05;  // m_u e = 0.01 kg m
const Real c = 2 * zeta * std::sqrt(k * M);
const Real w_n = std::sqrt(k / M);  // 632.5 rad/s

Model jeffcott_on_drive(const Drive& drive) {
  Model model;
  model.nodes = {{1, "disk", 0.0, true}};
  model.elements.emplace_back(
      RigidBody(0, {.mass = M, .transverse_inertia = 0.01, .polar_inertia = 0.02, .offset = 0.0}, true), "disk");
  SpringDamperCoefficients sc;
  for (const Dof d : {Dof::v, Dof::w}) {
    sc.k[static_cast<std::size_t>(d)] = k;
    sc.c[static_cast<std::size_t>(d)] = c;
  }
  model.elements.emplace_back(SpringDamper(0, std::nullopt, sc), "support");
  FixedDofs fixed{.node = 0, .dofs = {}};
  for (const Dof d : {Dof::u, Dof::rx, Dof::ry, Dof::rz}) fixed.dofs[static_cast<std::size_t>(d)] = true;
  model.fixed.push_back(fixed);
  model.forces.emplace_back(Unbalance{.node = 0, .mass = mu, .radius = e, .phase = 0.0, .lever = 0.0}, "u");
  model.drive = drive;
  return model;
}

Drive dc_motor(Real stall, Real no_load, Real inertia) {
  Drive d;
  d.motor.kind = MotorLaw::Kind::dc;
  d.motor.stall_torque = stall;
  d.motor.no_load_speed = no_load;
  d.inertia = inertia;
  return d;
}

// The unbalance's mean drag cΩr² at the steady speed Ω.
Real drag(Real w) {
  const Real f = mu * e * w * w;
  return c * w * f * f / ((k - M * w * w) * (k - M * w * w) + c * c * w * w);
}

// The roots of T(Ω) = drag(Ω) on (0, Ω₀), by scanning and bisection.
std::vector<Real> balance_roots(const Drive& d) {
  const auto g = [&](Real w) { return d.motor.torque(w) - drag(w); };
  std::vector<Real> roots;
  const Real top = d.motor.no_load_speed;
  Real lo = 1.0;
  for (Real hi = 1.0 + 1e-3 * top; hi < top; hi += 1e-3 * top) {
    if ((g(lo) > 0) != (g(hi) > 0)) {
      Real a = lo, b = hi;
      for (int it = 0; it < 80; ++it) ((g(0.5 * (a + b)) > 0) == (g(a) > 0) ? a : b) = 0.5 * (a + b);
      roots.push_back(0.5 * (a + b));
    }
    lo = hi;
  }
  return roots;
}

TransientOptions driven_run(Real duration) {
  TransientOptions options;
  options.profile = SpeedProfile::constant(0.0);  // the first speed: at rest
  options.driven = true;
  options.duration = duration;
  options.integrator = "trapezoidal";
  options.settings.dt = 2e-5;
  options.output_interval = 1e-3;
  options.probes = {0};
  return options;
}

TEST(DrivenRunup, WeakMotorIsCapturedBelowTheCriticalSpeed) {
  const Drive weak = dc_motor(40.0, 1.5 * w_n, 0.05);
  const std::vector<Real> roots = balance_roots(weak);
  ASSERT_EQ(roots.size(), 3U);  // captured (stable), unstable, beyond the resonance
  ASSERT_LT(roots[0], w_n);
  const TransientResult r = run_transient(jeffcott_on_drive(weak), driven_run(3.0));
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  // The last 0.2 s: the speed has settled on the lowest root, and the orbit is the
  // steady whirl there.
  Real worst_speed = 0.0, worst_radius = 0.0;
  const Real f = mu * e * roots[0] * roots[0];
  const Real radius = f / std::hypot(k - M * roots[0] * roots[0], c * roots[0]);
  for (const TransientSample& s : r.samples)
    if (s.t >= 2.8) {
      worst_speed = std::max(worst_speed, std::abs(s.speed / roots[0] - 1));
      worst_radius = std::max(worst_radius, std::abs(s.magnitude[0] / radius - 1));
    }
  EXPECT_LT(worst_speed, 1e-4) << "captured at " << roots[0] << " rad/s (critical " << w_n << ")";
  EXPECT_LT(worst_radius, 1e-3);
  EXPECT_LT(r.samples.back().speed, 0.99 * w_n);
}

TEST(DrivenRunup, StrongMotorPassesTheResonance) {
  const Drive strong = dc_motor(400.0, 1.5 * w_n, 0.05);
  const std::vector<Real> roots = balance_roots(strong);
  ASSERT_EQ(roots.size(), 1U);  // the only balance is beyond the resonance
  ASSERT_GT(roots[0], w_n);
  const TransientResult r = run_transient(jeffcott_on_drive(strong), driven_run(1.5));
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  EXPECT_NEAR(r.samples.back().speed / roots[0], 1.0, 1e-4);
}

TEST(DrivenRunup, InfiniteInertiaIsThePrescribedRamp) {
  // T = J·α with α = 2000 rad/s² held by a table law: as J grows, the speed follows
  // Ω(t) = αt and the orbit that of the prescribed ramp.
  constexpr Real alpha = 2000.0, duration = 0.5;
  TransientOptions ramp = driven_run(duration);
  ramp.driven = false;
  ramp.profile = SpeedProfile::ramp(0.0, alpha * duration, duration);
  const TransientResult prescribed = run_transient(jeffcott_on_drive({}), ramp);
  ASSERT_TRUE(prescribed.info.converged()) << prescribed.info.message;
  std::vector<Real> speed_error, orbit_error;
  for (const Real J : {1e2, 1e4}) {
    Drive d;
    d.motor.kind = MotorLaw::Kind::table;
    d.motor.table = {{0.0, J * alpha}, {1e4, J * alpha}};
    d.inertia = J - 0.02 - mu * e * e;  // the rotor's polar inertia and m_u e² make up J
    const TransientResult r = run_transient(jeffcott_on_drive(d), driven_run(duration));
    ASSERT_TRUE(r.info.converged()) << r.info.message;
    ASSERT_EQ(r.samples.size(), prescribed.samples.size());
    Real ds = 0.0, dx = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      ds = std::max(ds, std::abs(r.samples[i].speed - prescribed.samples[i].speed));
      dx = std::max(dx, std::abs(r.samples[i].probes[0][1] - prescribed.samples[i].probes[0][1]));
      peak = std::max(peak, prescribed.samples[i].magnitude[0]);
    }
    speed_error.push_back(ds / (alpha * duration));
    orbit_error.push_back(dx / peak);
  }
  // 1/J: a hundredfold inertia, a hundredth of the deviation (within 2 %).
  EXPECT_NEAR(speed_error[0] / speed_error[1], 100.0, 2.0);  // observed 100.04
  EXPECT_NEAR(orbit_error[0] / orbit_error[1], 100.0, 2.0);  // observed 100.02
  EXPECT_LT(orbit_error[1], 1e-3);
  EXPECT_GT(speed_error[0], 1e-6);  // the reaction torque is felt at the smaller inertia
}

TEST(DrivenRunup, JournalBearingDragIsPetroffPlusThePressureShare) {
  // Friswell et al. Example 5.5.1 at 1500 rpm: at the centre the torque is Petroff's
  // 2πμR³LΩ/c; at the equilibrium under W = 525 N it is the Couette term over
  // √(1 − ε²) plus ½εcW sin φ (Hamrock et al. 2004), φ the closed-form attitude angle:
  // the vector form ½(e × F) has the sign that resists the rotation.
  FluidFilmBearing b;
  b.geometry = {.diameter = 0.1, .length = 0.03, .clearance = 1e-4, .viscosity = 0.1};
  const Real w = 1500 * pi / 30, W = 525.0;
  const Real couette = 2 * pi * 0.1 * std::pow(0.05, 3) * 0.03 * w / 1e-4;
  EXPECT_NEAR(b.drag_torque({0, w, 0, 0}, Vector::Zero(2), Vector::Zero(2)), couette, 1e-12 * couette);
  // Load along −y on the journal (the film pushes +y): the journal sits at ε below
  // the centre, turned by φ towards the rotation (+y → +z), i.e. towards −z.
  const Real eps = film_eccentricity(b.geometry, FilmTheory::short_bearing, w, W);
  const Real phi = film_attitude_angle(FilmTheory::short_bearing, eps);
  Vector x(2);
  x << -eps * 1e-4 * std::cos(phi), -eps * 1e-4 * std::sin(phi);
  const NonlinearForceValue f = b.force({0, w, 0, 0}, x, Vector::Zero(2));
  ASSERT_NEAR(f.f(0), W, 1e-6 * W);  // it is the equilibrium
  ASSERT_NEAR(f.f(1), 0.0, 1e-6 * W);
  const Real expected = couette / std::sqrt(1 - eps * eps) + 0.5 * eps * 1e-4 * W * std::sin(phi);
  EXPECT_NEAR(b.drag_torque({0, w, 0, 0}, x, Vector::Zero(2)), expected, 1e-6 * expected);
}

}  // namespace
}  // namespace feran::test_driven_runup

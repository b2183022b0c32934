// Steady-state response checks that do not need a closed-form rotor.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/static/static_analysis.hpp>

#include "test_models.hpp"

namespace feran::test_harmonic_response {
namespace {

const Complex I(0, 1);

// Far below every resonance the unbalance response is the static deflection under the
// equivalent static force m·r·Ω² (pointing along +y at phase 0; along +z a quarter
// turn later, so W = −i·V). Friswell 5.9.1 with the unbalance on the second disk and
// an axial lever; at Ω = 1e-3·ω₁ the dynamic correction is (Ω/ω₁)² = 1e-6.
TEST(HarmonicResponse, QuasiStaticLimitIsTheStaticDeflection) {
  Model m = test::friswell_5_9_1();
  const Real mu = 1e-3, e = 0.1, lever = 0.03;
  m.forces.emplace_back(Unbalance{4, mu, e, 0.0, lever}, "u");
  const Real speed = 1e-3 * hz_to_rad(13.79);
  HarmonicOptions opt;
  opt.speeds = {speed};
  opt.probes = {1, 2, 4, 6};
  const HarmonicResult dyn = run_harmonic_response(m, opt);

  Model s = m;
  std::erase_if(s.forces, [](const Force& f) { return f.kind() == "unbalance"; });
  StaticLoad load;
  load.node = 4;
  const Real F = mu * e * speed * speed;
  load.load[static_cast<std::size_t>(Dof::v)] = F;
  load.load[static_cast<std::size_t>(Dof::rz)] = lever * F;  // moment of F_y about z
  s.forces.emplace_back(load);
  const StaticResult st = run_static(s, {});
  for (std::size_t p = 0; p < opt.probes.size(); ++p) {
    const Index node = opt.probes[p];
    const Real vs = st.q(global_dof(node, Dof::v));
    const NodeAmplitudes& q = dyn.probes[p].q[0];
    // 1e-5: the (Ω/ω₁)² = 1e-6 dynamic correction, amplified by mode mixing.
    EXPECT_NEAR(q[static_cast<std::size_t>(Dof::v)].real(), vs, 1e-5 * std::abs(vs));
    EXPECT_NEAR(std::abs(q[static_cast<std::size_t>(Dof::w)] + I * vs), 0.0, 1e-5 * std::abs(vs));
    EXPECT_NEAR(dyn.probes[p].orbit[0].major, std::abs(vs), 1e-5 * std::abs(vs));
  }
}

// A point mass on a bearing with cross-coupled stiffness and unequal direct terms:
// the synchronous orbit is an ellipse. Reference: the 2×2 complex system solved by
// hand and the orbit's axes found by sampling one period (20 000 points: the
// sampled maximum is within 1e-8 relative of the true one).
TEST(HarmonicResponse, CrossCoupledBearingGivesTheIndependentEllipse) {
  const Real mass = 4.0, kyy = 2e6, kzz = 3e6, kyz = 4e5, kzy = -6e5, cyy = 300, czz = 500;
  const Real mu = 2e-3, e = 0.05, phase = 0.4;
  Model m;
  const Index n = test::add_node(m, 0.0);
  test::add_body(m, n, mass, 1e-3, 1e-3);
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::v)] = kyy;
  c.k[static_cast<std::size_t>(Dof::w)] = kzz;
  c.kyz = kyz;
  c.kzy = kzy;
  c.c[static_cast<std::size_t>(Dof::v)] = cyy;
  c.c[static_cast<std::size_t>(Dof::w)] = czz;
  m.elements.emplace_back(SpringDamper(n, std::nullopt, c));
  test::fix(m, n, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  m.forces.emplace_back(Unbalance{n, mu, e, phase, 0.0}, "u");
  for (Real speed : {300.0, 700.0, 900.0, 1500.0}) {
    HarmonicOptions opt;
    opt.speeds = {speed};
    opt.probes = {n};
    const HarmonicResult r = run_harmonic_response(m, opt);
    const Complex F = mu * e * speed * speed * std::polar(1.0, phase);
    const Complex a11(kyy - mass * speed * speed, speed * cyy), a12(kyz), a21(kzy),
        a22(kzz - mass * speed * speed, speed * czz);
    const Complex det = a11 * a22 - a12 * a21;
    const Complex V = (F * a22 - a12 * (-I * F)) / det, W = (a11 * (-I * F) - a21 * F) / det;
    Real rmax = 0, rmin = 1e300, angle = 0;
    for (int k = 0; k < 20000; ++k) {
      const Real t = 2 * pi * k / 20000;
      const Real y = (V * std::polar(1.0, t)).real(), z = (W * std::polar(1.0, t)).real();
      const Real rad = std::hypot(y, z);
      if (rad > rmax) rmax = rad, angle = std::atan2(z, y);
      rmin = std::min(rmin, rad);
    }
    if (angle > pi / 2) angle -= pi;
    if (angle <= -pi / 2) angle += pi;
    const Orbit& o = r.probes[0].orbit[0];
    EXPECT_NEAR(o.major, rmax, 1e-7 * rmax) << speed;
    EXPECT_NEAR(o.minor, rmin, 1e-6 * rmax) << speed;  // the minimum is flat: sampling error ~1e-7
    EXPECT_NEAR(o.inclination, angle, 2 * pi / 20000) << speed;
    EXPECT_GT(o.major - o.minor, 0.05 * o.major) << "the orbit should be clearly elliptic";
  }
}

// A bearing whose stiffness steps at 50 Hz: the response at each speed equals that
// of a model with the constant coefficient valid at that speed.
TEST(HarmonicResponse, SpeedDependentBearingUsesTheCoefficientAtEachSpeed) {
  auto model = [](SpeedCoefficient k) {
    Model m = test::friswell_5_9_1();
    m.elements.erase(m.elements.end() - 2, m.elements.end());  // the two 1 MN/m bearings
    SpringDamperCoefficients c;
    c.k[static_cast<std::size_t>(Dof::v)] = k;
    c.k[static_cast<std::size_t>(Dof::w)] = k;
    c.c[static_cast<std::size_t>(Dof::v)] = 100.0;
    c.c[static_cast<std::size_t>(Dof::w)] = 100.0;
    m.elements.emplace_back(SpringDamper(0, std::nullopt, c));
    m.elements.emplace_back(SpringDamper(6, std::nullopt, c));
    m.forces.emplace_back(Unbalance{2, 1e-3, 0.1, 0.0, 0.0}, "u");
    return m;
  };
  const Model stepped = model(SpeedCoefficient(SpeedCoefficient::Step{1e6, 3e6, hz_to_rad(50)}));
  for (auto [hz, k] : {std::pair{20.0, 1e6}, std::pair{49.0, 1e6}, std::pair{51.0, 3e6}, std::pair{80.0, 3e6}}) {
    HarmonicOptions opt;
    opt.speeds = {hz_to_rad(hz)};
    opt.probes = {2, 6};
    const HarmonicResult a = run_harmonic_response(stepped, opt), b = run_harmonic_response(model(k), opt);
    for (std::size_t p = 0; p < 2; ++p)
      for (std::size_t d = 0; d < dofs_per_node; ++d)  // same matrices, same solver: round-off
        EXPECT_NEAR(std::abs(a.probes[p].q[0][d] - b.probes[p].q[0][d]), 0.0,
                    1e-12 * b.probes[p].orbit[0].major + 1e-18)
            << hz << " Hz";
    EXPECT_NEAR(a.springs[0].peak_lateral[0], b.springs[0].peak_lateral[0], 1e-12 * b.springs[0].peak_lateral[0]);
  }
}

// Frequency response of a non-rotating mass–spring–damper to a fixed force along y:
// V = F/(k − mω² + iωc) at every frequency; the orthogonal direction stays at rest.
TEST(HarmonicResponse, FrequencySweepGivesTheReceptance) {
  const Real mass = 2.0, k = 8e4, c = 40.0;
  Model m;
  const Index n = test::add_node(m, 0.0, false);
  test::add_body(m, n, mass, 1e-3, 1e-3, 0.0, false);
  test::add_isotropic_bearing(m, n, k, c);
  test::fix(m, n, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  HarmonicForce f;
  f.node = n;
  f.direction = Dof::v;
  f.amplitude = 3.0;
  f.phase = 0.2;
  HarmonicOptions opt;
  opt.speed = 0.0;
  for (int i = 1; i <= 50; ++i) opt.frequencies.push_back(10.0 * i);
  opt.extra_forces = {f};
  opt.probes = {n};
  const HarmonicResult r = run_harmonic_response(m, opt);
  ASSERT_TRUE(r.frequency_sweep);
  for (std::size_t i = 0; i < opt.frequencies.size(); ++i) {
    const Real w = opt.frequencies[i];
    const Complex V = 3.0 * std::polar(1.0, 0.2) / Complex(k - mass * w * w, w * c);
    EXPECT_NEAR(std::abs(r.probes[0].q[i][static_cast<std::size_t>(Dof::v)] - V), 0.0, 1e-10 * std::abs(V));
    EXPECT_EQ(r.probes[0].q[i][static_cast<std::size_t>(Dof::w)], Complex(0.0));
  }
}

// Newton's second law for a whole overhung rotor: the force on its clamp equals the
// unbalance force plus the inertia forces ω²·Σ(M q)_y of all elements minus the force
// of the tip damper, computed here from the element mass matrices and the response
// at every node. The section resultant at the root (the +x face there belongs to the
// support side) must be the same force. Round-off: 1e-9 relative.
TEST(HarmonicResponse, ClampForceBalancesTheRotorInertia) {
  Model m;
  test::add_shaft(m, 0.0, 0.3, 6, 0.02, test::steel());
  test::add_body(m, 6, 3.0, 0.01, 0.018, 0.01);
  test::fix_all(m, 0);
  const Real c = 50.0;
  test::add_isotropic_bearing(m, 6, 0.0, c);
  const Real mu = 1e-3, e = 0.05;
  m.forces.emplace_back(Unbalance{6, mu, e, 0.0, 0.0}, "u");
  HarmonicOptions opt;
  opt.speeds = {120.0, 400.0};
  opt.stations = StationOutput::all;
  for (Index node = 0; node < m.n_nodes(); ++node) opt.probes.push_back(node);
  const HarmonicResult r = run_harmonic_response(m, opt);
  ASSERT_EQ(r.reactions.size(), 1u);
  for (std::size_t k = 0; k < opt.speeds.size(); ++k) {
    const Real w = opt.speeds[k];
    Complex inertia_y = 0.0;
    for (const Element& el : m.elements) {
      const LocalMatrices lm = el.local_matrices({w});
      if (lm.M.size() == 0) continue;
      ComplexVector q(static_cast<Index>(lm.dofs.size()));
      for (std::size_t i = 0; i < lm.dofs.size(); ++i)
        q(static_cast<Index>(i)) = r.probes[static_cast<std::size_t>(lm.dofs[i] / dofs_per_node)]
                                       .q[k][static_cast<std::size_t>(lm.dofs[i] % dofs_per_node)];
      const ComplexVector mq = lm.M.cast<Complex>() * q;
      for (std::size_t i = 0; i < lm.dofs.size(); ++i)
        if (lm.dofs[i] % dofs_per_node == static_cast<Index>(Dof::v)) inertia_y += mq(static_cast<Index>(i));
    }
    const Complex v_tip = r.probes[6].q[k][static_cast<std::size_t>(Dof::v)];
    const Complex expected = mu * e * w * w + w * w * inertia_y - Complex(0, w * c) * v_tip;
    const Complex R = r.reactions[0].force[k][static_cast<std::size_t>(Dof::v)];
    EXPECT_NEAR(std::abs(R - expected), 0.0, 1e-9 * std::abs(expected)) << w;
    EXPECT_NEAR(std::abs(r.stations[0].forces[k].Vy - expected), 0.0, 1e-9 * std::abs(expected)) << w;
  }
}

}  // namespace
}  // namespace feran::test_harmonic_response

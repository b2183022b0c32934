// Unit tests of the plain annular seal (docs/theory/annular_seal.md), each against
// something the closed forms were not derived from:
// - Black and Jenssen's published coefficients (Black & Jenssen 1970; Childs 1993,
//   ch. 4): with a friction factor that depends on neither the Reynolds number nor the
//   swirl (m = 0) and at rest, where the two linearisations coincide, K, C and M equal
//   theirs to rounding (1e-12);
// - the first-order bulk-flow equations integrated numerically (RK4 over the seal's
//   length, the two-point boundary problem solved by superposition) at whirl
//   frequencies about half the speed: the impedance's value, slope and curvature by
//   central differences equal K − ik, C − ic and −M to 1e-6 (the differences' h² error
//   at h = 1e-3 and RK4's error at 400 steps are below 1e-8 of the terms);
// - the leakage equation ΔP = (1 + ξ + 2σ)ρV²/2, solved by bisection, to 1e-12;
// - invariants of half-swirl flow: k = Cω/2 and c = Mω exactly, the stiffness falling
//   by Mω²/4 from its value at rest;
// - the element's matrices are the coefficients in the force law's places.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>

#include <feran/core/error.hpp>
#include <feran/elements/annular_seal.hpp>

namespace feran::test_annular_seal {
namespace {

using cd = std::complex<Real>;

// A pump's wear ring: 2R = 100 mm, L = 25 mm, C = 0.2 mm, water, ΔP = 1 MPa.
AnnularSealGeometry wear_ring() {
  return {.radius = 0.05,
          .length = 0.025,
          .clearance = 2e-4,
          .pressure_drop = 1e6,
          .density = 1000.0,
          .viscosity = 1e-3,
          .entrance_loss = 0.1,
          .friction_n = 0.079,
          .friction_m = -0.25};
}

Real rel(Real a, Real b) { return std::abs(a - b) / std::abs(b); }

TEST(AnnularSeal, LeakageSatisfiesThePressureDrop) {
  for (const Real speed : {0.0, 300.0, 1500.0}) {
    const AnnularSealGeometry g = wear_ring();
    const AnnularSealCoefficients s = annular_seal_coefficients(g, speed);
    const Real V = s.axial_velocity;
    EXPECT_LT(rel((1 + g.entrance_loss + 2 * s.sigma) * g.density * V * V / 2, g.pressure_drop), 1e-12);
    // λ is Blasius' law at the resultant speed of the half-swirl flow.
    const Real swirl = g.radius * speed / (2 * V);
    const Real f = 0.079 * std::pow(2 * g.clearance * V * g.density / g.viscosity, -0.25);
    EXPECT_LT(rel(s.friction, f * std::pow(1 + swirl * swirl, 0.375)), 1e-12);
    EXPECT_LT(rel(s.leakage, 2 * pi * g.radius * g.clearance * V), 1e-15);
    EXPECT_GT(s.reynolds, 4000.0);  // turbulent: the model's premise
  }
}

// Black and Jenssen's coefficients as published, for a friction factor independent of
// the Reynolds number (m = 0): with E = (1 + ξ)/(2(1 + ξ + 2σ)),
//   μ0 = 2σ²E/(1 + ξ + 2σ), μ1 = 2σ²/(1 + ξ + 2σ)·(E/σ + 1/6 + E),
//   μ2 = σ(1/6 + E)/(1 + ξ + 2σ), μ3 = πRΔP/λ, T = L/V;
//   K = μ3(μ0 − μ2ω²T²/4), k = μ3μ1ωT/2, C = μ3μ1T, c = μ3μ2ωT², M = μ3μ2T².
TEST(AnnularSeal, EqualsBlackAndJenssenAtRest) {
  for (const Real xi : {0.0, 0.1, 0.5}) {
    for (const Real dp : {2e5, 1e6, 5e6}) {
      AnnularSealGeometry g = wear_ring();
      g.entrance_loss = xi;
      g.pressure_drop = dp;
      g.friction_m = 0.0;
      g.friction_n = 0.008;
      const AnnularSealCoefficients s = annular_seal_coefficients(g, 0.0);
      const Real sigma = s.sigma, D = 1 + xi + 2 * sigma, E = (1 + xi) / (2 * D);
      const Real mu0 = 2 * sigma * sigma * E / D;
      const Real mu1 = 2 * sigma * sigma / D * (E / sigma + 1.0 / 6 + E);
      const Real mu2 = sigma * (1.0 / 6 + E) / D;
      const Real mu3 = pi * g.radius * g.pressure_drop / s.friction, T = g.length / s.axial_velocity;
      EXPECT_LT(rel(s.K, mu3 * mu0), 1e-12) << xi << " " << dp;
      EXPECT_LT(rel(s.C, mu3 * mu1 * T), 1e-12);
      EXPECT_LT(rel(s.M, mu3 * mu2 * T * T), 1e-12);
      EXPECT_EQ(s.k, 0.0);
      EXPECT_EQ(s.c, 0.0);
    }
  }
}

TEST(AnnularSeal, HalfSwirlInvariants) {
  const AnnularSealGeometry g = wear_ring();
  for (const Real speed : {100.0, 600.0, -600.0, 2000.0}) {
    const AnnularSealCoefficients s = annular_seal_coefficients(g, speed);
    EXPECT_LT(rel(s.k, s.C * speed / 2), 1e-12);  // whirl frequency ratio 1/2
    EXPECT_LT(rel(s.c, s.M * speed), 1e-12);
    EXPECT_GT(s.C, 0.0);
    EXPECT_GT(s.M, 0.0);
  }
  // Reversed rotation reverses the cross-coupling only.
  const AnnularSealCoefficients f = annular_seal_coefficients(g, 700.0), b = annular_seal_coefficients(g, -700.0);
  EXPECT_EQ(f.K, b.K);
  EXPECT_EQ(f.k, -b.k);
  EXPECT_EQ(f.C, b.C);
  EXPECT_EQ(f.c, -b.c);
  EXPECT_EQ(f.M, b.M);
}

// The seal's impedance H(Ω), f = −H·(y + iz) for circular whirl (y + iz) = e^{iΩt},
// from the first-order bulk-flow equations in ζ = z/L (docs/theory/annular_seal.md):
//   v' = i s(ζ),  P' = −σ(1 − m) − σa·v − i s·(v − v₀) − i s,
//   P(0) = −(1 + ξ)v₀,  P(1) = 0,   H = μ3·2σ/(1 + ξ + 2σ)·∫P dζ,
// s = (Ω − ω/2)T the whirl relative to the fluid's swirl, integrated by RK4 with v₀
// found by superposing the solutions from v₀ = 0 and v₀ = 1.
cd impedance(const AnnularSealGeometry& g, Real speed, Real whirl) {
  const AnnularSealCoefficients s0 = annular_seal_coefficients(g, speed);
  const Real sigma = s0.sigma, xi = g.entrance_loss, m = g.friction_m, T = g.length / s0.axial_velocity;
  const Real b = s0.axial_velocity / (g.radius * std::abs(speed));
  const Real beta = speed != 0 ? 1 / (1 + 4 * b * b) : 0.0;
  const Real a = 1 + (1 + m) * (1 - beta);
  const cd s((whirl - speed / 2) * T, 0.0);
  const cd i(0.0, 1.0);
  // State (v, P, ∫P) from v(0) = v0, P(0) = −(1 + ξ)v0.
  auto integrate = [&](cd v0) {
    std::array<cd, 3> y = {v0, -(1 + xi) * v0, 0.0};
    auto rhs = [&](const std::array<cd, 3>& u) {
      return std::array<cd, 3>{i * s, -sigma * (1 - m) - sigma * a * u[0] - i * s * (u[0] - v0) - i * s, u[1]};
    };
    const int n = 400;
    const Real h = 1.0 / n;
    for (int k = 0; k < n; ++k) {
      auto add = [](const std::array<cd, 3>& u, const std::array<cd, 3>& d, Real c) {
        return std::array<cd, 3>{u[0] + c * d[0], u[1] + c * d[1], u[2] + c * d[2]};
      };
      const auto k1 = rhs(y), k2 = rhs(add(y, k1, h / 2)), k3 = rhs(add(y, k2, h / 2)), k4 = rhs(add(y, k3, h));
      for (std::size_t j = 0; j < 3; ++j) y[j] += h / 6 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    return y;
  };
  // P(1) is affine in v0 (the equations are linear, the inhomogeneity fixed).
  const std::array<cd, 3> y0 = integrate(0.0), y1 = integrate(1.0);
  const cd v0 = -y0[1] / (y1[1] - y0[1]);
  const std::array<cd, 3> y = integrate(v0);
  const Real mu3 = pi * g.radius * g.pressure_drop / s0.friction;
  return mu3 * 2 * sigma / (1 + xi + 2 * sigma) * y[2];
}

TEST(AnnularSeal, CoefficientsAreTheTaylorTermsOfTheBulkFlowImpedance) {
  for (const Real speed : {0.0, 400.0, 1500.0}) {
    for (const Real xi : {0.0, 0.3}) {
      AnnularSealGeometry g = wear_ring();
      g.entrance_loss = xi;
      const AnnularSealCoefficients c = annular_seal_coefficients(g, speed);
      const Real T = g.length / c.axial_velocity, h = 1e-3 / T;  // a step of 1e-3 in (Ω − ω/2)T
      const Real w0 = speed / 2;
      const cd hm = impedance(g, speed, w0 - h), h0 = impedance(g, speed, w0), hp = impedance(g, speed, w0 + h);
      const cd slope = (hp - hm) / (2 * h), curvature = (hp - 2.0 * h0 + hm) / (h * h);
      // H(Ω) = (K − ik) + iΩ(C − ic) − Ω²M at Ω = ω/2 and its derivatives there.
      const cd K(c.K, -c.k), Cc(c.C, -c.c), I(0.0, 1.0);
      const cd value = K + I * w0 * Cc - w0 * w0 * c.M;
      const cd d1 = I * Cc - 2 * w0 * c.M;
      const Real scale = std::abs(K) + std::abs(w0 * Cc) + std::abs(c.M * w0 * w0) + std::abs(c.C / T);
      EXPECT_LT(std::abs(h0 - value) / scale, 1e-9) << speed << " " << xi;
      EXPECT_LT(std::abs(slope - d1) / std::abs(d1), 1e-6) << speed << " " << xi;
      EXPECT_LT(std::abs(curvature + 2 * c.M) / (2 * c.M), 1e-5) << speed << " " << xi;
    }
  }
}

TEST(AnnularSeal, ElementMatricesHoldTheCoefficientsInTheForceLaw) {
  const AnnularSealGeometry g = wear_ring();
  const Real speed = 500.0;
  const AnnularSealCoefficients s = annular_seal_coefficients(g, speed);
  const AnnularSeal to_ground(3, std::nullopt, g);
  const LocalMatrices lm = to_ground.local_matrices({speed});
  ASSERT_EQ(lm.dofs, (std::vector<Index>{6 * 3 + 1, 6 * 3 + 2}));
  // f_y = −(K y + k z + …), f_z = −(K z − k y + …).
  EXPECT_EQ(lm.K(0, 0), s.K);
  EXPECT_EQ(lm.K(0, 1), s.k);
  EXPECT_EQ(lm.K(1, 0), -s.k);
  EXPECT_EQ(lm.C(0, 1), s.c);
  EXPECT_EQ(lm.C(1, 1), s.C);
  EXPECT_EQ(lm.M(0, 0), s.M);
  EXPECT_EQ(lm.M(0, 1), 0.0);
  const AnnularSeal between(3, 7, g);
  const LocalMatrices two = between.local_matrices({speed});
  ASSERT_EQ(two.dofs.size(), 4u);
  EXPECT_EQ(two.K(0, 3), -s.k);  // node a's y from node b's z
  EXPECT_EQ(two.M(2, 0), -s.M);
  const Transmission t = between.transmission(speed);
  EXPECT_EQ(t.K(1, 2), s.k);
  EXPECT_EQ(t.C(2, 1), -s.c);
  EXPECT_EQ(t.M(2, 2), s.M);
  EXPECT_EQ(t.M(0, 0), 0.0);
}

TEST(AnnularSeal, RefusesWhatIsNotASeal) {
  AnnularSealGeometry g = wear_ring();
  g.friction_m = -1.0;
  EXPECT_THROW(annular_seal_coefficients(g, 10.0), Error);
  g = wear_ring();
  g.pressure_drop = 0.0;
  EXPECT_THROW(AnnularSeal(0, std::nullopt, g), Error);
}

}  // namespace
}  // namespace feran::test_annular_seal

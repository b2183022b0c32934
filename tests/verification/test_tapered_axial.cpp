// Tapered (conical) shaft elements and the geometric stiffness of an axial force.
//
// Tapered: a truncated-cone cantilever (Euler–Bernoulli, no rotary inertia) against
// the frequencies of (EI w'')'' = ρAω²w found independently, by shooting: fourth-
// order Runge–Kutta on (w, w', M, V) from the clamped end and bisection on the
// determinant of the free-end moment and shear. The shooting code reproduces the
// uniform cantilever's 1.8751² and Kirchhoff's cone (tip → 0) coefficient 8.719 of
// ω L² √(ρA₀/EI₀) (Conway, Becker & Dubil 1964, J. Appl. Mech. 31:329–331). The
// elements' frequencies converge to the shooting ones as h⁴, like uniform
// cubic-Hermite elements. With shear and rotary inertia, tapered meshes converge as h²
// to the limit of a fine mesh of uniform steps (the section of each step at its
// mid-length, an O(h²) approximation of the same continuum).
//
// Axial force: a simply supported Euler–Bernoulli beam under tension P has exactly
// ω_n² = (EI k⁴ + P k²)/(ρA), k = nπ/L (Bokaian 1988, J. Sound Vib. 126:49–65; 1990, 142:481–498); under
// compression the first frequency falls to zero at Euler's load π²EI/L².
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

#include <feran/analyses/modal/modal.hpp>
#include <feran/io/model_reader.hpp>

#include "test_models.hpp"

namespace feran::test_tapered_axial {
namespace {

constexpr Real E = 2.1e11, nu = 0.3, rho = 7800, L = 1.0;
const Material steel{"steel", E, E / (2 * (1 + nu)), rho};

// Frequencies [rad/s] of the lowest @p count roots of the cantilever clamped at x = 0,
// free at L, with diameter d(x) linear from d0 to d1 (solid), Euler–Bernoulli.
std::vector<Real> shooting_rad_s(Real d0, Real d1, int count) {
  const auto diameter = [&](Real x) { return d0 + (d1 - d0) * x / L; };
  // Free-end determinant at ω: two solutions from (w, w', M, V) = (0, 0, 1, 0), (0, 0, 0, 1).
  const auto determinant = [&](Real w) {
    const int steps = 4000;
    const Real h = L / steps;
    using State = std::array<Real, 4>;
    const auto f = [&](Real x, const State& y) {
      const CircularSection s{diameter(x), 0.0};
      return State{y[1], y[2] / (E * s.second_moment()), y[3], rho * s.area() * w * w * y[0]};
    };
    std::array<State, 2> y{State{0, 0, 1, 0}, State{0, 0, 0, 1}};
    for (int i = 0; i < steps; ++i) {
      const Real x = i * h;
      for (State& s : y) {
        const State k1 = f(x, s);
        State t;
        for (int j = 0; j < 4; ++j) t[j] = s[j] + h / 2 * k1[j];
        const State k2 = f(x + h / 2, t);
        for (int j = 0; j < 4; ++j) t[j] = s[j] + h / 2 * k2[j];
        const State k3 = f(x + h / 2, t);
        for (int j = 0; j < 4; ++j) t[j] = s[j] + h * k3[j];
        const State k4 = f(x + h, t);
        for (int j = 0; j < 4; ++j) s[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
      }
    }
    return y[0][2] * y[1][3] - y[0][3] * y[1][2];
  };
  std::vector<Real> roots;
  Real lo = 1.0, f_lo = determinant(lo);
  for (Real hi = 1.02; static_cast<int>(roots.size()) < count; hi *= 1.02) {
    const Real f_hi = determinant(hi);
    if ((f_lo < 0) != (f_hi < 0)) {
      Real a = lo, b = hi, fa = f_lo;
      for (int it = 0; it < 60; ++it) {
        const Real m = 0.5 * (a + b), fm = determinant(m);
        if ((fm < 0) == (fa < 0)) {
          a = m;
          fa = fm;
        } else {
          b = m;
        }
      }
      roots.push_back(0.5 * (a + b));
    }
    lo = hi;
    f_lo = f_hi;
  }
  return roots;
}

// The lowest @p count distinct lateral frequencies [rad/s] of @p model at rest.
std::vector<Real> lateral_rad_s(const Model& model, int count) {
  std::vector<Real> out;
  for (const Mode& mode : run_modal(model, 0.0).modes) {
    if (mode.type != ModeType::lateral) continue;
    const Real w = hz_to_rad(mode.frequency_hz);
    if (out.empty() || w > out.back() * (1 + 1e-9)) out.push_back(w);
    if (static_cast<int>(out.size()) == count) break;
  }
  return out;
}

// A cantilever of n_el tapered elements (diameters d0 → d1), clamped at x = 0.
Model tapered_cantilever(int n_el, Real d0, Real d1, const BeamOptions& opt) {
  Model m;
  Index prev = test::add_node(m, 0.0);
  const Real le = L / n_el;
  const auto d = [&](int i) { return d0 + (d1 - d0) * i / n_el; };
  for (int e = 0; e < n_el; ++e) {
    const Index next = test::add_node(m, le * (e + 1));
    m.elements.emplace_back(
        TimoshenkoBeam(prev, next, le, CircularSection{d(e), 0.0}, CircularSection{d(e + 1), 0.0}, steel, opt));
    prev = next;
  }
  test::fix_all(m, 0);
  return m;
}

BeamOptions euler_bernoulli() {
  BeamOptions opt;
  opt.shear_deformation = false;
  opt.rotary_inertia = false;
  return opt;
}

TEST(TaperedShaft, ShootingReproducesUniformAndKirchhoffCone) {
  // The independent reference first: uniform cantilever β₁L = 1.875104, β₂L = 4.694091.
  const CircularSection s{0.05, 0.0};
  const Real scale = std::sqrt(E * s.second_moment() / (rho * s.area())) / (L * L);
  const std::vector<Real> uniform = shooting_rad_s(0.05, 0.05, 2);
  EXPECT_NEAR(uniform[0] / scale, 1.875104 * 1.875104, 1e-5);
  EXPECT_NEAR(uniform[1] / scale, 4.694091 * 4.694091, 1e-4);
  // A cone: the coefficient approaches its limit linearly in the tip ratio r (8.7018 at
  // r = 1e-3, 8.7175 at 1e-4); extrapolated to r = 0 it is Kirchhoff's 8.719 (Conway et
  // al. 1964, four digits).
  const Real at_3 = shooting_rad_s(0.05, 0.05e-3, 1)[0] / scale, at_4 = shooting_rad_s(0.05, 0.05e-4, 1)[0] / scale;
  EXPECT_NEAR(at_4 + (at_4 - at_3) / 9, 8.719, 1e-4 * 8.719);
}

TEST(TaperedShaft, ConeCantileverConvergesAsHToTheFourth) {
  const Real d0 = 0.06, d1 = 0.03;
  const std::vector<Real> exact = shooting_rad_s(d0, d1, 3);
  std::vector<std::array<Real, 3>> err;
  for (int n : {4, 8, 16}) {
    const std::vector<Real> f = lateral_rad_s(tapered_cantilever(n, d0, d1, euler_bernoulli()), 3);
    ASSERT_EQ(f.size(), 3U);
    err.push_back({std::abs(f[0] / exact[0] - 1), std::abs(f[1] / exact[1] - 1), std::abs(f[2] / exact[2] - 1)});
  }
  // 16 elements: the first mode to 1e-6 (observed 2.6e-7; the shooting reference is
  // good to ~1e-10).
  EXPECT_LT(err[2][0], 1e-6);
  for (std::size_t mode = 0; mode < 3; ++mode) {
    const Real rate = std::log2(err[1][mode] / err[2][mode]);
    // Cubic Hermite elements with consistent mass: h⁴ (observed 3.9–4.0); the bounds
    // exclude h² (a uniform-step approximation) and h⁶.
    EXPECT_GT(rate, 3.6) << "mode " << mode + 1;
    EXPECT_LT(rate, 4.4) << "mode " << mode + 1;
  }
}

TEST(TaperedShaft, TimoshenkoTaperConvergesToFineUniformSteps) {
  const Real d0 = 0.12, d1 = 0.06;  // stubby: L/d from 8 to 17, shear and rotary inertia matter
  // 4000 uniform steps, each with the diameter at its middle: an O(h²) approximation of
  // the same continuum, here within ~1e-8 of it (observed: 2000 → 4000 steps moves
  // the first frequency by 1.2e-7 relative).
  Model steps;
  const int n = 4000;
  Index prev = test::add_node(steps, 0.0);
  for (int e = 0; e < n; ++e) {
    const Index next = test::add_node(steps, L * (e + 1) / n);
    const Real d = d0 + (d1 - d0) * (e + 0.5) / n;
    steps.elements.emplace_back(TimoshenkoBeam(prev, next, L / n, CircularSection{d, 0.0}, steel, {}));
    prev = next;
  }
  test::fix_all(steps, 0);
  const std::vector<Real> stepped = lateral_rad_s(steps, 3);
  std::vector<std::vector<Real>> tapered;
  for (int elements : {32, 64, 128}) tapered.push_back(lateral_rad_s(tapered_cantilever(elements, d0, d1, {}), 3));
  const std::vector<Real> eb = lateral_rad_s(tapered_cantilever(128, d0, d1, euler_bernoulli()), 3);
  for (std::size_t k = 0; k < 3; ++k) {
    const Real e32 = tapered[0][k] / stepped[k] - 1, e64 = tapered[1][k] / stepped[k] - 1,
               e128 = tapered[2][k] / stepped[k] - 1;
    // With shear the interdependent element converges as h² (as for a uniform shaft,
    // test_timoshenko_convergence.cpp): observed 1.95–1.98.
    EXPECT_NEAR(std::log2(e64 / e128), 2.0, 0.2) << "mode " << k + 1;
    EXPECT_NEAR(std::log2(e32 / e64), 2.0, 0.25) << "mode " << k + 1;
    // Richardson's extrapolation of 64 and 128 elements meets the steps' limit.
    EXPECT_NEAR((4 * tapered[2][k] - tapered[1][k]) / 3 / stepped[k], 1.0, 2e-6) << "mode " << k + 1;
    // Shear and rotary inertia lower the frequencies noticeably (not a vacuous match).
    EXPECT_LT(tapered[2][k], eb[k] * (1 - 1e-3 * static_cast<Real>(k + 1))) << "mode " << k + 1;
  }
}

// Simply supported uniform beam with an axial force P (tension positive).
std::vector<Real> axial_beam_rad_s(Real P, int n_el, int count) {
  Model m;
  BeamOptions opt = euler_bernoulli();
  opt.axial_force = P;
  test::add_shaft(m, 0.0, L, n_el, 0.05, steel, 0.0, opt);
  test::fix(m, 0, {Dof::u, Dof::v, Dof::w, Dof::rx});
  test::fix(m, n_el, {Dof::v, Dof::w});
  return lateral_rad_s(m, count);
}

TEST(AxialForce, TensionStiffensAsTheStringBeamFormula) {
  const CircularSection s{0.05, 0.0};
  const Real EI = E * s.second_moment(), rhoA = rho * s.area();
  const Real P_cr = pi * pi * EI / (L * L);
  for (Real P : {0.5 * P_cr, 3.0 * P_cr}) {
    const std::vector<Real> f = axial_beam_rad_s(P, 64, 3);
    ASSERT_EQ(f.size(), 3U);
    for (int n = 1; n <= 3; ++n) {
      const Real k = n * pi / L;
      const Real exact = std::sqrt((EI * std::pow(k, 4) + P * k * k) / rhoA);
      // 64 cubic elements: discretisation error ≤ 3e-7 for these modes (h⁴: 4.9e-6 for
      // mode 3 at 32 elements).
      EXPECT_NEAR(f[static_cast<std::size_t>(n - 1)] / exact, 1.0, 2e-6) << "P/Pcr " << P / P_cr << " mode " << n;
    }
  }
}

TEST(AxialForce, CompressionSoftensTowardsEulerBuckling) {
  const CircularSection s{0.05, 0.0};
  const Real EI = E * s.second_moment(), rhoA = rho * s.area();
  const Real P_cr = pi * pi * EI / (L * L);
  const Real w0 = std::sqrt(EI / rhoA) * pi * pi / (L * L);
  for (Real ratio : {0.5, 0.9, 0.99}) {
    const std::vector<Real> f = axial_beam_rad_s(-ratio * P_cr, 32, 1);
    ASSERT_EQ(f.size(), 1U);
    // ω₁ = ω₀√(1 − P/P_cr): at 0.99 the frequency is a tenth, and the relative error of
    // ω₁² grows as 1/(1 − P/P_cr) (the discretisation error of P_cr, ~1e-7, over 0.01).
    EXPECT_NEAR(f[0] / (w0 * std::sqrt(1 - ratio)), 1.0, 1e-6 / (1 - ratio)) << ratio;
  }
}

TEST(TaperedShaft, ModelKeysBuildTaperedElementsAndAxialForce) {
  const ModelFile file = read_model_string(R"(
[[materials]]
name = "steel"
E = 2.1e11
G = 8.0769230769e10
rho = 7800

[[shafts]]
material = "steel"
[[shafts.sections]]
length = 0.3
outer_diameter = "60 mm"
outer_diameter_end = "30 mm"
inner_diameter_end = "10 mm"
elements = 3
axial_force = "2 kN"
[[fixed]]
node = 1
)",
                                           "tapered.toml");
  const Model& model = file.model;
  ASSERT_EQ(model.elements.size(), 3U);
  const auto* second = model.elements[1].target<TimoshenkoBeam>();
  ASSERT_NE(second, nullptr);
  // Element 2 spans ξ ∈ [1/3, 2/3] of the section: outer 50 → 40 mm, bore 10/3 → 20/3 mm.
  EXPECT_NEAR(second->section().outer_diameter, 0.050, 1e-15);
  EXPECT_NEAR(second->section_b().outer_diameter, 0.040, 1e-15);
  EXPECT_NEAR(second->section().inner_diameter, 0.010 / 3, 1e-15);
  EXPECT_NEAR(second->section_b().inner_diameter, 0.020 / 3, 1e-15);
  EXPECT_EQ(second->options().axial_force, 2000.0);
  // The elements' mass is the truncated cone's, ρπL/12·(D₀² + D₀D₁ + D₁²) minus the bore's.
  Real mass = 0;
  for (const Element& e : model.elements) {
    const LocalMatrices lm = e.local_matrices({});
    mass += lm.M(0, 0) + lm.M(0, 6) + lm.M(6, 0) + lm.M(6, 6);  // axial: ∫ρA(N_a + N_b)² dx
  }
  const auto frustum = [](Real a, Real b) { return pi * 0.3 / 12 * (a * a + a * b + b * b); };
  EXPECT_NEAR(mass, rho * (frustum(0.06, 0.03) - frustum(0.0, 0.01)), 1e-12 * mass);
}

}  // namespace
}  // namespace feran::test_tapered_axial

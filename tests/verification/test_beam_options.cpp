// The model options of [options] (rotary inertia, shear coefficient, non-rotating
// proportional damping) against closed forms, on a simply supported uniform steel shaft
// built through a ModelSpec (so the options go the way a file's do).
//
// For mode n with k = nπ/L the analytic ω of a simply supported beam solves
//   EI k⁴ − ρA ω² − r·ρI (1 + s E/(κG)) k² ω² + r·s ρ² I/(κG) ω⁴ = 0,
// s = 1 with shear deformation, r = 1 with rotary inertia (r = 0, s = 0: the
// Euler–Bernoulli beam, ω = k²√(EI/ρA)). Tolerances, 32 elements: without shear
// cubic elements converge as (nh)⁴ — measured 6e-8, 1.0e-6, 5.2e-6 for modes 1–3 —
// so 1e-7·n⁴; rotary inertia changes them by 3e-3 to 2.7e-2. With shear they converge
// as h² (mode 1: ~7e-6, test_timoshenko_convergence.cpp), so mode 1 is checked to
// 2e-5, which tells Hutchinson's κ from Cowper's (3.7e-4 apart in frequency) and a
// given κ = 0.5 from both (6.7e-3).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/elements/timoshenko_beam.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/parameters.hpp>

namespace feran::test_beam_options {
namespace {

constexpr Real L = 1.0, d = 0.1, E = 2.1e11, nu = 0.3, rho = 7800;
constexpr int n_el = 32;

ModelSpec shaft() {
  ModelSpec s;
  s.materials.push_back({.name = "steel", .E = E, .G = {}, .nu = nu, .rho = rho, .loss_factor = 0.0});
  ShaftSpec shaft;
  shaft.material = "steel";
  shaft.start_node = "a";
  shaft.sections.push_back({.length = L,
                            .outer_diameter = d,
                            .inner_diameter = 0.0,
                            .outer_diameter_end = {},
                            .inner_diameter_end = {},
                            .axial_force = 0.0,
                            .material = {},
                            .elements = n_el,
                            .end_node = "b"});
  s.shafts.push_back(shaft);
  s.fixed.push_back({.node = std::string("a"), .dofs = {"u", "v", "w", "rx"}});
  s.fixed.push_back({.node = std::string("b"), .dofs = {"v", "w"}});
  return s;
}

Real analytic_hz(int n, bool shear, bool rotary, Real kappa) {
  const Real G = E / (2 * (1 + nu));
  const CircularSection sec{d, 0.0};
  const Real A = sec.area(), I = sec.second_moment();
  const Real k = n * pi / L, s = shear ? 1.0 : 0.0, r = rotary ? 1.0 : 0.0;
  const Real a = r * s * rho * rho * I / (kappa * G);
  const Real b = -(rho * A + r * rho * I * (1 + s * E / (kappa * G)) * k * k);
  const Real c = E * I * std::pow(k, 4);
  const Real w2 = a == 0 ? -c / b : (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  return rad_to_hz(std::sqrt(w2));
}

/// The lowest three distinct oscillatory bending modes.
std::vector<Mode> bending_modes(const Model& model, Real speed = 0.0) {
  std::vector<Mode> out;
  for (const Mode& mode : run_modal(model, speed).modes) {
    // (Stiffness-proportional damping overdamps the highest modes: not oscillatory.)
    if (mode.type != ModeType::lateral || !mode.oscillatory) continue;
    if (out.empty() || mode.frequency_hz > out.back().frequency_hz * (1 + 1e-6)) out.push_back(mode);
    if (out.size() == 3) break;
  }
  return out;
}

TEST(BeamOptions, WithoutRotaryInertiaTheEulerBernoulliBeam) {
  ModelSpec s = shaft();
  s.options.shear_deformation = false;
  s.options.rotary_inertia = false;
  const std::vector<Mode> modes = bending_modes(build_model(s));
  ASSERT_EQ(modes.size(), 3u);
  for (int n = 1; n <= 3; ++n) {
    const Real exact = analytic_hz(n, false, false, 1.0);
    // ω_n = (nπ/L)²·√(EI/ρA) exactly when r = s = 0.
    EXPECT_NEAR(exact, rad_to_hz(std::pow(n * pi / L, 2) * std::sqrt(E * d * d / 16.0 / rho)), 1e-9 * exact);
    EXPECT_NEAR(modes[static_cast<std::size_t>(n - 1)].frequency_hz / exact, 1.0, 1e-7 * std::pow(n, 4)) << n;
  }
  // With rotary inertia (the Rayleigh beam) the frequencies are lower, as the closed form says.
  s.options.rotary_inertia = true;
  const std::vector<Mode> rayleigh = bending_modes(build_model(s));
  for (int n = 1; n <= 3; ++n)
    EXPECT_NEAR(rayleigh[static_cast<std::size_t>(n - 1)].frequency_hz / analytic_hz(n, false, true, 1.0), 1.0,
                1e-7 * std::pow(n, 4))
        << n;
  EXPECT_LT(rayleigh[2].frequency_hz, modes[2].frequency_hz * (1 - 1e-3));
}

TEST(BeamOptions, TheShearCoefficientChosenIsTheOneUsed) {
  ModelSpec s = shaft();
  // A given κ (far from the formulas, so that a wrong one shows).
  s.options.kappa = 0.5;
  std::vector<Mode> modes = bending_modes(build_model(s));
  EXPECT_NEAR(modes[0].frequency_hz / analytic_hz(1, true, true, 0.5), 1.0, 2e-5);
  // Hutchinson's formula, by its closed form for a solid circle: 6(1 + ν)²/(7 + 12ν + 4ν²).
  s.options.kappa.reset();
  s.options.shear_coefficient = "hutchinson";
  const Real kh = 6 * (1 + nu) * (1 + nu) / (7 + 12 * nu + 4 * nu * nu);
  modes = bending_modes(build_model(s));
  EXPECT_NEAR(modes[0].frequency_hz / analytic_hz(1, true, true, kh), 1.0, 2e-5);
  s.options.shear_coefficient = "hutchison";
  EXPECT_THROW((void)build_model(s), SpecError);
}

// Hutchinson's coefficient against its limits: at ν = 0 it is Cowper's (6/7 for the
// solid circle, 1/2 for the thin tube), and a thin tube tends to (1 + ν)/(2 + ν).
TEST(BeamOptions, HutchinsonShearCoefficientLimits) {
  const CircularSection solid{0.1, 0.0}, tube{0.1, 0.0999999};
  EXPECT_NEAR(solid.hutchinson_shear_coefficient(0.0), 6.0 / 7.0, 1e-15);
  EXPECT_NEAR(solid.hutchinson_shear_coefficient(0.0), solid.cowper_shear_coefficient(0.0), 1e-15);
  EXPECT_NEAR(tube.hutchinson_shear_coefficient(0.0), 0.5, 1e-6);
  EXPECT_NEAR(tube.hutchinson_shear_coefficient(0.3), 1.3 / 2.3, 1e-6);
}

// C = αM + βK on the whole (undamped) shaft is proportional damping: each mode keeps
// its shape and has ζ_n = α/(2ω_n) + βω_n/2 (exact; round-off 1e-8). Unlike rotating
// shaft damping it has no circulatory part, so spinning above the first critical speed
// leaves every mode damped, where rotating damping of the same β turns the first
// forward mode unstable (test_material_damping.cpp).
TEST(BeamOptions, RayleighDampingIsProportionalAndExternal) {
  ModelSpec s = shaft();
  s.options.shear_deformation = false;
  set_parameter(s, "options.rayleigh_alpha", "2 1/s");
  set_parameter(s, "options.rayleigh_beta", "1e-5 s");
  const Model model = build_model(s);
  const std::vector<Mode> modes = bending_modes(model);
  for (const Mode& mode : modes) {
    const Real w = 2 * pi * mode.frequency_hz / std::sqrt(1 - mode.damping_ratio * mode.damping_ratio);
    EXPECT_NEAR(mode.damping_ratio, 2.0 / (2 * w) + 1e-5 * w / 2, 1e-8) << mode.frequency_hz;
  }
  const Real above = 1.5 * 2 * pi * modes[0].frequency_hz;
  for (const Mode& mode : run_modal(model, above).modes)
    if (mode.oscillatory) {
      EXPECT_GT(mode.damping_ratio, 0.0) << mode.frequency_hz;
    }

  ModelSpec rotating = shaft();
  rotating.options.shear_deformation = false;
  rotating.options.shaft_damping = 1e-5;
  Real least = 1.0;
  for (const Mode& mode : run_modal(build_model(rotating), above).modes)
    if (mode.oscillatory) least = std::min(least, mode.damping_ratio);
  EXPECT_LT(least, 0.0);

  // A shaft's own values override [options].
  ModelSpec per_shaft = s;
  per_shaft.shafts[0].rayleigh_beta = 0.0;
  per_shaft.shafts[0].rayleigh_alpha = 0.0;
  for (const Mode& mode : bending_modes(build_model(per_shaft))) EXPECT_NEAR(mode.damping_ratio, 0.0, 1e-12);
}

}  // namespace
}  // namespace feran::test_beam_options

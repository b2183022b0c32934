// An annular seal in a model, through the model file, against the closed forms of the
// smallest rotor it can hold: a rotating mass m on an isotropic spring k_b to the ground
// with the seal at the same node, its other DOFs held. With q = y + iz the seal's force
// is −(K − ik)q − (C − ic)q' − Mq'' (docs/theory/annular_seal.md), so
//   (m + M)q'' + (C − ic)q' + (k_b + K − ik)q = 0,
// whose two roots p₁, p₂ and their conjugates are the real system's four eigenvalues
// (listed once per conjugate pair);
// a static load F = F_y + iF_z displaces it by F/(k_b + K − ik), and a synchronous
// unbalance force U·e^{iωt} whirls it by U/(k_b + K − ik + iω(C − ic) − ω²(m + M)).
// The coefficients come from annular_seal_coefficients (tested on their own in
// tests/unit/elements/test_annular_seal.cpp); what is checked here is that the model
// file, the assembly and each analysis put them where the force law says — modal with
// a mass matrix that changes with speed, static with the speed's Lomakin stiffness,
// the response's reported seal force with its inertia term — to 1e-9 (solver round-off
// on a 2-DOF system), and that a run-up refuses the speed-dependent added mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/elements/annular_seal.hpp>
#include <feran/forces/static_load.hpp>
#include <feran/forces/unbalance.hpp>
#include <feran/io/model_reader.hpp>

namespace feran::test_annular_seal_rotor {
namespace {

constexpr Real mass = 12.0, kb = 4e6;

const char* model_text = R"(
title = "a mass on a spring and a wear ring"
[[nodes]]
name = "impeller"
x = 0
rotating = true
[[rigid_bodies]]
node = "impeller"
mass = "12 kg"
Ja = 0.01
Jp = 0.02
[[springs]]
node = "impeller"
ky = "4 MN/m"
kz = "4 MN/m"
[[annular_seals]]
name = "wear ring"
node = "impeller"
diameter = "100 mm"
length = "25 mm"
clearance = "0.2 mm"
pressure_drop = "1 MPa"
density = "1000 kg/m^3"
viscosity = "1 mPa*s"
[[fixed]]
node = "impeller"
dofs = ["u", "rx", "ry", "rz"]
)";

AnnularSealGeometry geometry() {
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

Model model() { return read_model_string(model_text, "seal.toml").model; }

TEST(AnnularSealRotor, ModesAreTheRootsOfTheComplexEquation) {
  const Model m = model();
  for (const Real speed : {0.0, 300.0, 1200.0}) {
    const AnnularSealCoefficients s = annular_seal_coefficients(geometry(), speed);
    const Complex a(mass + s.M, 0.0), b(s.C, -s.c), c(kb + s.K, -s.k);
    const Complex root = std::sqrt(b * b - 4.0 * a * c);
    std::vector<Complex> expected = {(-b + root) / (2.0 * a), (-b - root) / (2.0 * a)};
    expected.push_back(std::conj(expected[0]));
    expected.push_back(std::conj(expected[1]));
    // The modes are listed once per conjugate pair (Im p ≥ 0): one forward, one backward.
    std::vector<Complex> upper;
    for (const Complex& p : expected)
      if (p.imag() > 0) upper.push_back(p);
    ASSERT_EQ(upper.size(), 2u);
    const ModalResult r = run_modal(m, speed);
    ASSERT_EQ(r.modes.size(), 2u) << speed;
    for (const Complex& p : upper) {
      const auto nearest = std::min_element(r.modes.begin(), r.modes.end(), [&](const Mode& x, const Mode& y) {
        return std::abs(x.eigenvalue - p) < std::abs(y.eigenvalue - p);
      });
      EXPECT_LT(std::abs(nearest->eigenvalue - p), 1e-9 * std::abs(p)) << speed << " " << p;
    }
  }
}

TEST(AnnularSealRotor, StaticDeflectionSeesTheLomakinStiffnessAtSpeed) {
  Model m = model();
  StaticLoad load;
  load.node = 0;
  load.load[static_cast<std::size_t>(Dof::v)] = -500.0;
  m.forces.emplace_back(load);
  for (const Real speed : {0.0, 800.0}) {
    StaticOptions options;
    options.speed = speed;
    const StaticResult r = run_static(m, options);
    ASSERT_TRUE(r.info.converged());
    const AnnularSealCoefficients s = annular_seal_coefficients(geometry(), speed);
    const Complex q = Complex(-500.0, 0.0) / Complex(kb + s.K, -s.k);
    EXPECT_NEAR(r.q(global_dof(0, Dof::v)), q.real(), 1e-9 * std::abs(q)) << speed;
    EXPECT_NEAR(r.q(global_dof(0, Dof::w)), q.imag(), 1e-9 * std::abs(q)) << speed;
  }
}

TEST(AnnularSealRotor, ReportedSealForceHasItsInertia) {
  Model m = model();
  Unbalance u;
  u.node = 0;
  u.mass = 0.01;
  u.radius = 0.1;
  m.forces.emplace_back(u);
  HarmonicOptions options;
  options.speeds = {200.0, 700.0, 1500.0};
  options.probes = {0};
  const HarmonicResult r = run_harmonic_response(m, options);
  ASSERT_EQ(r.springs.size(), 2u);  // the spring, then the seal
  const SpringForceResponse& seal = r.springs[1];
  for (std::size_t k = 0; k < options.speeds.size(); ++k) {
    const Real w = options.speeds[k];
    const AnnularSealCoefficients s = annular_seal_coefficients(geometry(), w);
    const Complex I(0.0, 1.0);
    const Complex Zs = Complex(s.K, -s.k) + I * w * Complex(s.C, -s.c) - w * w * s.M;
    const Complex U = u.mass * u.radius * w * w;  // forward whirl: y + iz = U/Z·e^{iωt}
    const Complex q = U / (Zs + kb - w * w * mass);
    // The probe's complex amplitudes: y and z of the forward whirl q e^{iωt}.
    const Complex y = r.probes[0].q[k][static_cast<std::size_t>(Dof::v)];
    const Complex z = r.probes[0].q[k][static_cast<std::size_t>(Dof::w)];
    EXPECT_LT(std::abs(y - q), 1e-9 * std::abs(q)) << w;
    EXPECT_LT(std::abs(z + I * q), 1e-9 * std::abs(q)) << w;
    // What the seal transmits: (K − ik + iω(C − ic) − ω²M)·(y + iz) in the same form.
    const Complex fy = seal.force[k][static_cast<std::size_t>(Dof::v)];
    EXPECT_LT(std::abs(fy - Zs * q), 1e-9 * std::abs(Zs * q)) << w;
  }
}

TEST(AnnularSealRotor, RunupRefusesTheSpeedDependentAddedMass) {
  const Model m = model();
  TransientOptions options;
  options.duration = 0.01;
  options.output_interval = 0.001;
  options.settings.dt = 1e-4;
  options.profile = SpeedProfile::constant(100.0);
  try {
    run_transient(m, options);
    FAIL() << "a run-up with a seal's speed-dependent added mass ran";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("added mass that changes with speed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feran::test_annular_seal_rotor

// Static analysis against statics and beam theory.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/static/static_analysis.hpp>
#include <feran/core/error.hpp>

#include "test_models.hpp"

namespace feran::test_static {
namespace {

constexpr Real L = 1.2, d = 0.05, g = 9.81;

// Simply supported uniform shaft under its own weight (gravity −y): statically
// determinate. Reactions wL/2 each; midspan deflection 5wL⁴/(384EI) + wL²/(8κGA)
// (the second term from shear deformation); midspan moment wL²/8. Consistent loads
// and element shape functions that solve the homogeneous beam equations make the
// nodal values exact, so the tolerances are round-off (1e-9 relative).
void simply_supported(bool shear) {
  Model m;
  BeamOptions beam;
  beam.shear_deformation = shear;
  const Material mat = test::steel();
  const int n_el = 8;
  test::add_shaft(m, 0.0, L, n_el, d, mat, 0.0, beam);
  test::fix(m, 0, {Dof::u, Dof::v, Dof::w, Dof::rx});
  test::fix(m, n_el, {Dof::v, Dof::w});
  StaticOptions opt;
  opt.gravity = Eigen::Vector3d(0, -g, 0);
  const StaticResult r = run_static(m, opt);

  const CircularSection sec{d, 0};
  const Real w = mat.rho * sec.area() * g, EI = mat.E * sec.second_moment();
  const Real kGA = sec.cowper_shear_coefficient(mat.poisson()) * mat.G * sec.area();
  const Real delta = 5 * w * std::pow(L, 4) / (384 * EI) + (shear ? w * L * L / (8 * kGA) : 0.0);
  EXPECT_NEAR(r.q(global_dof(n_el / 2, Dof::v)), -delta, 1e-9 * delta);
  EXPECT_NEAR(r.q(global_dof(n_el / 2, Dof::w)), 0.0, 1e-15);

  ASSERT_EQ(r.reactions.size(), 2u);
  for (const auto& [node, force] : r.reactions)  // the shaft pushes each support down by wL/2
    EXPECT_NEAR(force[static_cast<std::size_t>(Dof::v)], -w * L / 2, 1e-9 * w * L);
  EXPECT_NEAR(r.total_load[static_cast<std::size_t>(Dof::v)], -w * L, 1e-9 * w * L);

  // Midspan: the end of element n_el/2 − 1 (station 2·(n_el/2 − 1) + 1) and the start
  // of the next element see the same section: moment wL²/8 about z, stress M·r/I.
  const Real M_mid = w * L * L / 8;
  for (std::size_t s : {static_cast<std::size_t>(n_el - 1), static_cast<std::size_t>(n_el)}) {
    ASSERT_NEAR(r.stations[s].x, L / 2, 1e-12);
    EXPECT_NEAR(std::abs(r.section_forces[s].Mz), M_mid, 1e-9 * M_mid);
    EXPECT_NEAR(std::abs(r.section_forces[s].Vy), 0.0, 1e-9 * w * L);
    EXPECT_NEAR(r.stresses[s].bending, M_mid * (d / 2) / sec.second_moment(), 1e-9 * r.stresses[s].bending);
  }
  // At the supports: shear wL/2, no moment; the largest shear stress there, 4V/(3A).
  EXPECT_NEAR(std::abs(r.section_forces[0].Vy), w * L / 2, 1e-9 * w * L);
  EXPECT_NEAR(std::abs(r.section_forces[0].Mz), 0.0, 1e-9 * M_mid);
  EXPECT_NEAR(r.stresses[0].shear, 4.0 / 3.0 * (w * L / 2) / sec.area(), 1e-9 * r.stresses[0].shear);
}

TEST(StaticAnalysis, SimplySupportedShaftUnderGravityTimoshenko) { simply_supported(true); }
TEST(StaticAnalysis, SimplySupportedShaftUnderGravityEulerBernoulli) { simply_supported(false); }

// Cantilever with a tip disk whose centre of mass sits at an axial offset, plus a
// point load and a moment: the clamp carries the total force and the total moment
// about it (statics only).
TEST(StaticAnalysis, CantileverReactionsFromStatics) {
  Model m;
  const Material mat = test::steel();
  test::add_shaft(m, 0.0, 0.4, 4, 0.03, mat);
  const Real md = 5.0, e = 0.02;
  test::add_body(m, 4, md, 0.02 + md * e * e, 0.03, e);
  test::fix_all(m, 0);
  StaticLoad load;
  load.node = 2;
  load.load[static_cast<std::size_t>(Dof::w)] = 100.0;
  load.load[static_cast<std::size_t>(Dof::rx)] = 7.0;
  m.forces.emplace_back(load);
  StaticOptions opt;
  opt.gravity = Eigen::Vector3d(0, -g, 0);
  const StaticResult r = run_static(m, opt);
  ASSERT_EQ(r.reactions.size(), 1u);
  const NodeValues& R = r.reactions[0].second;
  const Real ws = mat.rho * CircularSection{0.03, 0}.area() * 0.4 * g;  // shaft weight, centre at 0.2 m
  const Real wd = md * g;                                               // disk weight at 0.4 + e
  const Real tol = 1e-9 * (ws + wd + 100);
  EXPECT_NEAR(R[static_cast<std::size_t>(Dof::v)], -(ws + wd), tol);
  EXPECT_NEAR(R[static_cast<std::size_t>(Dof::w)], 100.0, tol);
  EXPECT_NEAR(R[static_cast<std::size_t>(Dof::rx)], 7.0, tol);
  // Moments about the clamp (x = 0): M_z = Σ x·F_y, M_y = −Σ x·F_z.
  EXPECT_NEAR(R[static_cast<std::size_t>(Dof::rz)], -(ws * 0.2 + wd * (0.4 + e)), tol);
  EXPECT_NEAR(R[static_cast<std::size_t>(Dof::ry)], -(0.2 * 100.0), tol);
  // The tip deflects down and towards +z.
  EXPECT_LT(r.q(global_dof(4, Dof::v)), 0.0);
  EXPECT_GT(r.q(global_dof(4, Dof::w)), 0.0);
}

// Torsion and axial motion left free (allowed): a lateral load is still solved, a
// torque is refused with a message naming the free motion.
TEST(StaticAnalysis, FreeMotionsAllowedOnlyWhenTheLoadLeavesThemAlone) {
  Model m = test::friswell_5_9_1();
  m.fixed.clear();
  m.free_motions = {FreeMotion::axial, FreeMotion::torsion};
  StaticOptions opt;
  opt.gravity = Eigen::Vector3d(0, -g, 0);
  Model held = test::friswell_5_9_1();
  const StaticResult free = run_static(m, opt), fixed = run_static(held, opt);
  for (Index node = 0; node < m.n_nodes(); ++node)
    EXPECT_NEAR(free.q(global_dof(node, Dof::v)), fixed.q(global_dof(node, Dof::v)),
                1e-9 * std::abs(fixed.q(global_dof(3, Dof::v))));
  StaticLoad torque;
  torque.node = 2;
  torque.load[static_cast<std::size_t>(Dof::rx)] = 10.0;
  m.forces.emplace_back(torque);
  try {
    run_static(m, opt);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rotation about the x axis"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feran::test_static

namespace feran::test_static {
namespace {

// A model built in code skips the builder's ranges: a load of 1e308 N on a soft
// spring gives displacements that overflow. That is a numerical failure with a
// plain message, not infinite displacements reported as a success.
TEST(Static, NonFiniteDisplacementsAreANumericalFailure) {
  Model model = test::jeffcott(1.0, 1e-300, 0.0, 0.0);
  StaticLoad load;
  load.node = 0;
  load.load[static_cast<std::size_t>(Dof::v)] = 1e308;
  model.forces.emplace_back(load, "huge");
  const StaticOptions options;  // no gravity
  const StaticResult r = run_static(model, options);
  EXPECT_EQ(r.info.status, SolverStatus::numerical_failure);
  EXPECT_NE(r.info.message.find("the displacements are not finite"), std::string::npos) << r.info.message;
}

}  // namespace
}  // namespace feran::test_static

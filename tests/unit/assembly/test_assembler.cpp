#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include <Eigen/Eigenvalues>

#include <feran/assembly/assembler.hpp>
#include <feran/assembly/checks.hpp>
#include <feran/core/error.hpp>

#include "test_models.hpp"

namespace feran::test_assembler {
namespace {

// Structure of the assembled matrices (M, K symmetric, G and K_i
// skew-symmetric, M positive definite), on a model with every element kind, a
// rigid link and fixed DOFs. Tolerances: exact up to the sum of a few
// floating-point terms, 1e-12 of the largest entry.
TEST(Assembler, SymmetryAndDefiniteness) {
  BeamOptions damped;
  damped.damping_beta = 1e-5;  // rotating shaft damping: C_i and K_i from every shaft element
  Model m = test::friswell_5_9_1(6, damped);
  m.elements.emplace_back(RotatingDamper(3, std::nullopt, {100.0, 0.1, 0.0, 0.0}));
  const Index stator = test::add_node(m, 1.5, false);
  const Index stator2 = test::add_node(m, 1.6, false);
  test::add_body(m, stator, 10.0, 0.1, 0.1, 0.0, false);
  m.links.push_back({stator, {stator2}});
  test::add_isotropic_bearing(m, stator, 1e7, 10.0);
  test::fix(m, stator, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  const Assembler assembler(m);
  const SystemMatrices s = assembler.at(100.0);
  auto norm = [](const SparseMatrix& a) { return Matrix(a).cwiseAbs().maxCoeff(); };
  auto asym = [](const SparseMatrix& a) { return Matrix(a - SparseMatrix(a.transpose())).cwiseAbs().maxCoeff(); };
  auto sym = [](const SparseMatrix& a) { return Matrix(a + SparseMatrix(a.transpose())).cwiseAbs().maxCoeff(); };
  EXPECT_LE(asym(s.M), 1e-12 * norm(s.M));
  EXPECT_LE(asym(s.K), 1e-12 * norm(s.K));
  EXPECT_LE(asym(s.C), 1e-12 * norm(s.C));
  EXPECT_LE(asym(s.Ci), 1e-12 * norm(s.Ci));
  EXPECT_LE(sym(s.G), 1e-12 * norm(s.G));
  EXPECT_LE(sym(s.Ki), 1e-12 * norm(s.Ki));
  EXPECT_GT(norm(s.G), 0.0);
  EXPECT_GT(norm(s.Ki), 0.0);
  const Eigen::SelfAdjointEigenSolver<Matrix> eig{Matrix(s.M)};
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

// The total translating mass seen by the assembled M: a unit y translation of every
// node has kinetic-energy mass equal to shaft + disks (the stator is linked and
// fixed otherwise). Hand value: ρπ/4·d²·L + both disks (RigidBody::disk).
TEST(Assembler, RigidTranslationCarriesTheTotalMass) {
  const Model m = test::friswell_5_9_1();
  const Assembler assembler(m);
  const SystemMatrices s = assembler.at(0.0);
  const DofMap& d = assembler.dof_map();
  Vector q = Vector::Zero(d.n_reduced());
  for (Index r = 0; r < d.n_reduced(); ++r)
    if (d.full_dof(r) % dofs_per_node == static_cast<Index>(Dof::v)) q(r) = 1.0;
  const Real shaft = 7810 * pi / 4 * 0.05 * 0.05 * 1.5;
  const Real disks = RigidBody::disk(7810, 0.28, 0.05, 0.07).mass + RigidBody::disk(7810, 0.35, 0.05, 0.07).mass;
  EXPECT_NEAR(q.dot(s.M * q), shaft + disks, 1e-10 * (shaft + disks));
}

TEST(Assembler, SpeedDependentCoefficientsFollowTheSpeed) {
  Model m = test::friswell_5_9_1();
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Step{1e6, 2e6, 100.0});
  m.elements.emplace_back(SpringDamper(3, std::nullopt, c));
  const Assembler assembler(m);
  ASSERT_TRUE(assembler.speed_dependent());
  const Index r = assembler.dof_map().reduced_dof(global_dof(3, Dof::v));
  const Real below = assembler.at(50.0).K.coeff(r, r), above = assembler.at(150.0).K.coeff(r, r);
  EXPECT_DOUBLE_EQ(above - below, 1e6);
}

// variable_values() writes into a fixed pattern what variable_at() assembles from
// scratch. Checked on speed-dependent springs between a shaft node and a stator tied
// by a rigid link (so rows of T have several entries) with fixed DOFs, cross-coupled
// terms, a loss factor and the arctan law, at speeds on both sides of a step and
// after the pattern was made (the second call must reuse it). Tolerance 1e-13 of the
// largest entry: the same products summed in another order.
TEST(Assembler, VariableValuesInPlaceEqualTheAssembledOnes) {
  Model m = test::friswell_5_9_1();
  const Index stator = test::add_node(m, 1.5, false);
  const Index stator2 = test::add_node(m, 1.6, false);
  test::add_body(m, stator, 10.0, 0.1, 0.1, 0.0, false);
  m.links.push_back({stator, {stator2}});
  test::fix(m, stator, {Dof::u, Dof::rx});
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Step{1e6, 2e6, 100.0});
  c.k[static_cast<std::size_t>(Dof::w)] = SpeedCoefficient(SpeedCoefficient::Step{1.5e6, 2e6, 120.0});
  c.k[static_cast<std::size_t>(Dof::ry)] = SpeedCoefficient(3e4);
  c.c[static_cast<std::size_t>(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Step{50.0, 80.0, 90.0});
  c.kyz = SpeedCoefficient(SpeedCoefficient::Step{1e5, -2e5, 110.0});
  c.loss_factor = 0.02;
  m.elements.emplace_back(SpringDamper(3, stator2, c));
  SpringDamperCoefficients ground;
  ground.k[static_cast<std::size_t>(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Step{4e5, 4e6, 60.0});
  ground.k[static_cast<std::size_t>(Dof::w)] = SpeedCoefficient(SpeedCoefficient::Step{4e5, 4e6, 60.0});
  m.elements.emplace_back(SpringDamper(stator, std::nullopt, ground));
  const Assembler assembler(m);
  ASSERT_TRUE(assembler.speed_dependent());
  SystemMatrices in_place;
  for (const Real speed : {0.0, 50.0, 95.0, 115.0, 150.0, 50.0}) {
    assembler.variable_values(speed, in_place);
    const SystemMatrices ref = assembler.variable_at(speed);
    auto diff = [](const SparseMatrix& a, const SparseMatrix& b) {
      return Matrix(Matrix(a) - Matrix(b)).cwiseAbs().maxCoeff();
    };
    const Real scale = Matrix(ref.K).cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 1e5);
    EXPECT_LE(diff(in_place.K, ref.K), 1e-13 * scale) << speed;
    EXPECT_LE(diff(in_place.C, ref.C), 1e-13 * scale) << speed;
    EXPECT_LE(diff(in_place.Kh, ref.Kh), 1e-13 * scale) << speed;
    EXPECT_LE(diff(in_place.M, ref.M) + diff(in_place.G, ref.G), 1e-13 * scale) << speed;
    EXPECT_GT(Matrix(in_place.Kh).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(Checks, NamesTheFreeMotions) {
  Model m = test::friswell_5_9_1();
  m.fixed.clear();
  const Assembler assembler(m);
  const auto motions = find_free_motions(m, assembler);
  ASSERT_EQ(motions.size(), 2u);
  EXPECT_EQ(motions[0].family, FreeMotion::axial);
  EXPECT_EQ(motions[1].family, FreeMotion::torsion);
  EXPECT_NE(motions[1].description.find("rotation about the x axis"), std::string::npos);
  try {
    check_model(m, assembler);
    FAIL() << "expected a singular-stiffness error";
  } catch (const ModelStructureError& e) {
    EXPECT_NE(std::string(e.what()).find("free_motions = [\"axial\", \"torsion\"]"), std::string::npos) << e.what();
  }
  m.free_motions = {FreeMotion::axial, FreeMotion::torsion};
  EXPECT_NO_THROW(check_model(m, Assembler(m)));
}

// The null space of K relative to M holds the motions with λ = xᵀKx/xᵀMx below
// τ = 1e-12·λ_max (λ_max = max K_ii/M_ii). A rotor on two bearings of stiffness k has a
// translation and a tilt per bending plane with λ between about 0.02·k and 0.12·k (m ≈
// 107 kg, transverse inertia ≈ 9.5 kg m² about the middle, bearings 1.5 m apart):
// bearings of 1e-3·τ N/m make four rigid motions, of 1e3·τ N/m none, as do the real
// 1 MN/m ones and, without bearings, four again — on a coarse and a fine mesh (λ_max
// 1.3e9 and 9.1e12). The usual case (none) is decided by the inertia of K − τM, a
// rigid one by subspace iteration: both must agree with the criterion. Bearings of
// τ N/m put the four motions at λ = 0.02τ … 0.12τ, between the floor 1e-14·λ_max and τ:
// vibrations of a wide spectrum (what a fine mesh makes of real bearings), found as
// such by the inertia at the floor — none rigid (the iteration shifted by 1e-8·λ_max,
// far above them, grew with the model and found them or not by chance).
TEST(Checks, NullSpaceFollowsTheRigidBodyCriterion) {
  for (int n_el : {6, 501}) {
    auto on_bearings = [&](std::optional<Real> k) {
      Model m = test::friswell_5_9_1(n_el);
      m.elements.erase(std::remove_if(m.elements.begin(), m.elements.end(),
                                      [](const Element& e) { return e.kind() == "spring_damper"; }),
                       m.elements.end());
      if (k) {
        test::add_isotropic_bearing(m, 0, *k);
        test::add_isotropic_bearing(m, m.n_nodes() - 1, *k);
      }
      return m;
    };
    const SystemMatrices free_sys = Assembler(on_bearings(std::nullopt)).at(0.0);
    Real lambda_max = 0.0;
    for (Index i = 0; i < free_sys.M.rows(); ++i)
      lambda_max = std::max(lambda_max, free_sys.K.coeff(i, i) / free_sys.M.coeff(i, i));
    const Real tau = 1e-12 * lambda_max;
    for (const auto& [k, expected] : std::vector<std::pair<std::optional<Real>, Index>>{
             {std::nullopt, 4}, {1e-3 * tau, 4}, {1.0 * tau, 0}, {1e3 * tau, 0}, {1e6, 0}}) {
      const SystemMatrices sys = Assembler(on_bearings(k)).at(0.0);
      const Matrix N = stiffness_null_space(sys.K, sys.M);
      EXPECT_EQ(N.cols(), expected) << n_el << " elements, bearings " << (k ? *k : 0.0) << " N/m";
      for (Index j = 0; j < N.cols(); ++j) {
        const Vector x = N.col(j);
        EXPECT_LT(x.dot(sys.K * x) / x.dot(sys.M * x), tau) << n_el << " elements, vector " << j;
      }
    }
  }
}

// A spring 1e16 times stiffer than the bearings (1e22 N/m) puts the shaft's bending
// vibrations — dozens of them, on 150 elements — below 1e-14 of the highest
// eigenvalue, within a hundred times the round-off: more than the six rigid motions a
// body can have per separate part. The message names that, not a free motion.
TEST(Checks, AnUnresolvableSpectrumIsSaidToBeOne) {
  Model m = test::friswell_5_9_1(150);
  test::add_isotropic_bearing(m, m.n_nodes() / 2, 1e22);
  try {
    check_model(m, Assembler(m));
    FAIL() << "expected an error";
  } catch (const ModelStructureError& e) {
    EXPECT_NE(std::string(e.what()).find("the stiffness spans too many orders of magnitude to be resolved"),
              std::string::npos)
        << e.what();
  }
  // The same rotor with bearings of its own kind is fine.
  EXPECT_NO_THROW(check_model(test::friswell_5_9_1(150), Assembler(test::friswell_5_9_1(150))));
}

// A shaft on a single isotropic bearing can pivot about it: the lateral free motion
// is a rotation about an axis through the bearing.
TEST(Checks, LocatesAPivot) {
  Model m;
  test::add_shaft(m, 0.0, 1.0, 4, 0.05, test::steel());
  test::add_isotropic_bearing(m, 2, 1e6);
  test::fix(m, 0, {Dof::u, Dof::rx});
  const auto motions = find_free_motions(m, Assembler(m));
  ASSERT_EQ(motions.size(), 2u);  // one per bending plane
  EXPECT_NE(motions[0].description.find("rotation about the z axis through x = 0.5 m"), std::string::npos)
      << motions[0].description;
  EXPECT_NE(motions[1].description.find("rotation about the y axis through x = 0.5 m"), std::string::npos)
      << motions[1].description;
}

TEST(Checks, NamesANodeWithoutMass) {
  Model m = test::friswell_5_9_1();
  const Index loose = test::add_node(m, 0.7, false, "housing");
  test::fix(m, loose, {Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry});
  try {
    check_model(m, Assembler(m));
    FAIL() << "expected a zero-mass error";
  } catch (const ModelStructureError& e) {
    EXPECT_EQ(e.node(), loose);
    EXPECT_NE(std::string(e.what()).find("node 8 (housing) has no mass in DOF rz"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feran::test_assembler

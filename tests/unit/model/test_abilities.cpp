// Elements and forces declare abilities that analyses ask for (model/element.hpp,
// model/force.hpp). A type defined here, unknown to the library, takes part in the
// analyses through its abilities alone: the seam a new bearing or force plugs into.

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/model/force.hpp>

#include <gtest/gtest.h>

#include "test_models.hpp"

namespace feran::test_abilities {
namespace {

/// A linear spring from a node to ground along y and z, with only the matrix
/// function and the transmission ability.
struct TestBearing {
  Index node = 0;
  Real k = 0.0;
  Matrix K6() const {
    Matrix K = Matrix::Zero(6, 6);
    K(1, 1) = K(2, 2) = k;
    return K;
  }
  LocalMatrices local_matrices(const OperatingPoint&) const {
    LocalMatrices lm;
    for (int d = 0; d < dofs_per_node; ++d) lm.dofs.push_back(global_dof(node, static_cast<Dof>(d)));
    lm.K = K6();
    return lm;
  }
  std::string_view kind() const { return "test_bearing"; }
  bool speed_dependent() const { return false; }
  Transmission transmission(Real) const { return {node, std::nullopt, K6(), Matrix::Zero(6, 6), 0.0, {}}; }
};

/// A constant lateral load with only the static ability.
struct TestLoad {
  Index node = 0;
  Real fy = 0.0;
  std::string_view kind() const { return "test_load"; }
  std::vector<Index> nodes() const { return {node}; }
  void add_static(Vector& f) const { f(global_dof(node, Dof::v)) += fy; }
};

TEST(Abilities, AreDetectedFromTheMembersATypeHas) {
  const Force load(TestLoad{2, 5.0}, "push");
  EXPECT_TRUE(load.has_static());
  EXPECT_FALSE(load.has_harmonic());
  EXPECT_FALSE(load.has_transient());
  EXPECT_FALSE(load.is_nonlinear());
  EXPECT_EQ(load.kind(), "test_load");
  EXPECT_EQ(load.label(), "push");
  EXPECT_EQ(load.nodes(), std::vector<Index>{2});
  ComplexVector h = ComplexVector::Zero(18);
  load.add_harmonic({}, h);  // no ability: nothing added
  EXPECT_EQ(h.norm(), 0.0);
  Vector f = Vector::Zero(18);
  const Force copy = load;  // value semantics
  copy.add_static(f);
  EXPECT_EQ(f(global_dof(2, Dof::v)), 5.0);

  const Force unbalance(Unbalance{1, 1e-3, 0.1, 0.0, 0.0});
  EXPECT_TRUE(unbalance.has_harmonic());
  EXPECT_TRUE(unbalance.has_transient());
  EXPECT_FALSE(unbalance.has_static());
  EXPECT_TRUE(Force(CoulombFriction{}).is_nonlinear());

  const Element bearing(TestBearing{0, 1e6});
  EXPECT_TRUE(bearing.transmission(0.0).has_value());
  EXPECT_FALSE(bearing.shaft_segment().has_value());
}

// A clamped–free shaft: a new element type's transmitted force is reported by the
// static analysis, and a new force type loads it, without the analysis knowing
// either type. A tip bearing of stiffness k under a tip load F on a cantilever of
// stiffness k_c = 3EI/L³ carries k/(k + k_c)·F (Euler–Bernoulli, exact for cubic
// elements: round-off 1e-9).
TEST(Abilities, ANewElementAndForceTakePartInTheStaticAnalysis) {
  Model m;
  BeamOptions euler_bernoulli;
  euler_bernoulli.shear_deformation = false;
  const Material steel = test::steel();
  const Real L = 0.5, d = 0.02;
  test::add_shaft(m, 0.0, L, 4, d, steel, 0.0, euler_bernoulli);
  test::fix_all(m, 0);
  const Real k = 2e5, F = 100.0;
  m.elements.emplace_back(TestBearing{4, k}, "tip bearing");
  m.forces.emplace_back(TestLoad{4, F}, "tip load");
  const StaticResult r = run_static(m, {});
  const Real I = pi * std::pow(d, 4) / 64.0;
  const Real kc = 3.0 * steel.E * I / (L * L * L);
  ASSERT_EQ(r.springs.size(), 1u);
  EXPECT_EQ(r.springs[0].first, 4);  // the element's index
  EXPECT_NEAR(r.springs[0].second[static_cast<std::size_t>(Dof::v)] / (k / (k + kc) * F), 1.0, 1e-9);
}

}  // namespace
}  // namespace feran::test_abilities

// Whirl classification from complex shapes whose orbits are known by construction:
// q(t) = Re(shape·e^{iωt}), ω > 0; V = 1, W = −i gives v = cos ωt, w = sin ωt, an
// orbit turning from +y to +z, the direction of the spin about +x (forward).
#include <gtest/gtest.h>

#include <feran/analyses/modal/whirl.hpp>

namespace feran::test_whirl {
namespace {

const Complex I(0, 1);

ComplexVector shape(std::initializer_list<std::pair<Complex, Complex>> orbits) {
  ComplexVector s = ComplexVector::Zero(static_cast<Index>(orbits.size()) * dofs_per_node);
  Index node = 0;
  for (auto [v, w] : orbits) {
    s(global_dof(node, Dof::v)) = v;
    s(global_dof(node, Dof::w)) = w;
    ++node;
  }
  return s;
}

TEST(Whirl, CirclesAndLines) {
  EXPECT_EQ(classify_whirl(shape({{1.0, -I}, {2.0, -2.0 * I}})).whirl, Whirl::forward);
  EXPECT_NEAR(classify_whirl(shape({{1.0, -I}})).directivity, 1.0, 1e-15);
  EXPECT_EQ(classify_whirl(shape({{1.0, I}})).whirl, Whirl::backward);
  EXPECT_NEAR(classify_whirl(shape({{1.0, I}})).directivity, -1.0, 1e-15);
  // Straight-line orbit: equal forward and backward circles.
  const WhirlResult line = classify_whirl(shape({{1.0, 0.5}}));
  EXPECT_EQ(line.whirl, Whirl::planar);
  EXPECT_NEAR(line.directivity, 0.0, 1e-15);
}

TEST(Whirl, PhaseOfTheShapeDoesNotMatter) {
  const Complex phase = std::polar(1.0, 0.7);
  EXPECT_EQ(classify_whirl(phase * shape({{1.0, -I}})).whirl, Whirl::forward);
}

TEST(Whirl, EllipseDirectivity) {
  // v = cos, w = 0.5 sin: r_f = 0.75, r_b = 0.25 → (r_f² − r_b²)/(r_f² + r_b²) = 0.8.
  const WhirlResult e = classify_whirl(shape({{1.0, -0.5 * I}}));
  EXPECT_EQ(e.whirl, Whirl::forward);
  EXPECT_NEAR(e.directivity, 0.8, 1e-15);
}

TEST(Whirl, MixedWhenNodesDisagree) {
  EXPECT_EQ(classify_whirl(shape({{1.0, -I}, {0.5, 0.5 * I}})).whirl, Whirl::mixed);
}

TEST(Whirl, TinyOrbitsNearANodalPointAreIgnored) {
  // The second node's orbit is 1 % of the largest and turns backward: still forward.
  EXPECT_EQ(classify_whirl(shape({{1.0, -I}, {0.01, 0.01 * I}})).whirl, Whirl::forward);
}

TEST(Whirl, PureTiltUsesTheTiltVector) {
  ComplexVector s = ComplexVector::Zero(dofs_per_node);
  // rz = cos, −ry = sin: the shaft axis tip (rz, −ry) turns from +y to +z.
  s(static_cast<Index>(Dof::rz)) = 1.0;
  s(static_cast<Index>(Dof::ry)) = I;
  EXPECT_EQ(classify_whirl(s).whirl, Whirl::forward);
}

TEST(Whirl, NoLateralMotion) {
  ComplexVector s = ComplexVector::Zero(dofs_per_node);
  s(static_cast<Index>(Dof::u)) = 1.0;
  EXPECT_EQ(classify_whirl(s).whirl, Whirl::none);
}

TEST(Whirl, FormsMatchTheCircleRadii) {
  ComplexMatrix two(dofs_per_node, 2);
  two.col(0) = shape({{1.0, -I}});
  two.col(1) = shape({{1.0, I}});
  const ComplexMatrix s = whirl_form(two), n = lateral_form(two);
  EXPECT_NEAR(s(0, 0).real(), 1.0, 1e-15);  // Im(V·conj(W)) = Im(1·i) = 1
  EXPECT_NEAR(s(1, 1).real(), -1.0, 1e-15);
  EXPECT_NEAR(std::abs(s(0, 1)), 0.0, 1e-15);
  EXPECT_NEAR(n(0, 0).real(), 2.0, 1e-15);
  EXPECT_NEAR(std::abs(n(0, 1)), 0.0, 1e-15);  // forward and backward circles are orthogonal
}

}  // namespace
}  // namespace feran::test_whirl

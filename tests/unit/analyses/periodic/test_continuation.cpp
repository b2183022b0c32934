// Pseudo-arclength continuation (analyses/periodic/continuation.hpp) on Duffing's
// frequency response with one harmonic, whose curve is known in closed form:
// [(k − mω²)A + ¾k₃A³]² + (cωA)² = F²:
// - every point of the branch from ω = 0.5 to 2.5 meets it (to 1e-8, the corrector's
//   tolerance 1e-10 on the balance with a margin for the curve's conditioning);
// - the branch turns twice, and the turning points located on it are the curve's folds,
//   where the cubic in A² has a double root (its discriminant vanishes; found by
//   bisection to 1e-13): to 1e-8 in ω;
// - the point of the branch in phase quadrature with the force (a₁ = 0, located on
//   it) lies on the backbone ω² = (k + ¾k₃A²)/m, the free undamped oscillation's
//   single-harmonic frequency at that amplitude (1e-9: the location's tolerance);
// - the branch ends on the range's limit and says it was clipped there;
// - a corrector that cannot converge ends the branch with a reason and keeps the points.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <feran/analyses/periodic/continuation.hpp>
#include <feran/analyses/periodic/harmonic_balance.hpp>
#include <feran/core/error.hpp>

#include "duffing.hpp"

namespace feran::test_continuation {
namespace {

using namespace test::duffing;  // NOLINT(google-build-using-namespace): the shared case's names

PeriodicSystem duffing(const FourierBasis& basis) { return test::duffing::system(basis); }

TEST(Continuation, DuffingsFrequencyResponseWithBothFolds) {
  const FourierBasis basis{.harmonics = 1, .samples = 8};
  const PeriodicSystem s = duffing(basis);
  const BranchFunction G = [&](const Vector& X, Real w) {
    BalanceTerms t = balance_terms(basis, s, w, X);
    return BranchEquations{
        .G = std::move(t.R), .Gu = std::move(t.dR_dX), .Gp = std::move(t.dR_domega), .scale = t.scale};
  };
  ContinuationSettings settings{.p_min = 0.5, .p_max = 2.5, .max_points = 2000, .tolerance = 1e-10};
  const BranchPoint start = correct_at_fixed_parameter(G, Vector::Zero(3), 0.5, settings);
  ASSERT_LE(start.residual, 1e-10);
  const Vector u_scale = Vector::Constant(3, 1.0);
  const Branch b = continue_branch(G, start, Vector(), +1.0, u_scale, 1.0, settings);
  EXPECT_TRUE(b.clipped()) << b.ended_by;
  EXPECT_NEAR(b.points.back().p, 2.5, 1e-14);
  std::vector<Real> folds;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const BranchPoint& p = b.points[i];
    EXPECT_NEAR(response_curve(p.p, std::hypot(p.u(1), p.u(2))), F * F, 1e-8 * F * F) << i;
    if (i > 0 && fold_test(b.points[i - 1]) * fold_test(p) < 0)
      folds.push_back(locate_on_branch(G, b.points[i - 1], p, u_scale, 1.0, settings, fold_test).p);
  }
  // Phase quadrature: a₁ changes sign once, near the peak.
  std::vector<BranchPoint> quadrature;
  const auto a1 = [](const BranchPoint& p) { return p.u(1); };
  for (std::size_t i = 1; i < b.points.size(); ++i)
    if (a1(b.points[i - 1]) * a1(b.points[i]) < 0)
      quadrature.push_back(locate_on_branch(G, b.points[i - 1], b.points[i], u_scale, 1.0, settings, a1));
  ASSERT_EQ(quadrature.size(), 1U);
  {
    const Real w = quadrature[0].p, A = std::hypot(quadrature[0].u(1), quadrature[0].u(2));
    EXPECT_NEAR(w * w, (k + 0.75 * k3 * A * A) / m, 1e-9 * w * w);
  }
  const std::vector<Real> expected = closed_form_folds();
  ASSERT_EQ(expected.size(), 2U);
  ASSERT_EQ(folds.size(), 2U);
  // Along the branch the upper fold (the jump-down) comes first, at the larger ω.
  EXPECT_NEAR(folds[0], expected[1], 1e-8);
  EXPECT_NEAR(folds[1], expected[0], 1e-8);
}

TEST(Continuation, ABranchThatCannotBeFollowedKeepsItsPoints) {
  // G = u² + p² − 1 beyond |p| = 1 has no solution; a function that throws past p = 0.5
  // stands for a model that cannot be evaluated there.
  const BranchFunction G = [](const Vector& u, Real p) {
    if (p > 0.5) throw Error("outside");
    return BranchEquations{.G = Vector::Constant(1, u(0) - p),
                           .Gu = Matrix::Identity(1, 1),
                           .Gp = Vector::Constant(1, -1.0),
                           .scale = 1.0};
  };
  ContinuationSettings settings{.p_min = 0.0, .p_max = 2.0, .step = 0.1};
  const BranchPoint start = correct_at_fixed_parameter(G, Vector::Zero(1), 0.0, settings);
  const Branch b = continue_branch(G, start, Vector(), +1.0, Vector::Ones(1), 1.0, settings);
  EXPECT_FALSE(b.clipped());
  EXPECT_NE(b.ended_by.find("could not be continued"), std::string::npos) << b.ended_by;
  EXPECT_GT(b.points.size(), 3U);
  EXPECT_LE(b.points.back().p, 0.5);
  EXPECT_GT(b.points.back().p, 0.49);
}

}  // namespace
}  // namespace feran::test_continuation

#pragma once
/// @file
/// Pseudo-arclength continuation of a branch of solutions of G(u, p) = 0, G: ℝ^{m+1} →
/// ℝ^m, through folds (Keller 1977; Allgower & Georg 2003): a tangent predictor and a
/// Newton corrector on the hyperplane normal to the tangent, in scaled variables
/// (u/σ_u, p/σ_p), with the step adapted to the corrector's iterations. It knows
/// nothing of rotors; the periodic analysis continues harmonic-balance orbits with it.
/// Theory: docs/theory/harmonic_balance.md ("Continuation").

#include <functional>
#include <string>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// G and its derivatives at (u, p).
struct BranchEquations {
  Vector G;          ///< m values
  Matrix Gu;         ///< ∂G/∂u, m × m
  Vector Gp;         ///< ∂G/∂p
  Real scale = 1.0;  ///< the size against which ‖G‖ is judged (> 0)
};

/// The equations of a branch.
using BranchFunction = std::function<BranchEquations(const Vector& u, Real p)>;

struct ContinuationSettings {
  Real p_min = 0.0, p_max = 0.0;  ///< the branch stops where p leaves [p_min, p_max]
  Real step = 0.05;               ///< first step, in the scaled arclength
  Real min_step = 1e-6;           ///< below it the branch stops (it cannot be followed)
  Real max_step = 0.5;
  /// The most the parameter moves in one step, as a fraction of its scale (0: no
  /// limit): keeps a branch drawn finely where its orbits change fast.
  Real max_parameter_step = 0.0;
  Index max_points = 200;     ///< points on the branch, the start included
  int max_iterations = 8;     ///< Newton steps of one corrector
  int target_iterations = 4;  ///< the step grows when the corrector needs fewer, shrinks when more
  Real tolerance = 1e-9;      ///< on ‖G‖/scale; and on the scaled Newton step
};

/// One point of a branch.
struct BranchPoint {
  Vector u;
  Real p = 0.0;
  Vector tangent;  ///< unit tangent (u, p) in scaled variables, oriented along the branch
  int iterations = 0;
  Real residual = 0.0;  ///< ‖G‖/scale reached
};

/// A continued branch: its points and why it ended.
struct Branch {
  std::vector<BranchPoint> points;
  /// "range" (p left [p_min, p_max]; the last point is on the limit), "points" (the
  /// number asked for), "stopped" (the caller's monitor asked), or a plain reason why
  /// it could not be continued (the step fell below min_step: the corrector did not
  /// converge, with its residual).
  std::string ended_by;
  bool clipped() const { return ended_by == "range"; }
};

/// Converges (u, p0) at fixed p0 by Newton's method; returns the point (iterations and
/// residual say whether it converged: residual ≤ tolerance).
BranchPoint correct_at_fixed_parameter(const BranchFunction& G, const Vector& u0, Real p0,
                                       const ContinuationSettings& settings);

/// Continues the branch through @p start (converged) from the direction @p direction:
/// a unit scaled tangent to start from (empty: the branch's own, oriented so that p
/// moves by the sign of @p towards). σ_u = @p u_scale (per unknown), σ_p = @p p_scale.
/// @p monitor, called with each new point (its index in the branch), returns false to
/// stop the branch there.
Branch continue_branch(const BranchFunction& G, const BranchPoint& start, const Vector& direction, Real towards,
                       const Vector& u_scale, Real p_scale, const ContinuationSettings& settings,
                       const std::function<bool(const Branch&)>& monitor = {});

/// The point between consecutive branch points @p a and @p b where the test function
/// @p tau changes sign (τ(a)·τ(b) ≤ 0), by the Illinois variant of regula falsi on the
/// distance σ along a's tangent: each trial point is corrected on the hyperplane
/// through ẑ_a + σ·t_a normal to t_a. Stops when |σ − σ'| ≤ @p tolerance·σ_b or after
/// 40 trials. Folds: τ = the tangent's p component.
BranchPoint locate_on_branch(const BranchFunction& G, const BranchPoint& a, const BranchPoint& b, const Vector& u_scale,
                             Real p_scale, const ContinuationSettings& settings,
                             const std::function<Real(const BranchPoint&)>& tau, Real tolerance = 1e-10);

/// The tangent's p component (dp/ds in scaled variables): a fold's test function.
inline Real fold_test(const BranchPoint& point) { return point.tangent(point.tangent.size() - 1); }

}  // namespace feran

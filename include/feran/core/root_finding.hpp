#pragma once
/// @file
/// Bracketed scalar root finding.

#include <functional>

#include <feran/core/types.hpp>

namespace feran {

struct RootResult {
  Real x = 0;           ///< the root estimate
  Real fx = 0;          ///< f at the root estimate
  int evaluations = 0;  ///< calls of f
  bool converged = false;
};

/// Brent's method (inverse quadratic interpolation safeguarded by bisection) on a
/// bracket [a, b] with f(a)·f(b) ≤ 0, given fa = f(a) and fb = f(b). Stops when the
/// bracket is narrower than 2·(4ε|x| + x_tol) or after @p max_evaluations calls.
RootResult brent_root(const std::function<Real(Real)>& f, Real a, Real b, Real fa, Real fb, Real x_tol,
                      int max_evaluations = 100);

}  // namespace feran

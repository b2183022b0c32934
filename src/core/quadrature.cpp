#include <feran/core/quadrature.hpp>

#include <cmath>
#include <stdexcept>

namespace feran {

GaussLegendre gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be at least 1");
  GaussLegendre rule;
  rule.nodes.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  const Real nn = n;
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Tricomi: the i-th root from the top is near cos(π(i + 3/4)/(n + 1/2)).
    Real x = std::cos(pi * (i + 0.75) / (nn + 0.5)) * (1.0 - (nn - 1.0) / (8.0 * nn * nn * nn));
    Real dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      // P_n(x) and P_n'(x) by the three-term recurrence.
      Real p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const Real p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const Real pn = n == 1 ? x : p1, pm = n == 1 ? 1.0 : p0;
      dp = nn * (x * pn - pm) / (x * x - 1.0);
      const Real dx = pn / dp;
      x -= dx;
      if (std::abs(dx) <= 1e-16) break;
    }
    // The derivative at the converged root.
    Real p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const Real p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n == 1 ? 1.0 : nn * (x * p1 - p0) / (x * x - 1.0);
    const Real w = 2.0 / ((1.0 - x * x) * dp * dp);
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(n - 1 - i);
    rule.nodes[lo] = -x;
    rule.nodes[hi] = x;
    rule.weights[lo] = w;
    rule.weights[hi] = w;
  }
  if (n % 2 == 1) rule.nodes[static_cast<std::size_t>(n / 2)] = 0.0;
  return rule;
}

}  // namespace feran

#include <feran/core/root_finding.hpp>

#include <cmath>
#include <limits>
#include <utility>

namespace feran {

// Brent (1973), "Algorithms for Minimization without Derivatives", ch. 4 (zero).
RootResult brent_root(const std::function<Real(Real)>& f, Real a, Real b, Real fa, Real fb, Real x_tol,
                      int max_evaluations) {
  RootResult r;
  if (fa == 0.0) return {a, fa, 0, true};
  if (fb == 0.0) return {b, fb, 0, true};
  if ((fa > 0) == (fb > 0)) return {b, fb, 0, false};
  const Real eps = std::numeric_limits<Real>::epsilon();
  Real c = a, fc = fa, d = b - a, e = d;
  for (;;) {
    if ((fb > 0) == (fc > 0)) {
      c = a, fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b, b = c, c = a;
      fa = fb, fb = fc, fc = fa;
    }
    const Real tol = 2.0 * eps * std::abs(b) + 0.5 * x_tol;
    const Real m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) {
      r.x = b, r.fx = fb, r.converged = true;
      return r;
    }
    if (r.evaluations >= max_evaluations) {
      r.x = b, r.fx = fb;
      return r;
    }
    if (std::abs(e) < tol || std::abs(fa) <= std::abs(fb)) {
      d = e = m;  // bisection
    } else {
      Real p, q;
      const Real s = fb / fa;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const Real qa = fa / fc, rr = fb / fc;
        p = s * (2.0 * m * qa * (qa - rr) - (b - a) * (rr - 1.0));
        q = (qa - 1.0) * (rr - 1.0) * (s - 1.0);
      }
      if (p > 0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = m;
      }
    }
    a = b, fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
    ++r.evaluations;
  }
}

}  // namespace feran

// A rigid disk at the tip of a massless cantilever (Euler–Bernoulli, no shear): a
// 2-DOF-per-plane problem with a closed form. For circular whirl at frequency ω > 0,
// forward (+) or backward (−), the tilt inertia becomes J_A ∓ J_P·Ω/ω:
//   (k11 − mω²)(k22 − J_A ω² ± J_P Ω ω) − k12² = 0,
// with k11 = 12EI/L³, k12 = −6EI/L², k22 = 4EI/L. Cubic shape functions are exact for
// an end-loaded beam, so one element reproduces this to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include <feran/analyses/modal/modal.hpp>

#include "test_models.hpp"

namespace feran::test_overhung_disk {
namespace {

constexpr Real E = 2.1e11, d = 0.012, L = 0.08, m = 3.0, Ja = 0.004, Jp = 0.007;

// Roots of f on (0, w_max) by scanning and bisection (independent of feran's solvers).
std::vector<Real> roots(const std::function<Real(Real)>& f, Real w_max) {
  std::vector<Real> out;
  const int n = 200000;
  Real a = 1e-6, fa = f(a);
  for (int i = 1; i <= n; ++i) {
    const Real b = w_max * i / n, fb = f(b);
    if ((fa > 0) != (fb > 0)) {
      Real lo = a, hi = b, flo = fa;
      for (int it = 0; it < 200; ++it) {
        const Real mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm > 0) == (flo > 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      out.push_back(0.5 * (lo + hi));
    }
    a = b, fa = fb;
  }
  return out;
}

TEST(OverhungDisk, WhirlFrequenciesMatchClosedForm) {
  Model model;
  BeamOptions euler_bernoulli;
  euler_bernoulli.shear_deformation = false;
  const Material massless{"massless", E, E / 2.6, 0.0};
  test::add_shaft(model, 0.0, L, 1, d, massless, 0.0, euler_bernoulli);
  test::add_body(model, 1, m, Ja, Jp);
  test::fix_all(model, 0);

  const Real I = pi * std::pow(d, 4) / 64, EI = E * I;
  const Real k11 = 12 * EI / (L * L * L), k12 = -6 * EI / (L * L), k22 = 4 * EI / L;
  for (Real speed : {0.0, 300.0, 1500.0}) {
    auto forward = [&](Real w) { return (k11 - m * w * w) * (k22 - Ja * w * w + Jp * speed * w) - k12 * k12; };
    auto backward = [&](Real w) { return (k11 - m * w * w) * (k22 - Ja * w * w - Jp * speed * w) - k12 * k12; };
    const Real w_max = 20 * std::sqrt(k22 / Ja + k11 / m);
    const std::vector<Real> wf = roots(forward, w_max), wb = roots(backward, w_max);
    ASSERT_EQ(wf.size(), 2u);
    ASSERT_EQ(wb.size(), 2u);

    const ModalResult r = run_modal(model, speed);
    std::vector<Real> ff, fb;
    for (const Mode& mode : r.modes) {
      if (mode.type != ModeType::lateral) continue;
      (mode.whirl == Whirl::forward ? ff : fb).push_back(mode.eigenvalue.imag());
      EXPECT_NE(mode.whirl, Whirl::mixed);
    }
    ASSERT_EQ(ff.size(), 2u);
    ASSERT_EQ(fb.size(), 2u);
    for (int i = 0; i < 2; ++i) {
      // 1e-9 relative: the bisection resolves 1e-15, the FE model is exact.
      EXPECT_NEAR(ff[static_cast<std::size_t>(i)], wf[static_cast<std::size_t>(i)],
                  1e-9 * wf[static_cast<std::size_t>(i)])
          << "speed " << speed;
      EXPECT_NEAR(fb[static_cast<std::size_t>(i)], wb[static_cast<std::size_t>(i)],
                  1e-9 * wb[static_cast<std::size_t>(i)])
          << "speed " << speed;
    }
  }
}

}  // namespace
}  // namespace feran::test_overhung_disk

#include <feran/forces/fluid_film_bearing.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/quadrature.hpp>
#include <feran/core/root_finding.hpp>
#include <feran/forces/finite_bearing_table.hpp>

#include "dual.hpp"
#include "lateral_pair.hpp"

namespace feran {

namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// Points of the rule over the positive-pressure half of the film. In the variable γ
// below the integrands are trigonometric polynomials of low degree, so that 32
// points integrate them to rounding for any eccentricity ratio below 1.
constexpr int film_points = 32;

const GaussLegendre& film_rule() {
  static const GaussLegendre rule = gauss_legendre(film_points);
  return rule;
}

// The eccentric-anomaly substitution for h = c(1 − ε cos α):
//   tan(γ/2) = k·tan(α/2), k = √((1 + ε)/(1 − ε)),
// so that 1 − ε cos α = (1 − ε²)/(1 + ε cos γ) and dα = √(1 − ε²)/(1 + ε cos γ) dγ.
// It spreads the points where the film is thin. Both maps keep the branch: α and γ
// lie in the same interval (2πm − π, 2πm + π].
Real gamma_of_alpha(Real alpha, Real k) {
  const Real m = std::round(alpha / (2.0 * pi));
  const Real a = alpha - 2.0 * pi * m;
  return 2.0 * std::atan2(k * std::sin(0.5 * a), std::cos(0.5 * a)) + 2.0 * pi * m;
}
Real alpha_of_gamma(Real gamma, Real k) {
  const Real m = std::round(gamma / (2.0 * pi));
  const Real g = gamma - 2.0 * pi * m;
  return 2.0 * std::atan2(std::sin(0.5 * g), k * std::cos(0.5 * g)) + 2.0 * pi * m;
}

// Ocvirk's short bearing. With h = c − y cos θ − z sin θ the Reynolds equation
// without its circumferential flow, ∂/∂z(h³ ∂p/∂z) = 12μ·G(θ) with
// G = (Ω/2)·∂h/∂θ + ∂h/∂t = (Ω/2)(y sin θ − z cos θ) − ẏ cos θ − ż sin θ, and p = 0 at
// both ends, gives p = (6μG/h³)(s² − L²/4) (s axial), positive where G < 0. Over
// the length, ∫p ds = −μL³G/h³; the force on the journal is
//   f = −R∫∫p·(cos θ, sin θ) ds dθ = μRL³ ∫_{G<0} G/h³ (cos θ, sin θ) dθ.
// G = A sin θ + B cos θ is negative on one half-turn, (π − β, 2π − β) with
// β = atan2(B, A). The Jacobian is the integral of the integrand's derivatives:
// the integrand vanishes at both ends (G = 0), so the moving ends add nothing.
FilmForce short_bearing_force(const JournalBearingGeometry& g, Real speed, Vec2 x, const Vec2& v) {
  FilmForce out;
  const Real c = g.clearance;
  // A journal at rest at the very centre has G ≡ 0: no film half to integrate over,
  // though the Jacobian has a limit (a pure cross-coupled stiffness). It is taken at a
  // displacement of 1e-9 c, which changes it by that fraction.
  if (x.norm() < 1e-9 * c && v.norm() == 0.0) x = Vec2(1e-9 * c, 0.0);
  const Real A = 0.5 * speed * x(0) - v(1), B = -0.5 * speed * x(1) - v(0);
  if (A == 0.0 && B == 0.0) return out;
  const Real e = x.norm(), eps = e / c;
  const Real psi = e > 0.0 ? std::atan2(x(1), x(0)) : 0.0;
  const Real k = std::sqrt((1.0 + eps) / (1.0 - eps));
  const Real theta1 = pi - std::atan2(B, A);
  const Real g1 = gamma_of_alpha(theta1 - psi, k), g2 = gamma_of_alpha(theta1 - psi + pi, k);
  const Real scale = g.viscosity * 0.5 * g.diameter * g.length * g.length * g.length;
  const Real half = 0.5 * (g2 - g1), mid = 0.5 * (g1 + g2), root = std::sqrt(1.0 - eps * eps);
  const GaussLegendre& rule = film_rule();
  for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
    const Real gamma = mid + half * rule.nodes[j];
    const Real theta = alpha_of_gamma(gamma, k) + psi;
    const Real w = scale * rule.weights[j] * half * root / (1.0 + eps * std::cos(gamma));
    const Real ct = std::cos(theta), st = std::sin(theta);
    const Real h = c - x(0) * ct - x(1) * st;
    const Real G = A * st + B * ct;
    const Real h3 = h * h * h, h4 = h3 * h;
    const Vec2 n(ct, st);
    out.f += w * G / h3 * n;
    // ∂G/∂(y, z) = (Ω/2)(sin θ, −cos θ), ∂G/∂(ẏ, ż) = −(cos θ, sin θ); ∂h/∂(y, z) = −(cos θ, sin θ).
    const Vec2 dG_dx(0.5 * speed * st, -0.5 * speed * ct);
    const Vec2 dI_dx = dG_dx / h3 + 3.0 * G / h4 * n;
    out.dfdx += w * n * dI_dx.transpose();
    out.dfdv += w * n * (-n / h3).transpose();
  }
  return out;
}

// The infinitely long bearing (Sommerfeld) with Gümbel's condition. Without axial
// flow, d/dθ(h³ dp/dθ) = 12μR²·G. In the axes of the displacement (α = θ − ψ,
// h = c(1 − ε cos α)) and with the velocity's radial and tangential parts u_r, u_t:
//   p′ = 12μR²·[(Ω/2)/h² + (κ + u_t cos α − u_r sin α)/h³],
// κ = −(Ωc(1 − ε²) + 3ε·u_t)/(2 + ε²) making p periodic. Integrated in the variable γ
// (tan(γ/2) = √((1+ε)/(1−ε)) tan(α/2)), from the thickest film (γ = ±π, p = 0):
//   ∫dα/(1−ε cos α)²       = s^{-3/2}(γ + ε sin γ),
//   ∫dα/(1−ε cos α)³       = s^{-5/2}((1 + ε²/2)γ + 2ε sin γ + (ε²/4) sin 2γ),
//   ∫cos α dα/(1−ε cos α)³ = s^{-5/2}((1 + ε²) sin γ + (3ε/2)γ + (ε/4) sin 2γ),
//   ∫sin α dα/(1−ε cos α)³ = s^{-2}(−cos γ − (ε/4) cos 2γ),      s = 1 − ε².
template <class T>
struct LongBearingState {
  T eps, psi, s, ur, ut, kappa;
};

template <class T>
LongBearingState<T> long_bearing_state(Real c, Real speed, const T& y, const T& z, const T& yd, const T& zd) {
  using detail::atan2, detail::cos, detail::sin, detail::sqrt;
  LongBearingState<T> st;
  st.eps = sqrt(y * y + z * z) / c;
  st.psi = atan2(z, y);
  st.s = 1.0 - st.eps * st.eps;
  const T cp = cos(st.psi), sp = sin(st.psi);
  st.ur = yd * cp + zd * sp;
  st.ut = zd * cp - yd * sp;
  st.kappa = -(speed * c * st.s + 3.0 * st.eps * st.ut) / (2.0 + st.eps * st.eps);
  return st;
}

// p at γ over 12μR²/c² (the pressure's scale), zero at γ = ±π.
template <class T>
T long_bearing_pressure(const LongBearingState<T>& st, Real c, Real speed, Real gamma) {
  using detail::pow;
  const T& e = st.eps;
  const Real sg = std::sin(gamma), s2g = std::sin(2.0 * gamma), cg = std::cos(gamma), c2g = std::cos(2.0 * gamma);
  const T s32 = pow(st.s, -1.5), s52 = pow(st.s, -2.5), s2 = pow(st.s, -2.0);
  // Each antiderivative minus its value at γ = π (where sin γ = sin 2γ = 0).
  const T a2 = s32 * ((gamma - pi) + e * sg);
  const T a3 = s52 * ((1.0 + 0.5 * e * e) * (gamma - pi) + 2.0 * e * sg + 0.25 * e * e * s2g);
  const T ac = s52 * ((1.0 + e * e) * sg + 1.5 * e * (gamma - pi) + 0.25 * e * s2g);
  const T as = s2 * (-cg - 0.25 * e * c2g - 1.0 + 0.25 * e);
  return 0.5 * speed * a2 + (st.kappa * a3 + st.ut * ac - st.ur * as) / c;
}

FilmForce long_bearing_force(const JournalBearingGeometry& g, Real speed, Vec2 x, const Vec2& v) {
  using D = detail::Dual<4>;
  const Real c = g.clearance, R = 0.5 * g.diameter;
  // At the very centre the displacement's direction is undefined: a displacement of
  // 1e-9 c changes the force by that fraction.
  if (x.norm() < 1e-9 * c) x = Vec2(1e-9 * c, 0.0);
  const LongBearingState<Real> plain = long_bearing_state<Real>(c, speed, x(0), x(1), v(0), v(1));
  const LongBearingState<D> dual =
      long_bearing_state<D>(c, speed, D::input(x(0), 0), D::input(x(1), 1), D::input(v(0), 2), D::input(v(1), 3));
  const auto p = [&](Real gamma) { return long_bearing_pressure(plain, c, speed, gamma); };
  // The intervals of γ in [−π, π] where p > 0: sign changes on a fine grid, refined by
  // Brent's method.
  constexpr int samples = 96;
  std::vector<std::pair<Real, Real>> positive;
  Real a = -pi, pa = 0.0, start = 0.0;
  bool inside = false;
  for (int i = 1; i <= samples; ++i) {
    const Real b = -pi + 2.0 * pi * i / samples, pb = i == samples ? 0.0 : p(b);
    if (!inside && pb > 0.0) {
      start = pa >= 0.0 ? a : brent_root(p, a, b, pa, pb, 1e-14, 200).x;
      inside = true;
    } else if (inside && !(pb > 0.0)) {
      positive.emplace_back(start, pb == 0.0 ? b : brent_root(p, a, b, pa, pb, 1e-14, 200).x);
      inside = false;
    }
    a = b;
    pa = pb;
  }
  // f = −RL ∫_{p>0} p (cos θ, sin θ) dθ, in γ with dα/dγ = √s/(1 + ε cos γ).
  const Real scale = -12.0 * g.viscosity * R * R * R * g.length / (c * c);
  const GaussLegendre& rule = film_rule();
  D fy(0.0), fz(0.0);
  const D k = detail::sqrt((1.0 + dual.eps) / (1.0 - dual.eps));
  // dα/dγ and the normal hold 1/(1 + ε cos γ) each, which peaks at the thickest
  // film as ε → 1: four panels per interval keep the rule at rounding to ε = 0.97.
  constexpr int panels = 4;
  for (const auto& [g1, g2] : positive) {
    for (int panel = 0; panel < panels; ++panel) {
      const Real width = (g2 - g1) / panels, half = 0.5 * width, mid = g1 + (panel + 0.5) * width;
      for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const Real gamma = mid + half * rule.nodes[j];
        // α(γ) = 2·atan2(sin(γ/2), k·cos(γ/2)) on (−π, π).
        const D alpha = 2.0 * detail::atan2(D(std::sin(0.5 * gamma)), k * std::cos(0.5 * gamma));
        const D w = (rule.weights[j] * half) * detail::sqrt(dual.s) / (1.0 + dual.eps * std::cos(gamma));
        const D pw = long_bearing_pressure(dual, c, speed, gamma) * w;
        fy += pw * detail::cos(alpha + dual.psi);
        fz += pw * detail::sin(alpha + dual.psi);
      }
    }
  }
  FilmForce out;
  out.f << scale * fy.v, scale * fz.v;
  for (int i = 0; i < 2; ++i) {
    out.dfdx(0, i) = scale * fy.d[static_cast<std::size_t>(i)];
    out.dfdx(1, i) = scale * fz.d[static_cast<std::size_t>(i)];
    out.dfdv(0, i) = scale * fy.d[static_cast<std::size_t>(i) + 2];
    out.dfdv(1, i) = scale * fz.d[static_cast<std::size_t>(i) + 2];
  }
  return out;
}

// The radial and tangential components of the steady force, (F_r, F_t), and their
// derivatives with respect to ε, over W₀ (film_load).
struct SteadyForce {
  Real fr, ft, dfr, dft;
};
SteadyForce steady_force(FilmTheory theory, Real e) {
  const Real e2 = e * e, s = 1.0 - e2;
  switch (theory) {
    case FilmTheory::short_bearing:
      return {4.0 * e2 / (s * s), pi * e / std::pow(s, 1.5), 8.0 * e * (1.0 + e2) / (s * s * s),
              pi * (1.0 + 2.0 * e2) / std::pow(s, 2.5)};
    case FilmTheory::long_bearing: {
      const Real q = 2.0 + e2, D = q * s;
      return {2.0 * e2 / D, pi * e / (q * std::sqrt(s)), (8.0 * e + 4.0 * e2 * e2 * e) / (D * D),
              pi * (2.0 - e2 + 2.0 * e2 * e2) / (q * q * std::pow(s, 1.5))};
    }
    case FilmTheory::finite_length:
      break;
  }
  throw Error(
      "the finite-length bearing has no closed form: its load and coefficients come from the numerical "
      "film force (film_force) at an equilibrium");
}

Real load_scale(const JournalBearingGeometry& g, FilmTheory theory, Real speed) {
  const Real c2 = g.clearance * g.clearance;
  switch (theory) {
    case FilmTheory::short_bearing:
      return g.viscosity * speed * g.diameter * std::pow(g.length, 3) / (8.0 * c2);
    case FilmTheory::long_bearing:
      return 6.0 * g.viscosity * speed * std::pow(0.5 * g.diameter, 3) * g.length / c2;
    case FilmTheory::finite_length:
      break;
  }
  throw Error("the finite-length bearing has no closed form");
}

}  // namespace

FilmForce film_force(const JournalBearingGeometry& g, FilmTheory theory, Real speed, const Vec2& x, const Vec2& v,
                     const FiniteBearingGrid& grid, bool trajectory) {
  const Real eps = x.norm() / g.clearance;
  if (!(eps < 1.0))
    throw Error(
        fmt::format("the journal has reached the bearing: eccentricity ratio {:.4g} (it must stay below 1)", eps));
  switch (theory) {
    case FilmTheory::short_bearing:
      return short_bearing_force(g, speed, x, v);
    case FilmTheory::long_bearing:
      return long_bearing_force(g, speed, x, v);
    case FilmTheory::finite_length:
      if (grid.evaluation == FilmEvaluation::table || (grid.evaluation == FilmEvaluation::automatic && trajectory)) {
        const auto table = FiniteBearingTable::shared(g.length / g.diameter, grid);
        FilmForce f;
        if (table->usable() && table->force(g, speed, x, v, f)) return f;
      }
      return finite_bearing_force(g, grid, speed, x, v);
  }
  return {};
}

Real film_load(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real eps) {
  const SteadyForce f = steady_force(theory, eps);
  return load_scale(g, theory, speed) * std::hypot(f.fr, f.ft);
}

Real film_attitude_angle(FilmTheory theory, Real eps) {
  const SteadyForce f = steady_force(theory, eps);
  return std::atan2(f.ft, f.fr);
}

Real film_eccentricity(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real load) {
  if (!(speed > 0.0)) throw Error("a fluid-film bearing carries a steady load only when the journal turns");
  if (load == 0.0) return 0.0;
  // W(ε) rises monotonically from 0 to ∞ on [0, 1).
  const auto f = [&](Real eps) { return film_load(g, theory, speed, eps) - load; };
  Real hi = 0.5;
  while (f(hi) < 0.0) hi = 0.5 * (1.0 + hi);
  return brent_root(f, 0.0, hi, -load, f(hi), 1e-15, 200).x;
}

BearingCoefficients film_coefficients(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real load) {
  const Real e = film_eccentricity(g, theory, speed, load), e2 = e * e, s = 1.0 - e2;
  if (e == 0.0) throw Error("an unloaded journal bearing has no coefficients at its centre");
  // In polar axes (r along the displacement, t turned by +90°) the steady force is
  // (−F_r(ε), F_t(ε)). A radial step moves along the curves, a tangential one turns
  // the force with the displacement: K = [[F_r′, F_t/e], [−F_t′, F_r/e]]. A
  // tangential velocity eψ̇ makes the film see Ω − 2ψ̇ (G holds Ω/2 − ψ̇), scaling the
  // force by (1 − 2ψ̇/Ω): C's second column is (2/(eΩ))(−F_r, F_t). A radial velocity ė
  // adds the squeeze pressure over the same part of the film: C's first column.
  const Real W0 = load_scale(g, theory, speed), c = g.clearance;
  const SteadyForce f = steady_force(theory, e);
  Mat2 K;
  Mat2 C = Mat2::Zero();
  K << f.dfr, f.ft / e, -f.dft, f.fr / e;
  K *= W0 / c;
  const Real ct = 2.0 * W0 / (c * speed);
  C(0, 1) = -ct * f.fr / e;
  C(1, 1) = ct * f.ft / e;
  switch (theory) {
    case FilmTheory::short_bearing: {
      // μRL³/c³ ∫ over the positive half of (cos α, sin α)·cos α/(1 − ε cos α)³.
      const Real q = 4.0 * W0 / (c * speed);
      C(0, 0) = q * pi * (1.0 + 2.0 * e2) / (2.0 * std::pow(s, 2.5));
      C(1, 0) = -q * 2.0 * e / (s * s);
      break;
    }
    case FilmTheory::long_bearing: {
      // (6μR³L/(εc³)) ∫_{−π}^{0} [(1 − ε cos α)^{-2} − (1 + ε)^{-2}](cos α, sin α) dα.
      const Real R = 0.5 * g.diameter, q = g.viscosity * R * R * R * g.length / (c * c * c);
      C(0, 0) = 6.0 * pi * q / std::pow(s, 1.5);
      C(1, 0) = -24.0 * q / ((1.0 + e) * (1.0 + e) * (1.0 - e));
      break;
    }
    case FilmTheory::finite_length:
      break;  // steady_force() has thrown
  }
  // The displacement lies at the attitude angle φ from the load: polar → load frame.
  const Real phi = std::atan2(f.ft, f.fr);
  Mat2 T;
  T << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  return {T * K * T.transpose(), T * C * T.transpose()};
}

std::vector<Index> FluidFilmBearing::nodes() const { return detail::lateral_nodes(node_a, node_b); }

std::vector<Index> FluidFilmBearing::dofs() const { return detail::lateral_dofs(node_a, node_b); }

namespace {

// The drag torque of a film whose force on the journal at e is F (above): the Couette
// shear over the whole film and the pressure's share.
Real film_drag_torque(const JournalBearingGeometry& g, Real speed, const Eigen::Vector2d& e, const FilmForce& F) {
  const Real R = g.diameter / 2, eps = e.norm() / g.clearance;
  const Real couette = 2 * pi * g.viscosity * R * R * R * g.length * speed / (g.clearance * std::sqrt(1 - eps * eps));
  return couette + 0.5 * (e(0) * F.f(1) - e(1) * F.f(0));
}

}  // namespace

Real FluidFilmBearing::drag_torque(const MotionState& s, const Vector& x, const Vector& v) const {
  const bool housing = node_b.has_value();
  const Eigen::Vector2d e = detail::relative(x, housing);
  return film_drag_torque(geometry, s.speed, e,
                          film_force(geometry, theory, s.speed, e, detail::relative(v, housing), grid, s.trajectory));
}

NonlinearForceValue FluidFilmBearing::force(const MotionState& s, const Vector& x, const Vector& v) const {
  const bool housing = node_b.has_value();
  const FilmForce F = film_force(geometry, theory, s.speed, detail::relative(x, housing), detail::relative(v, housing),
                                 grid, s.trajectory);
  return detail::pair_force(F.f, F.dfdx, F.dfdv, housing);
}

namespace {

// The largest value of p over α ∈ [0, 2π): the best of 180 samples (p has one
// positive lobe, far wider than 2°), then golden-section search between its neighbours
// to 1e-10 rad (50 steps): 230 evaluations per call, cheap enough for every sample of
// a run-up.
template <class P>
Real peak_over_angle(P&& p) {
  constexpr int n = 180;
  int best = 0;
  Real top = p(0.0);
  for (int i = 1; i < n; ++i)
    if (const Real v = p(2 * pi * i / n); v > top) top = v, best = i;
  const Real h = 2 * pi / n, ratio = 0.5 * (std::sqrt(5.0) - 1);
  Real lo = best * h - h, hi = best * h + h;
  Real x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo), f1 = p(x1), f2 = p(x2);
  for (int k = 0; k < 50; ++k) {
    if (f1 < f2)
      lo = x1, x1 = x2, f1 = f2, x2 = lo + ratio * (hi - lo), f2 = p(x2);
    else
      hi = x2, x2 = x1, f2 = f1, x1 = hi - ratio * (hi - lo), f1 = p(x1);
  }
  return std::max({top, f1, f2});
}

}  // namespace

Real short_bearing_peak_pressure(const JournalBearingGeometry& g, Real speed, const Eigen::Vector2d& x,
                                 const Eigen::Vector2d& v) {
  const Real mu = g.viscosity, L = g.length, c = g.clearance;
  const Real peak = peak_over_angle([&](Real a) {
    const Real ca = std::cos(a), sa = std::sin(a);
    const Real h = c - x(0) * ca - x(1) * sa;
    const Real h_a = x(0) * sa - x(1) * ca, h_t = -(v(0) * ca + v(1) * sa);
    return -3 * mu * L * L / (2 * h * h * h) * (0.5 * speed * h_a + h_t);
  });
  return std::max(peak, 0.0);
}

std::vector<OperatingValue> FluidFilmBearing::operating_data(const MotionState& s, const Vector& x,
                                                             const Vector& v) const {
  const bool housing = node_b.has_value();
  const Eigen::Vector2d e = detail::relative(x, housing), ev = detail::relative(v, housing);
  const FilmForce F = film_force(geometry, theory, s.speed, e, ev, grid, s.trajectory);
  const Real c = geometry.clearance, R = geometry.diameter / 2, eps = e.norm() / c;
  const Eigen::Vector2d load = -F.f;  // what the journal puts on the film
  const Real W = load.norm();
  const Real attitude = std::atan2(load(0) * e(1) - load(1) * e(0), load.dot(e));
  const Real N = s.speed / (2 * pi);
  const Real torque = film_drag_torque(geometry, s.speed, e, F);  // from the same film force
  Real peak = F.peak_pressure;  // the finite bearing's largest nodal pressure (or its table's)
  if (theory == FilmTheory::short_bearing) {
    peak = short_bearing_peak_pressure(geometry, s.speed, e, ev);
  } else if (theory == FilmTheory::long_bearing && ev.isZero(0.0)) {
    // Sommerfeld's pressure with θ from the thickest film, Gümbel's positive half.
    const Real mu = geometry.viscosity;
    peak = std::max(0.0, peak_over_angle([&](Real t) {
                      const Real ct = std::cos(t);
                      return 6 * mu * s.speed * (R / c) * (R / c) * eps * std::sin(t) * (2 + eps * ct) /
                             ((2 + eps * eps) * (1 + eps * ct) * (1 + eps * ct));
                    }));
  }
  return {
      {"eccentricity_ratio", eps},
      {"attitude_angle_deg", W > 0 && eps > 0 ? attitude * 180 / pi : std::numeric_limits<Real>::quiet_NaN()},
      {"min_film_thickness_m", c * (1 - eps)},
      {"min_film_angle_deg", eps > 0 ? std::atan2(e(1), e(0)) * 180 / pi : std::numeric_limits<Real>::quiet_NaN()},
      {"load_n", W},
      {"sommerfeld_number", W > 0 ? geometry.viscosity * N * geometry.length * geometry.diameter / W * (R / c) * (R / c)
                                  : std::numeric_limits<Real>::infinity()},
      {"friction_torque_nm", torque},
      {"power_loss_w", torque * s.speed},
      {"peak_pressure_pa", peak},
      // The design limits of Trumpler ("Design of Film Bearings", 1966): a unit
      // load W/(L·D) of at most 2.07 MPa (300 psi) and a minimum film thickness of
      // at least 0.0002 in + 0.00004·D (5.08 µm + 4e-5·D).
      {"specific_load_pa", W / (geometry.length * geometry.diameter)},
      {"specific_load_limit_pa", trumpler_specific_load_limit},
      {"min_film_limit_m", trumpler_min_film(geometry.diameter)}};
}

}  // namespace feran

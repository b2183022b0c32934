#include <feran/integrators/w_method.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// A factorisation made for h_T is reused for steps h with |h − h_T| ≤ 3 % of h_T
// (OrdinaryDiffEq.jl's W-method rule); the method uses T scaled by h_T/h, so it stays
// consistent, and stability is that of a Jacobian off by at most 3 %.
constexpr Real step_reuse_tolerance = 0.03;
// Step-size controller: safety factor and bounds of the change per step.
constexpr Real safety = 0.9;
constexpr Real max_growth = 5.0;
constexpr Real max_shrink = 0.2;
// A proposed step within [1, keep_band] times the current one keeps the current step,
// so its factorisation is reused instead of redone for a few per cent more step.
constexpr Real keep_band = 1.2;

}  // namespace

WTableau WTableau::wolfbrandt() {
  WTableau t;
  t.name = "wolfbrandt";
  t.gamma = 1.0 - std::sqrt(2.0) / 2.0;
  t.alpha = Matrix::Zero(2, 2);
  t.gamma_ij = Matrix::Zero(2, 2);
  t.alpha(1, 0) = 2.0 / 3.0;
  t.gamma_ij(1, 0) = -4.0 * t.gamma / 3.0;
  t.b = Vector{{0.25, 0.75}};
  t.order = 2;
  return t;
}

WTableau WTableau::ros34pw2() {
  WTableau t;
  t.name = "ros34pw2";
  t.gamma = 0.43586652150845900;
  t.alpha = Matrix::Zero(4, 4);
  t.gamma_ij = Matrix::Zero(4, 4);
  t.alpha(1, 0) = 0.87173304301691801;
  t.alpha(2, 0) = 0.84457060015369423;
  t.alpha(2, 1) = -0.11299064236484185;
  t.alpha(3, 2) = 1.0;
  t.gamma_ij(1, 0) = -0.87173304301691801;
  t.gamma_ij(2, 0) = -0.90338057013044082;
  t.gamma_ij(2, 1) = 0.054180672388095326;
  t.gamma_ij(3, 0) = 0.24212380706095346;
  t.gamma_ij(3, 1) = -1.2232505839045147;
  t.gamma_ij(3, 2) = 0.54526025533510214;
  t.b = Vector{{0.24212380706095346, -1.2232505839045147, 1.5452602553351020, 0.43586652150845900}};
  t.b_hat = Vector{{0.37810903145819369, -0.096042292212423178, 0.5, 0.21793326075422950}};
  t.order = 3;
  t.embedded_order = 2;
  return t;
}

WMethod::WMethod(WTableau tableau, const IntegratorSettings& settings, bool adaptive)
    : tableau_(std::move(tableau)), settings_(settings), adaptive_(adaptive) {
  const Index s = tableau_.stages();
  const std::string& nm = tableau_.name;
  if (s < 1 || tableau_.alpha.rows() != s || tableau_.alpha.cols() != s || tableau_.gamma_ij.rows() != s ||
      tableau_.gamma_ij.cols() != s || (tableau_.b_hat.size() != 0 && tableau_.b_hat.size() != s))
    throw Error(fmt::format("{}: inconsistent W-method coefficients", nm));
  if (!(tableau_.gamma > 0.0)) throw Error(fmt::format("{}: the diagonal gamma must be positive", nm));
  if (adaptive_ && tableau_.b_hat.size() == 0)
    throw Error(fmt::format("{}: adaptive stepping needs an embedded method", nm));
  if (!(settings_.dt > 0.0)) throw Error(fmt::format("{}: dt must be positive (got {})", nm, settings_.dt));
  if (settings_.jacobian_interval < 1)
    throw Error(fmt::format("{}: jacobian_interval must be at least 1 (got {})", nm, settings_.jacobian_interval));
  if (adaptive_) {
    if (!(settings_.rel_tol >= 0.0 && settings_.abs_tol >= 0.0) ||
        !(settings_.rel_tol > 0.0 || settings_.abs_tol > 0.0))
      throw Error(
          fmt::format("{}: tolerances must be non-negative and not both zero "
                      "(rel_tol = {}, abs_tol = {})",
                      nm, settings_.rel_tol, settings_.abs_tol));
    if (!(settings_.dt_min > 0.0) || !(settings_.dt_min <= settings_.dt_max))
      throw Error(fmt::format("{}: need 0 < dt_min <= dt_max (dt_min = {}, dt_max = {})", nm, settings_.dt_min,
                              settings_.dt_max));
  }
  c_ = tableau_.alpha.rowwise().sum();
  if (tableau_.b_hat.size() == s) b_error_ = tableau_.b - tableau_.b_hat;
  kq_.resize(static_cast<std::size_t>(s));
  kv_.resize(static_cast<std::size_t>(s));
}

StepReport WMethod::start(SecondOrderSystem& sys, State& s) {
  StepReport report = detail::initial_acceleration(name(), sys, s, r_);
  if (!report.ok) return report;
  jacobian_set_ = false;
  jacobian_current_ = false;
  steps_since_jacobian_ = 0;
  factored_ = false;
  report.dt = settings_.dt;
  report.dt_next = adaptive_ ? std::clamp(settings_.dt, settings_.dt_min, settings_.dt_max) : settings_.dt;
  return report;
}

bool WMethod::prepare(SecondOrderSystem& sys, const State& s, Real h, bool after_rejection, StepReport& report) {
  bool refactor = !factored_ || std::abs(h - h_factored_) > step_reuse_tolerance * h_factored_;
  if (!jacobian_set_ || steps_since_jacobian_ >= settings_.jacobian_interval ||
      (after_rejection && !jacobian_current_)) {
    sys.set_jacobian(s.t, s.x, s.v, settings_.exact_jacobian);
    jacobian_set_ = true;
    jacobian_current_ = true;
    steps_since_jacobian_ = 0;
    refactor = true;
  }
  if (!refactor) return true;
  const Real hg = h * tableau_.gamma;
  ++report.factorizations;
  factored_ = sys.factor_tangent(hg * hg, hg, 1.0);
  h_factored_ = h;
  return factored_;
}

void WMethod::stages(SecondOrderSystem& sys, const State& s, Real h) {
  const Index n_stages = tableau_.stages();
  const Real hT = h_factored_;
  const Real hTg = hT * tableau_.gamma;
  for (Index i = 0; i < n_stages; ++i) {
    const auto si = static_cast<std::size_t>(i);
    // Stage value Y_i and right-hand side r(Y_i); r(y_n) = M·a_n.
    if (i == 0) {
      sys.mass_times(s.a, r_);
      yv_ = s.v;
    } else {
      yq_ = s.x;
      yv_ = s.v;
      for (Index j = 0; j < i; ++j) {
        const Real a = tableau_.alpha(i, j);
        if (a == 0.0) continue;
        yq_ += a * kq_[static_cast<std::size_t>(j)];
        yv_ += a * kv_[static_cast<std::size_t>(j)];
      }
      sys.rhs(s.t + c_(i) * h, yq_, yv_, r_);
    }
    // g = Σ γ_ij k_j.
    bool has_g = false;
    for (Index j = 0; j < i; ++j) {
      const Real g = tableau_.gamma_ij(i, j);
      if (g == 0.0) continue;
      const auto sj = static_cast<std::size_t>(j);
      if (!has_g) {
        gq_ = g * kq_[sj];
        gv_ = g * kv_[sj];
        has_g = true;
      } else {
        gq_ += g * kq_[sj];
        gv_ += g * kv_[sj];
      }
    }
    // r_q = h·V_i + h_T·g_v (kept in kq_[i]); right-hand side of the condensed solve
    // h·r(Y_i) − h_T·D_T·g_v − K_T·(h_T·g_q + h_Tγ·r_q).
    Vector& kq = kq_[si];
    Vector& kv = kv_[si];
    rhs_ = h * r_;
    if (has_g) {
      kq = h * yv_ + hT * gv_;
      sys.damping_times(gv_, work_);
      rhs_ -= hT * work_;
      work2_ = hT * gq_ + hTg * kq;
    } else {
      kq = h * yv_;
      work2_ = hTg * kq;
    }
    sys.stiffness_times(work2_, work_);
    rhs_ -= work_;
    sys.solve_tangent(rhs_, kv);
    kq += hTg * kv;
  }
  x_new_ = s.x;
  v_new_ = s.v;
  for (Index i = 0; i < n_stages; ++i) {
    const auto si = static_cast<std::size_t>(i);
    x_new_ += tableau_.b(i) * kq_[si];
    v_new_ += tableau_.b(i) * kv_[si];
  }
  if (!adaptive_) return;
  eq_.setZero(s.x.size());
  ev_.setZero(s.x.size());
  for (Index i = 0; i < n_stages; ++i) {
    const auto si = static_cast<std::size_t>(i);
    eq_ += b_error_(i) * kq_[si];
    ev_ += b_error_(i) * kv_[si];
  }
}

Real WMethod::error_norm(const State& s) const {
  Real sum = 0.0;
  const Real atol = settings_.abs_tol;
  const Real rtol = settings_.rel_tol;
  for (Index i = 0; i < s.x.size(); ++i) {
    const Real sx = atol + rtol * std::max(std::abs(s.x(i)), std::abs(x_new_(i)));
    const Real sv = atol + rtol * std::max(std::abs(s.v(i)), std::abs(v_new_(i)));
    const Real ex = eq_(i) / sx;
    const Real ev = ev_(i) / sv;
    sum += ex * ex + ev * ev;
  }
  const Real err = std::sqrt(sum / static_cast<Real>(2 * s.x.size()));
  return err;
}

void WMethod::commit(SecondOrderSystem& sys, State& s, Real h) {
  s.t += h;
  s.x.swap(x_new_);
  s.v.swap(v_new_);
  sys.rhs(s.t, s.x, s.v, r_);
  sys.solve_mass(r_, s.a);
  ++steps_since_jacobian_;
  jacobian_current_ = false;
}

StepReport WMethod::step(SecondOrderSystem& sys, State& s, Real dt) {
  StepReport report;
  if (!adaptive_) {
    report.dt = dt;
    report.dt_next = dt;
    if (!prepare(sys, s, dt, false, report)) {
      report.ok = false;
      report.message = fmt::format(
          "{}: singular stage matrix M + h*gamma*D_T + (h*gamma)^2*K_T at "
          "t = {:.9g} (dt = {:.6g})",
          name(), s.t, dt);
      return report;
    }
    stages(sys, s, dt);
    commit(sys, s, dt);
    return report;
  }

  Real h = std::min(dt, settings_.dt_max);
  for (;;) {
    Real err = std::numeric_limits<Real>::infinity();
    if (prepare(sys, s, h, report.rejected > 0, report)) {
      stages(sys, s, h);
      err = error_norm(s);
    }
    if (err <= 1.0) {
      Real factor = err > 0.0 ? safety * std::pow(err, -1.0 / 3.0) : max_growth;
      factor = std::clamp(factor, max_shrink, report.rejected > 0 ? 1.0 : max_growth);
      if (factor >= 1.0 && factor <= keep_band) factor = 1.0;
      report.dt = h;
      report.dt_next = std::clamp(h * factor, settings_.dt_min, settings_.dt_max);
      commit(sys, s, h);
      return report;
    }
    ++report.rejected;
    // err > 1, so the factor is below the safety factor; NaN or ∞ gives max_shrink.
    const Real factor = std::isfinite(err) ? std::max(max_shrink, safety * std::pow(err, -1.0 / 3.0)) : max_shrink;
    Real h_new = h * factor;
    if (h_new < settings_.dt_min) {
      if (h > settings_.dt_min) {
        h_new = settings_.dt_min;
      } else {
        report.ok = false;
        report.dt = h;
        report.dt_next = h;
        report.message = fmt::format(
            "{}: error test failed at the minimum step dt_min = {:.6g} s at t = {:.9g} s "
            "(scaled error estimate {:.3g} > 1 after {} rejected tries); loosen rel_tol/abs_tol "
            "or lower dt_min",
            name(), settings_.dt_min, s.t, err, report.rejected);
        return report;
      }
    }
    h = h_new;
  }
}

}  // namespace feran

// A run of the condensed rotor at constant speed until it settles, and the orbit it
// settled on (settle.hpp): BDF2 with Newton's method on the forces' own Jacobians, the
// settling judged window by window, the period from the mean crossings, the orbit's
// coefficients from one period sampled by Hermite interpolation of the steps
// (integrators/second_order_system.hpp).
#include <feran/analyses/periodic/settle.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/integrators/second_order_system.hpp>

namespace feran {

namespace {

// M ẍ + C ẋ + K x = f_e(t) + f(t, x, ẋ), f_e = c₀ + a₁ cos Ωt + b₁ sin Ωt, stepped by
// BDF2 (its first step, and a step that fails, by backward Euler).
class Stepper {
 public:
  Stepper(const PeriodicSystem& s, Real speed, Real length) : s_(s), speed_(speed), length_(length) {
    const Index n = s.M.rows();
    c0_ = s.external.head(n);
    if (s.external.size() >= 3 * n) {
      a1_ = s.external.segment(n, n);
      b1_ = s.external.segment(2 * n, n);
    } else {
      a1_ = b1_ = Vector::Zero(n);
    }
    dofs_ = s.force_dofs;
    if (dofs_.empty() && s.force)
      for (Index i = 0; i < n; ++i) dofs_.push_back(i);
  }

  // (x, v) at t advanced by dt; (xp, vp) the state at t − dt when @p bdf2.
  void step(Real t, Real dt, Vector& x, Vector& v, const Vector& xp, const Vector& vp, bool bdf2) const {
    Vector xn = x, vn = v;
    if (bdf2 && solve(t + dt, 2.0 * dt / 3.0, (4.0 * x - xp) / 3.0, (4.0 * v - vp) / 3.0, xn, vn)) {
      x = xn, v = vn;
      return;
    }
    // Backward Euler in ten sub-steps: slower, but it starts where BDF2 has no history
    // and takes the steps a contact's sudden stiffness makes Newton's method miss.
    const int parts = bdf2 ? 10 : 1;
    const Real h = dt / parts;
    for (int k = 1; k <= parts; ++k) {
      xn = x + h * v;
      if (!solve(t + k * h, h, x, v, xn, vn))
        throw Error(fmt::format(
            "periodic orbits: the run's time step did not converge at t = {:.6g} s (the motion at {:.3g} m, "
            "the length scale {:.3g} m)",
            t + k * h, x.cwiseAbs().maxCoeff(), length_));
      x = xn, v = vn;
    }
  }

 private:
  // x = x̂ + h·v, M(v − v̂)/h + C v + K x = f_e(t) + f(t, x, v), for x from its guess.
  bool solve(Real t, Real h, const Vector& xh, const Vector& vh, Vector& x, Vector& v) const {
    const Vector fe = c0_ + std::cos(speed_ * t) * a1_ + std::sin(speed_ * t) * b1_;
    const Matrix J0 = s_.M / (h * h) + s_.C / h + s_.K;
    const Index nf = static_cast<Index>(dofs_.size());
    Vector xf(nf), vf(nf);
    for (int it = 0; it < 30; ++it) {
      v = (x - xh) / h;
      Vector r = s_.M * ((v - vh) / h) + s_.C * v + s_.K * x - fe;
      Matrix J = J0;
      if (s_.force) {
        for (Index i = 0; i < nf; ++i) xf(i) = x(dofs_[i]), vf(i) = v(dofs_[i]);
        const NonlinearForceValue f = s_.force(t, xf, vf);
        for (Index i = 0; i < nf; ++i) {
          r(dofs_[i]) -= f.f(i);
          for (Index j = 0; j < nf; ++j)
            J(dofs_[i], dofs_[j]) -= f.dfdx(i, j) + (f.dfdv.size() != 0 ? f.dfdv(i, j) / h : 0.0);
        }
      }
      if (!r.allFinite()) return false;
      const Vector dx = Eigen::PartialPivLU<Matrix>(J).solve(r);
      x -= dx;
      if (!dx.allFinite()) return false;
      if (dx.norm() <= 1e-11 * (x.norm() + length_)) {
        v = (x - xh) / h;
        return true;
      }
    }
    return false;
  }

  const PeriodicSystem& s_;
  Real speed_, length_;
  Vector c0_, a1_, b1_;
  std::vector<Index> dofs_;
};

}  // namespace

SettledOrbit settle_orbit(const RotorFamily& family, Real p, const OrbitSettings& settings, const SettleSettings& run) {
  const CondensedRotor& rotor = family.at(p);
  const Real speed = family.speed(p);
  if (!(speed > 0))
    throw Error("periodic orbits: a run settles on an orbit at a rotor speed above 0 (the revolutions time it)");
  const FourierBasis& fourier = settings.fourier;
  fourier.check();
  const Index n = rotor.size(), H = fourier.harmonics;
  const Real L = length_scale(family, settings);
  const bool forced = rotor.forced();
  const PeriodicSystem system = rotor.at(speed, speed, FourierBasis{.harmonics = 1, .samples = 3});
  const Stepper stepper(system, speed, L);

  // The start: the equilibrium (the centre when it is not found), the nonlinear forces'
  // coordinates displaced by L/100.
  Vector x = Vector::Zero(n), v = Vector::Zero(n);
  try {
    x = rotor.static_equilibrium(speed);
  } catch (const Error&) {
    x.setZero();
  }
  for (const Index i : rotor.force_coordinates()) x(i) += 0.01 * L;
  const Real disturbance =
      0.01 * L * std::sqrt(static_cast<Real>(std::max<std::size_t>(1, rotor.force_coordinates().size())));

  const Index steps = std::max<Index>(run.steps, 8);
  const Real revolution = 2.0 * pi / speed, dt = revolution / static_cast<Real>(steps);
  const Real duration = run.duration > 0 ? run.duration : 2000.0 * revolution;
  const Index window = std::max<Index>(run.window, 2) * steps;
  if (duration < 2.0 * static_cast<Real>(window) * dt)
    throw Error(fmt::format(
        "periodic orbits: a run of {:.4g} s is shorter than the {} revolutions ({:.4g} s) it needs to tell whether "
        "its motion repeats (two windows of {})",
        duration, 2 * window / steps, 2.0 * static_cast<Real>(window) * dt, window / steps));
  const std::string where = family.is_speed() ? fmt::format("{:.6g} rad/s ({:.6g} rpm)", p, p * 30.0 / pi)
                                              : fmt::format("{} = {:.6g}", family.name(), p);

  // The steps of the current window, kept for the period and the sampling.
  std::vector<State> kept;
  Vector xp = x, vp = v;
  Index i = 0;
  bool history = false;
  const auto advance = [&] {
    const Vector x0 = x, v0 = v;
    stepper.step(static_cast<Real>(i) * dt, dt, x, v, xp, vp, history);
    xp = x0, vp = v0;
    history = true;
    ++i;
    for (const Index c : rotor.force_coordinates())
      if (!(std::abs(x(c)) <= 100.0 * L))
        throw Error(fmt::format(
            "periodic orbits: the run at {} grows beyond a hundred times the length scale ({:.3g} m) by t = {:.4g} "
            "s: the rotor has no bounded motion there to settle on",
            where, L, static_cast<Real>(i) * dt));
  };
  const auto keep = [&] { kept.push_back(State{.t = static_cast<Real>(i) * dt, .x = x, .v = v, .a = {}}); };
  Vector range_before, mean_before;
  Real settled_at = -1, ratio = 1;  // ratio: the extent's growth over the last window
  while (settled_at < 0) {
    if (static_cast<Real>(i) * dt >= duration) {
      const Index w = window / steps;
      const std::string how =
          ratio < 1 - run.tolerance
              ? fmt::format("{}, its extent shrinking by a factor {:.4g} every {} revolutions ({})",
                            forced ? "its free vibration was still dying out" : "it was still dying out", ratio, w,
                            forced ? "a barely damped mode" : "the equilibrium is stable there but barely damped")
          : ratio > 1 + run.tolerance
              ? fmt::format("it was still growing, by a factor {:.4g} every {} revolutions", ratio, w)
              : fmt::format(
                    "its extent over {} revolutions still changed by more than {:g} (a beat: a motion with two "
                    "frequencies)",
                    w, run.tolerance);
      throw Error(
          fmt::format("periodic orbits: the run at {} had not settled after {:.4g} s ({:.0f} revolutions): {}; "
                      "a longer run (settle) may tell",
                      where, duration, duration / revolution, how));
    }
    if (run.watch && !run.watch(static_cast<Real>(i) * dt, duration)) throw Error("stopped");
    kept.clear();
    keep();
    Vector lo = x, hi = x, sum = Vector::Zero(n);
    for (Index k = 0; k < window; ++k) {
      advance();
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x), sum += x;
      keep();
    }
    const Vector range = hi - lo, mean = sum / static_cast<Real>(window);
    if (!forced && range.norm() < 1e-6 * disturbance)
      throw Error(fmt::format(
          "periodic orbits: the run at {} dies out onto the static equilibrium (stable there): it settles on no "
          "orbit; a run where the equilibrium is unstable, or beyond a self-excited branch's fold, finds one",
          where));
    if (range_before.size() != 0 && (range - range_before).norm() <= run.tolerance * range.norm() &&
        (mean - mean_before).norm() <= run.tolerance * range.norm())
      settled_at = static_cast<Real>(i) * dt;
    if (range_before.size() != 0 && range_before.norm() > 0) ratio = range.norm() / range_before.norm();
    range_before = range, mean_before = mean;
  }

  // The period: the rotor's, or from the upward crossings of the middle of its extent by
  // the coordinate that moves most, over the last window.
  Real T = revolution;
  if (!forced) {
    Index j = 0;
    range_before.maxCoeff(&j);
    Real lo = kept[0].x(j), hi = lo;
    for (const State& s : kept) lo = std::min(lo, s.x(j)), hi = std::max(hi, s.x(j));
    const Real middle = 0.5 * (lo + hi);
    std::vector<Real> up;
    for (std::size_t k = 1; k < kept.size(); ++k) {
      const Real a = kept[k - 1].x(j) - middle, b = kept[k].x(j) - middle;
      if (a < 0 && b >= 0) up.push_back(kept[k - 1].t + (kept[k].t - kept[k - 1].t) * a / (a - b));
    }
    if (up.size() < 3)
      throw Error(fmt::format(
          "periodic orbits: the run at {} settled on a motion slower than a tenth of the rotor speed: its period "
          "is not told within {} revolutions",
          where, window / steps));
    T = (up.back() - up.front()) / static_cast<Real>(up.size() - 1);
  }

  // Two more periods, kept; the second sampled at N equal phases.
  kept.clear();
  keep();
  const Real t0 = kept.front().t;
  while (kept.back().t < t0 + 2.0 * T + dt) {
    advance();
    keep();
  }
  const auto at = [&](Real t) {
    const auto k =
        static_cast<std::size_t>(std::clamp<Real>(std::floor((t - t0) / dt), 0.0, static_cast<Real>(kept.size() - 2)));
    Vector xt, vt;
    interpolate(kept[k], kept[k + 1], t, xt, vt);
    return xt;
  };
  const Index N = std::max<Index>(steps, 4 * fourier.samples);
  const Real t1 = t0 + T;
  Matrix samples(n, N);
  for (Index k = 0; k < N; ++k) samples.col(k) = at(t1 + T * static_cast<Real>(k) / static_cast<Real>(N));
  const Vector extent = samples.rowwise().maxCoeff() - samples.rowwise().minCoeff();
  SettledOrbit out;
  out.kind = forced ? OrbitBranch::Kind::forced : OrbitBranch::Kind::self_excited;
  out.time = settled_at;
  out.mismatch = (at(t1 + T) - at(t1)).norm() / std::max(extent.norm(), 1e-300);
  if (out.mismatch > 1e-2)
    throw Error(fmt::format(
        "periodic orbits: the run at {} settles on a motion that does not repeat after one period of {:.5g} s "
        "(it differs by {:.2g} of its extent){}",
        where, T, out.mismatch,
        forced ? ": a whirl together with the unbalance is quasi-periodic, and a doubled period is not an orbit "
                 "at the rotor speed; neither is computed"
               : ""));
  // The discrete Fourier transform of the period (phase 0 at t1, a whole number of
  // revolutions for a forced orbit: the rotor's angle is the orbit's phase).
  Vector X = Vector::Zero(n * fourier.terms());
  for (Index k = 0; k < N; ++k) {
    const Real theta = 2.0 * pi * static_cast<Real>(k) / static_cast<Real>(N);
    X.head(n) += samples.col(k) / static_cast<Real>(N);
    for (Index h = 1; h <= H; ++h) {
      const Real angle = static_cast<Real>(h) * theta;
      X.segment((2 * h - 1) * n, n) += samples.col(k) * (2.0 * std::cos(angle) / static_cast<Real>(N));
      X.segment(2 * h * n, n) += samples.col(k) * (2.0 * std::sin(angle) / static_cast<Real>(N));
    }
  }
  out.start.parameter = p;
  out.start.speed = speed;
  out.start.frequency = 2.0 * pi / T;
  out.start.X = std::move(X);
  return out;
}

}  // namespace feran

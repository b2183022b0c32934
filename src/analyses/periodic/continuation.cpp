#include <feran/analyses/periodic/continuation.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/LU>
#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

Real relative(const BranchEquations& e) { return e.G.norm() / (e.scale > 0 ? e.scale : 1.0); }

// [[Ĝu, Ĝp], [rowᵀ]], the bordered Jacobian in scaled variables.
Matrix bordered(const BranchEquations& e, const Vector& u_scale, Real p_scale, const Vector& row) {
  const Index m = e.G.size();
  Matrix B(m + 1, m + 1);
  B.topLeftCorner(m, m) = e.Gu * u_scale.asDiagonal();
  B.topRightCorner(m, 1) = e.Gp * p_scale;
  B.bottomRows(1) = row.transpose();
  return B;
}

Vector scaled(const Vector& u, Real p, const Vector& u_scale, Real p_scale) {
  Vector z(u.size() + 1);
  z.head(u.size()) = u.cwiseQuotient(u_scale);
  z(u.size()) = p / p_scale;
  return z;
}

// The unit tangent at a point, oriented along @p reference (its sign: t·reference > 0).
Vector tangent_at(const BranchEquations& e, const Vector& u_scale, Real p_scale, const Vector& reference) {
  const Index m = e.G.size();
  Vector rhs = Vector::Zero(m + 1);
  rhs(m) = 1.0;
  Vector t = Eigen::PartialPivLU<Matrix>(bordered(e, u_scale, p_scale, reference)).solve(rhs);
  if (!t.allFinite() || t.norm() == 0) {
    // The reference lies in the branch's normal space: try the unknowns' axis of
    // the reference's largest entry instead.
    Vector alt = Vector::Zero(m + 1);
    Index at = 0;
    reference.cwiseAbs().maxCoeff(&at);
    alt(at == m ? 0 : m) = 1.0;
    t = Eigen::PartialPivLU<Matrix>(bordered(e, u_scale, p_scale, alt)).solve(rhs);
  }
  t.normalize();
  if (t.dot(reference) < 0) t = -t;
  return t;
}

struct Corrected {
  BranchPoint point;
  bool converged = false;
  std::string refused;  // the model's reason when it could not be evaluated there
};

// Newton on G = 0 with tᵀ(ẑ − ẑ_pred) = 0.
Corrected correct(const BranchFunction& G, const Vector& predicted, const Vector& t, const Vector& u_scale,
                  Real p_scale, const ContinuationSettings& s) {
  const Index m = u_scale.size();
  Vector z = predicted;
  Corrected out;
  for (int it = 0; it <= s.max_iterations; ++it) {
    const Vector u = z.head(m).cwiseProduct(u_scale);
    const Real p = z(m) * p_scale;
    BranchEquations e;
    try {
      e = G(u, p);
    } catch (const Error& error) {
      out.refused = error.what();
      return out;  // outside the model's domain (a journal at its wall): a shorter step
    }
    const Real r = relative(e);
    if (!std::isfinite(r)) return out;
    out.point = BranchPoint{.u = u, .p = p, .tangent = t, .iterations = it, .residual = r};
    if (r <= s.tolerance) {
      out.converged = true;
      out.point.tangent = tangent_at(e, u_scale, p_scale, t);
      return out;
    }
    if (it == s.max_iterations) return out;
    Vector rhs(m + 1);
    rhs.head(m) = e.G;
    rhs(m) = t.dot(z - predicted);
    const Vector step = Eigen::PartialPivLU<Matrix>(bordered(e, u_scale, p_scale, t)).solve(rhs);
    if (!step.allFinite()) return out;
    z -= step;
  }
  return out;
}

}  // namespace

BranchPoint correct_at_fixed_parameter(const BranchFunction& G, const Vector& u0, Real p0,
                                       const ContinuationSettings& settings) {
  BranchPoint point{.u = u0, .p = p0, .tangent = {}, .iterations = 0, .residual = 0.0};
  BranchEquations e = G(point.u, p0);
  point.residual = relative(e);
  while (point.residual > settings.tolerance && point.iterations < 4 * settings.max_iterations) {
    const Vector step = Eigen::PartialPivLU<Matrix>(e.Gu).solve(e.G);
    if (!step.allFinite()) break;
    ++point.iterations;
    // Halve the step until the residual falls.
    Real f = 1.0;
    for (int halving = 0; halving <= 20; ++halving, f *= 0.5) {
      const Vector trial = point.u - f * step;
      BranchEquations next;
      try {
        next = G(trial, p0);
      } catch (const Error&) {
        continue;
      }
      if (relative(next) < point.residual || halving == 20) {
        point.u = trial;
        e = std::move(next);
        break;
      }
    }
    point.residual = relative(e);
  }
  return point;
}

Branch continue_branch(const BranchFunction& G, const BranchPoint& start, const Vector& direction, Real towards,
                       const Vector& u_scale, Real p_scale, const ContinuationSettings& settings,
                       const std::function<bool(const Branch&)>& monitor) {
  const Index m = start.u.size();
  if (u_scale.size() != m || !(p_scale > 0) || !(u_scale.array() > 0).all())
    throw Error("continuation: the scales must be positive, one per unknown");
  Branch branch;
  BranchPoint first = start;
  {
    Vector reference = direction;
    if (reference.size() != m + 1) {
      reference = Vector::Zero(m + 1);
      reference(m) = towards < 0 ? -1.0 : 1.0;
    }
    first.tangent = tangent_at(G(start.u, start.p), u_scale, p_scale, reference);
    if (direction.size() == m + 1) first.tangent = direction.normalized();
  }
  branch.points.push_back(first);
  const bool bounded = settings.p_max > settings.p_min;
  Real h = settings.step;
  while (static_cast<Index>(branch.points.size()) < settings.max_points) {
    const BranchPoint& last = branch.points.back();
    const Vector z = scaled(last.u, last.p, u_scale, p_scale);
    if (const Real tp = std::abs(last.tangent(m)); settings.max_parameter_step > 0 && tp > 0)
      h = std::max(settings.min_step, std::min(h, settings.max_parameter_step / tp));
    Corrected next;
    Real residual = 0.0;
    while (true) {
      next = correct(G, z + h * last.tangent, last.tangent, u_scale, p_scale, settings);
      if (next.converged) break;
      residual = next.point.residual;
      h *= 0.5;
      if (h < settings.min_step && !next.refused.empty()) {
        branch.ended_by = fmt::format(
            "the branch could not be continued beyond p = {:.8g}: the model cannot be evaluated just beyond it: {}",
            last.p, next.refused);
        return branch;
      }
      if (h < settings.min_step) {
        branch.ended_by = fmt::format(
            "the branch could not be continued beyond p = {:.8g}: the corrector did not converge even with the "
            "smallest step (residual {:.3g}); a turning point too sharp for the steps allowed, a branch point, or "
            "a solution the model cannot follow (more harmonics, or another parameter, may help)",
            last.p, residual);
        return branch;
      }
    }
    BranchPoint point = std::move(next.point);
    // The step follows the corrector's effort.
    if (point.iterations < settings.target_iterations)
      h = std::min(settings.max_step, 1.5 * h);
    else if (point.iterations > settings.target_iterations)
      h = std::max(settings.min_step, 0.6 * h);
    if (bounded && (point.p > settings.p_max || point.p < settings.p_min)) {
      // The limit crossed: the point on it, from the interpolation between the two.
      const Real limit = point.p > settings.p_max ? settings.p_max : settings.p_min;
      const Real f = (limit - last.p) / (point.p - last.p);
      try {
        BranchPoint end = correct_at_fixed_parameter(G, last.u + f * (point.u - last.u), limit, settings);
        if (end.residual <= settings.tolerance) {
          end.tangent = tangent_at(G(end.u, end.p), u_scale, p_scale, point.tangent);
          branch.points.push_back(std::move(end));
        }
      } catch (const Error&) {
        // The model cannot be evaluated at the limit itself: the branch ends at the
        // last point before it (the range was reached all the same).
      }
      branch.ended_by = "range";
      if (monitor) static_cast<void>(monitor(branch));
      return branch;
    }
    branch.points.push_back(std::move(point));
    if (monitor && !monitor(branch)) {
      branch.ended_by = "stopped";
      return branch;
    }
  }
  branch.ended_by = "points";
  return branch;
}

BranchPoint locate_on_branch(const BranchFunction& G, const BranchPoint& a, const BranchPoint& b, const Vector& u_scale,
                             Real p_scale, const ContinuationSettings& settings,
                             const std::function<Real(const BranchPoint&)>& tau, Real tolerance) {
  const Vector za = scaled(a.u, a.p, u_scale, p_scale), zb = scaled(b.u, b.p, u_scale, p_scale);
  const Vector& t = a.tangent;
  Real s0 = 0.0, s1 = t.dot(zb - za), f0 = tau(a), f1 = tau(b);
  BranchPoint best = std::abs(f0) < std::abs(f1) ? a : b;
  if (f0 == 0.0) return a;
  if (f1 == 0.0) return b;
  int side = 0;  // the end kept last time (Illinois: halve the other's value when kept twice)
  for (int trial = 0; trial < 40 && std::abs(s1 - s0) > tolerance * std::abs(t.dot(zb - za)); ++trial) {
    const Real s = s1 - f1 * (s1 - s0) / (f1 - f0);
    const Corrected c = correct(G, za + s * t, t, u_scale, p_scale, settings);
    if (!c.converged) break;
    const Real f = tau(c.point);
    best = c.point;
    if (f == 0.0) break;
    if ((f < 0) == (f1 < 0)) {
      s1 = s;
      f1 = f;
      if (side == 1) f0 *= 0.5;
      side = 1;
    } else {
      s0 = s;
      f0 = f;
      if (side == -1) f1 *= 0.5;
      side = -1;
    }
  }
  return best;
}

}  // namespace feran

#include <feran/analyses/periodic/orbits.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

const char* bifurcation_name(Bifurcation::Kind kind) {
  switch (kind) {
    case Bifurcation::Kind::fold:
      return "fold";
    case Bifurcation::Kind::period_doubling:
      return "period_doubling";
    case Bifurcation::Kind::neimark_sacker:
      return "neimark_sacker";
    case Bifurcation::Kind::hopf:
      return "hopf";
    case Bifurcation::Kind::static_instability:
      return "static_instability";
  }
  return "";
}

Real critical_frequency(const Bifurcation& b) {
  const Floquet& f = b.at.floquet;
  Index critical = -1;
  Real nearest = std::numeric_limits<Real>::infinity();
  for (Index j = 0; j < f.exponents.size(); ++j) {
    if (j == f.trivial || f.exponents(j).imag() <= 0) continue;
    const Real d = b.kind == Bifurcation::Kind::hopf ? std::abs(f.exponents(j).real())
                                                     : std::abs(std::abs(f.multipliers(j)) - 1.0);
    if (d < nearest) {
      nearest = d;
      critical = j;
    }
  }
  switch (b.kind) {
    case Bifurcation::Kind::hopf:
      return critical < 0 ? 0.0 : f.exponents(critical).imag();
    case Bifurcation::Kind::neimark_sacker:
      return critical < 0 ? 0.0 : std::abs(std::arg(f.multipliers(critical))) * b.at.frequency / (2.0 * pi);
    case Bifurcation::Kind::period_doubling:
      return 0.5 * b.at.frequency;
    default:
      return 0.0;
  }
}

Real length_scale(const RotorFamily& family, const OrbitSettings& settings) {
  if (settings.length_scale > 0) return settings.length_scale;
  Real c = std::numeric_limits<Real>::infinity();
  for (const Force& f : family.base().model().forces)
    if (const auto cl = f.clearance(); cl && *cl > 0) c = std::min(c, *cl);
  return std::isfinite(c) ? c : 1e-3;
}

const char* branch_kind_name(OrbitBranch::Kind kind) {
  switch (kind) {
    case OrbitBranch::Kind::equilibrium:
      return "equilibrium";
    case OrbitBranch::Kind::forced:
      return "forced";
    case OrbitBranch::Kind::self_excited:
      return "self_excited";
  }
  return "";
}

RotorFamily::RotorFamily(const CondensedRotor& rotor) : base_(rotor) {}

RotorFamily::RotorFamily(const CondensedRotor& rotor, Real speed, std::function<Model(Real)> build, std::string name)
    : base_(rotor), speed_(speed), build_(std::move(build)), name_(std::move(name)) {}

const CondensedRotor& RotorFamily::at(Real p) const {
  if (!build_) return base_;
  for (auto it = cache_.begin(); it != cache_.end(); ++it)
    if (it->p == p) {
      cache_.splice(cache_.begin(), cache_, it);
      return *cache_.front().rotor;
    }
  Member m{.p = p, .model = std::make_unique<Model>(build_(p)), .rotor = nullptr};
  m.rotor = std::make_unique<CondensedRotor>(*m.model, nullptr, base_);
  cache_.push_front(std::move(m));
  if (cache_.size() > 8) cache_.pop_back();
  return *cache_.front().rotor;
}

namespace {

using Kind = OrbitBranch::Kind;

// The continuation problem of one branch: u = X (equilibrium, forced) or (X, ω)
// (self-excited, with the phase fixed by u(anchor) = 0); p = Ω.
struct BranchProblem {
  const RotorFamily& family;
  FourierBasis fourier;
  Kind kind;
  Index anchor = -1;
  Real p_scale = 1.0;  // the parameter's scale (its differences' step)

  Index nx() const { return family.base().size() * fourier.terms(); }
  Real omega(const Vector& u, Real p) const {
    if (kind == Kind::self_excited) return u(nx());
    return kind == Kind::forced ? family.speed(p) : 1.0;  // an equilibrium's ω does not enter
  }
  Vector X(const Vector& u) const { return u.head(nx()); }
  PeriodicSystem system(Real p, Real w) const { return family.at(p).at(family.speed(p), w, fourier); }

  BalanceTerms terms(const Vector& u, Real p, bool velocity) const {
    const Real w = omega(u, p);
    return balance_terms(fourier, system(p, w), w, X(u), velocity);
  }
  // ∂R/∂p by central differences (the model's dependence on the speed — gyroscopics,
  // speed-dependent supports, the film's speed, the unbalance's Ω²; a forced orbit's
  // ω = Ω moves with it — or on the number a path names); the step 1e-6·|p| leaves an
  // error of about 1e-10 of ‖R‖'s terms.
  Vector dR_dp(const Vector& u, Real p) const {
    const Real h = 1e-6 * (p != 0.0 ? std::abs(p) : p_scale);
    const auto residual = [&](Real q) {
      const Real w = omega(u, q);
      return balance_residual(fourier, system(q, w), w, X(u));
    };
    return (residual(p + h) - residual(p - h)) / (2 * h);
  }

  BranchEquations operator()(const Vector& u, Real p) const {
    BalanceTerms t = terms(u, p, false);
    const Index n = nx();
    if (kind != Kind::self_excited)
      return BranchEquations{.G = std::move(t.R), .Gu = std::move(t.dR_dX), .Gp = dR_dp(u, p), .scale = t.scale};
    BranchEquations e{
        .G = Vector(n + 1), .Gu = Matrix::Zero(n + 1, n + 1), .Gp = Vector::Zero(n + 1), .scale = t.scale};
    e.G.head(n) = t.R;
    e.G(n) = u(anchor) * (t.scale > 0 ? t.scale : 1.0);  // the phase, weighted like the forces
    e.Gu.topLeftCorner(n, n) = t.dR_dX;
    e.Gu.topRightCorner(n, 1) = t.dR_domega;
    e.Gu(n, anchor) = t.scale > 0 ? t.scale : 1.0;
    e.Gp.head(n) = dR_dp(u, p);
    return e;
  }

  SteadyState orbit(const Vector& u, Real p, const OrbitSettings& settings) const {
    const Real w = omega(u, p), speed = family.speed(p);
    const PeriodicSystem sys = system(p, w);
    const BalanceTerms t = balance_terms(fourier, sys, w, X(u), true);
    // An equilibrium's "multipliers" are over one revolution (any period would do).
    const Real period_frequency = kind == Kind::equilibrium ? std::max(speed, 1e-300) : w;
    SteadyState o{.parameter = p,
                  .speed = speed,
                  .frequency = kind == Kind::equilibrium ? 0.0 : w,
                  .X = X(u),
                  .floquet = hill_floquet(fourier, sys, period_frequency, t, kind == Kind::self_excited),
                  .stable = true,
                  .truncation = truncation_estimate(fourier, sys, w, X(u)),
                  .residual = t.scale > 0 ? t.R.norm() / t.scale : t.R.norm()};
    o.stable = growth(o) <= settings.stability_tolerance;
    return o;
  }

  // The test functions of stability, largest first: an equilibrium's Re s/|s|, an
  // orbit's ln|μ| (the phase's multiplier left out).
  std::vector<Real> growths(const SteadyState& o) const {
    std::vector<Real> out;
    for (Index j = 0; j < o.floquet.exponents.size(); ++j) {
      if (j == o.floquet.trivial) continue;
      const Complex s = o.floquet.exponents(j);
      out.push_back(kind == Kind::equilibrium ? (std::abs(s) > 0 ? s.real() / std::abs(s) : 0.0)
                                              : std::log(std::abs(o.floquet.multipliers(j))));
    }
    std::sort(out.begin(), out.end(), std::greater<>());
    return out;
  }
  Real growth(const SteadyState& o) const {
    const std::vector<Real> g = growths(o);
    return g.empty() ? -std::numeric_limits<Real>::infinity() : g.front();
  }
};

// Which crossing an orbit's critical multiplier makes.
Bifurcation::Kind multiplier_kind(const SteadyState& o, Kind kind) {
  Index critical = -1;
  Real nearest = std::numeric_limits<Real>::infinity();
  for (Index j = 0; j < o.floquet.exponents.size(); ++j) {
    if (j == o.floquet.trivial) continue;
    const Real d = kind == Kind::equilibrium ? std::abs(o.floquet.exponents(j).real())
                                             : std::abs(std::abs(o.floquet.multipliers(j)) - 1.0);
    if (d < nearest) {
      nearest = d;
      critical = j;
    }
  }
  if (critical < 0) return Bifurcation::Kind::fold;
  if (kind == Kind::equilibrium) {
    const Complex s = o.floquet.exponents(critical);
    return std::abs(s.imag()) > 1e-6 * std::max(std::abs(s), o.speed * 1e-9) ? Bifurcation::Kind::hopf
                                                                             : Bifurcation::Kind::static_instability;
  }
  const Complex mu = o.floquet.multipliers(critical);
  const Real angle = std::abs(std::arg(mu));
  if (angle > pi - 1e-3) return Bifurcation::Kind::period_doubling;
  if (angle < 1e-3) return Bifurcation::Kind::fold;
  return Bifurcation::Kind::neimark_sacker;
}

OrbitBranch follow(const BranchProblem& problem, const BranchPoint& start, const Vector& direction, Real towards,
                   const Vector& u_scale, Real p_scale, const OrbitSettings& settings) {
  const BranchFunction G = [&](const Vector& u, Real p) { return problem(u, p); };
  OrbitBranch out;
  out.kind = problem.kind;
  out.fourier = problem.fourier;
  out.phase_anchor = problem.anchor;
  std::vector<SteadyState> orbits;
  // A self-excited branch that comes back to the equilibrium (a Hopf point, reached
  // from the orbits' side) would go on through it — with the anchor coordinate's a₁,
  // its amplitude (b₁ being held at 0), changing sign: the same orbits half a period
  // later — or along the trivial solutions there (harmonics 0, any ω). It ends there
  // instead: at the first state whose a₁ has changed sign or whose harmonics have
  // shrunk below 10⁻³ of the length scale, once they had exceeded 10⁻² of it (a
  // branch leaving a Hopf point starts at 0).
  const Index n = problem.family.base().size(), nx = problem.nx();
  const Index amplitude = problem.kind == Kind::self_excited ? problem.anchor - n : -1;
  const Real L = u_scale.size() > 0 ? u_scale(0) : 1.0;
  Real sign = 0.0;
  bool grown = false;
  std::string met;
  const auto crosses = [&](const BranchPoint& p) {
    if (amplitude < 0) return false;
    const Real a = p.u(amplitude), h = p.u.segment(n, nx - n).norm();
    if (grown && (sign * a < 0 || h < 1e-3 * L)) return true;
    grown = grown || h > 1e-2 * L;
    if (std::abs(a) > 1e-6 * L) sign = a > 0 ? 1.0 : -1.0;  // not the Hopf point's own 0
    return false;
  };
  const auto monitor = [&](const Branch& b) {
    const BranchPoint& p = b.points.back();
    if (crosses(p)) {
      const Real before = b.points[b.points.size() - 2].p;
      met = problem.family.is_speed()
                ? fmt::format(
                      "it meets the static equilibrium (orbits of amplitude 0: a Hopf point) between "
                      "{:.6g} and {:.6g} rad/s ({:.6g} and {:.6g} Hz)",
                      before, p.p, before / (2 * pi), p.p / (2 * pi))
                : fmt::format(
                      "it meets the static equilibrium (orbits of amplitude 0: a Hopf point) between {} = "
                      "{:.6g} and {:.6g}",
                      problem.family.name(), before, p.p);
      return false;
    }
    orbits.push_back(problem.orbit(p.u, p.p, settings));
    return !settings.monitor || settings.monitor(orbits.back());
  };
  orbits.push_back(problem.orbit(start.u, start.p, settings));
  static_cast<void>(crosses(start));
  const Branch b = continue_branch(G, start, direction, towards, u_scale, p_scale, settings.continuation, monitor);
  out.orbits = std::move(orbits);
  out.ended_by = met.empty() ? b.ended_by : met;
  out.clipped = met.empty() && b.clipped();
  // Bifurcations between consecutive points: folds by dp/ds, and each change in the
  // number of exponents (multipliers) beyond the stability limit — also one more
  // crossing on a branch already unstable — by the test function of the first that
  // crosses, each located on the branch.
  const Real limit = settings.stability_tolerance;
  const auto unstable = [&](const SteadyState& o) {
    const std::vector<Real> g = problem.growths(o);
    return static_cast<std::size_t>(std::count_if(g.begin(), g.end(), [&](Real x) { return x > limit; }));
  };
  for (std::size_t i = 1; i < b.points.size() && i < out.orbits.size(); ++i) {
    const BranchPoint &a = b.points[i - 1], &c = b.points[i];
    bool fold = false;
    if (problem.kind != Kind::equilibrium && fold_test(a) * fold_test(c) < 0) {
      const BranchPoint f = locate_on_branch(G, a, c, u_scale, p_scale, settings.continuation, fold_test);
      out.bifurcations.push_back({Bifurcation::Kind::fold, problem.orbit(f.u, f.p, settings), i - 1});
      fold = true;
    }
    const std::size_t ua = unstable(out.orbits[i - 1]), uc = unstable(out.orbits[i]);
    if (ua != uc) {
      const std::size_t rank = std::min(ua, uc);  // the (rank + 1)-th largest crosses
      const auto test = [&](const BranchPoint& p) {
        const std::vector<Real> g = problem.growths(problem.orbit(p.u, p.p, settings));
        return (rank < g.size() ? g[rank] : -std::numeric_limits<Real>::infinity()) - limit;
      };
      const BranchPoint x = locate_on_branch(G, a, c, u_scale, p_scale, settings.continuation, test);
      SteadyState at = problem.orbit(x.u, x.p, settings);
      const Bifurcation::Kind k = multiplier_kind(at, problem.kind);
      if (!fold) out.bifurcations.push_back({k, std::move(at), i - 1});
    }
  }
  return out;
}

// The equilibrium at parameter @p p: Newton's method from rest, else from the static
// analysis's equilibrium (a support without stiffness at rest).
BranchPoint equilibrium_start(const BranchFunction& G, const RotorFamily& family, Real p,
                              const ContinuationSettings& c) {
  const CondensedRotor& rotor = family.at(p);
  BranchPoint start = correct_at_fixed_parameter(G, Vector::Zero(rotor.size()), p, c);
  if (start.residual <= c.tolerance) return start;
  return correct_at_fixed_parameter(G, rotor.static_equilibrium(family.speed(p)), p, c);
}

// The forced orbit at parameter @p p when Newton's method from the equilibrium @p u0
// does not reach it (a strongly nonlinear support: contacts opening, a film near its
// clearance): the loads at the rotor speed switched on gradually, the orbit continued
// in their scale λ from 0 (the equilibrium) to 1.
BranchPoint forced_start(const BranchProblem& problem, const Vector& u0, Real p, Real length,
                         const ContinuationSettings& c) {
  const Real w = problem.omega(u0, p);
  const PeriodicSystem full = problem.system(p, w);
  const Index n0 = problem.family.base().size();
  const auto system = [&](Real lambda) {
    PeriodicSystem s = full;
    if (s.external.size() > n0) s.external.tail(s.external.size() - n0) *= lambda;
    return s;
  };
  const BranchFunction G = [&](const Vector& u, Real lambda) {
    BalanceTerms t = balance_terms(problem.fourier, system(lambda), w, u, false);
    const Real h = 1e-6;
    const Vector Gp = (balance_residual(problem.fourier, system(lambda + h), w, u) -
                       balance_residual(problem.fourier, system(lambda - h), w, u)) /
                      (2 * h);
    return BranchEquations{.G = std::move(t.R), .Gu = std::move(t.dR_dX), .Gp = Gp, .scale = t.scale};
  };
  ContinuationSettings homotopy = c;
  homotopy.p_min = 0.0;
  homotopy.p_max = 1.0;
  homotopy.max_parameter_step = 0.1;
  homotopy.max_points = std::max<Index>(c.max_points, 200);
  const BranchPoint zero = correct_at_fixed_parameter(G, u0, 0.0, c);
  const Branch b = continue_branch(G, zero, Vector(), +1.0, Vector::Constant(u0.size(), length), 1.0, homotopy);
  BranchPoint out = b.points.back();
  if (!b.clipped() || out.p != 1.0) out.residual = std::numeric_limits<Real>::infinity();
  out.p = p;
  return out;
}

}  // namespace

Real parameter_scale(const ContinuationSettings& c, Real start) {
  const Real range = c.p_max - c.p_min;
  return range > 0 ? range : std::max(std::abs(start), 1e-300);
}

OrbitBranch equilibrium_branch(const RotorFamily& family, const OrbitSettings& settings) {
  const ContinuationSettings& c = settings.continuation;
  const Real p_scale = parameter_scale(c, c.p_min);
  const BranchProblem problem{.family = family,
                              .fourier = {.harmonics = 0, .samples = 1},
                              .kind = Kind::equilibrium,
                              .anchor = -1,
                              .p_scale = p_scale};
  const CondensedRotor& rotor = family.base();
  const BranchFunction G = [&](const Vector& u, Real p) { return problem(u, p); };
  const BranchPoint start = equilibrium_start(G, family, c.p_min, c);
  if (!(start.residual <= c.tolerance))
    throw Error(fmt::format("periodic orbits: the static equilibrium at {} = {:.6g} was not found (residual {:.3g})",
                            family.name(), c.p_min, start.residual));
  const Real L = length_scale(family, settings);
  return follow(problem, start, Vector(), +1.0, Vector::Constant(rotor.size(), L), p_scale, settings);
}

OrbitBranch equilibrium_branch(const CondensedRotor& rotor, const OrbitSettings& settings) {
  return equilibrium_branch(RotorFamily(rotor), settings);
}

OrbitBranch forced_branch(const RotorFamily& family, const OrbitSettings& settings, bool downwards) {
  const CondensedRotor& rotor = family.base();
  if (!rotor.forced())
    throw Error("periodic orbits: no unbalance or synchronous force acts: there is no forced orbit to follow");
  const ContinuationSettings& c = settings.continuation;
  const Real first = downwards ? c.p_max : c.p_min;
  const Real p_scale = parameter_scale(c, first);
  const BranchProblem problem{
      .family = family, .fourier = settings.fourier, .kind = Kind::forced, .anchor = -1, .p_scale = p_scale};
  const BranchFunction G = [&](const Vector& u, Real p) { return problem(u, p); };
  // From the equilibrium at the first point, then the forced orbit there.
  const BranchProblem statics{.family = family,
                              .fourier = {.harmonics = 0, .samples = 1},
                              .kind = Kind::equilibrium,
                              .anchor = -1,
                              .p_scale = p_scale};
  const BranchPoint eq = equilibrium_start([&](const Vector& u, Real p) { return statics(u, p); }, family, first, c);
  Vector u0 = Vector::Zero(problem.nx());
  u0.head(rotor.size()) = eq.u;
  BranchPoint start = correct_at_fixed_parameter(G, u0, first, c);
  if (!(start.residual <= c.tolerance) && eq.residual <= c.tolerance)
    start = forced_start(problem, u0, first, length_scale(family, settings), c);
  if (!(start.residual <= c.tolerance))
    throw Error(fmt::format("periodic orbits: the forced orbit at {} = {:.6g} was not found (residual {:.3g})",
                            family.name(), first, start.residual));
  const Real L = length_scale(family, settings);
  return follow(problem, start, Vector(), downwards ? -1.0 : 1.0, Vector::Constant(problem.nx(), L), p_scale, settings);
}

OrbitBranch forced_branch(const CondensedRotor& rotor, const OrbitSettings& settings, bool downwards) {
  return forced_branch(RotorFamily(rotor), settings, downwards);
}

OrbitBranch hopf_branch(const RotorFamily& family, const Bifurcation& hopf, const OrbitSettings& settings) {
  if (hopf.kind != Bifurcation::Kind::hopf)
    throw Error("periodic orbits: a self-excited branch starts at a Hopf point");
  const CondensedRotor& rotor = family.base();
  const Index n = rotor.size();
  const Real p0 = hopf.at.parameter, speed = family.speed(p0);
  // The critical mode at the Hopf point: the linearised equations about the
  // equilibrium, (s²M + s(C − ∂f/∂ẋ) + (K − ∂f/∂x))φ = 0.
  const FourierBasis mean{.harmonics = 0, .samples = 1};
  const PeriodicSystem system = family.at(p0).at(speed, speed, mean);
  const BalanceTerms t = balance_terms(mean, system, 1.0, hopf.at.X, true);
  Matrix A = Matrix::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::PartialPivLU<Matrix> mass(system.M);
  A.bottomLeftCorner(n, n) = -mass.solve(t.dR_dX);
  A.bottomRightCorner(n, n) = -mass.solve(system.C - t.Jv);
  const Eigen::EigenSolver<Matrix> eig(A);
  Index critical = -1;
  for (Index j = 0; j < 2 * n; ++j) {
    const Complex s = eig.eigenvalues()(j);
    if (s.imag() > 0 && (critical < 0 || std::abs(s.real()) < std::abs(eig.eigenvalues()(critical).real())))
      critical = j;
  }
  if (critical < 0) throw Error("periodic orbits: no oscillatory mode crosses at the Hopf point");
  const Real omega = eig.eigenvalues()(critical).imag();
  ComplexVector phi = eig.eigenvectors().col(critical).head(n);
  Index anchor = 0;
  phi.cwiseAbs().maxCoeff(&anchor);
  phi *= std::abs(phi(anchor)) / phi(anchor);  // φ_anchor real and positive
  phi /= phi.norm();

  const FourierBasis& fourier = settings.fourier;
  if (fourier.harmonics < 1) throw Error("periodic orbits: a self-excited orbit needs at least one harmonic");
  const Real p_scale = parameter_scale(settings.continuation, p0);
  const BranchProblem problem{
      .family = family, .fourier = fourier, .kind = Kind::self_excited, .anchor = 2 * n + anchor, .p_scale = p_scale};
  const Index nx = problem.nx();
  const Real L = length_scale(family, settings);
  Vector u_scale = Vector::Constant(nx + 1, L);
  u_scale(nx) = omega;
  // The start: the equilibrium as an orbit of amplitude 0 at ω; the direction: the
  // critical mode's x = Re(φ e^{iωt}) = Re φ cos ωt − Im φ sin ωt.
  BranchPoint start{.u = Vector::Zero(nx + 1), .p = p0, .tangent = {}, .iterations = 0, .residual = 0.0};
  start.u.head(n) = hopf.at.X;
  start.u(nx) = omega;
  Vector direction = Vector::Zero(nx + 2);
  direction.segment(n, n) = phi.real() / L;
  direction.segment(2 * n, n) = -phi.imag() / L;
  direction.normalize();
  OrbitBranch out = follow(problem, start, direction, 0.0, u_scale, p_scale, settings);
  // The orbit of amplitude 0 is the Hopf point itself: its multipliers are the
  // equilibrium's, not an orbit's; the branch's criticality is the side its next
  // orbits lie on.
  if (out.orbits.size() > 1) {
    const Real dp = out.orbits[1].parameter - p0;
    // Which side of the Hopf point the equilibrium is unstable on: its growth just
    // beyond it.
    const BranchProblem statics{
        .family = family, .fourier = mean, .kind = Kind::equilibrium, .anchor = -1, .p_scale = p_scale};
    const Real beyond = p0 + 1e-4 * p_scale;
    const BranchPoint eq = correct_at_fixed_parameter([&](const Vector& u, Real p) { return statics(u, p); }, hopf.at.X,
                                                      beyond, settings.continuation);
    const bool unstable_beyond = statics.growth(statics.orbit(eq.u, beyond, settings)) > 0;
    out.criticality = (dp > 0) == unstable_beyond ? "supercritical" : "subcritical";
  }
  return out;
}

OrbitBranch hopf_branch(const CondensedRotor& rotor, const Bifurcation& hopf, const OrbitSettings& settings) {
  return hopf_branch(RotorFamily(rotor), hopf, settings);
}

OrbitBranch branch_through(const RotorFamily& family, const SteadyState& start, OrbitBranch::Kind kind,
                           const OrbitSettings& settings, bool downwards) {
  if (kind == Kind::equilibrium)
    throw Error("periodic orbits: an equilibrium branch starts from the static equilibrium (equilibrium_branch)");
  const CondensedRotor& rotor = family.base();
  const Index n = rotor.size();
  const FourierBasis& fourier = settings.fourier;
  fourier.check();
  if (fourier.harmonics < 1) throw Error("periodic orbits: an orbit needs at least one harmonic");
  if (start.X.size() < n || start.X.size() % n != 0)
    throw Error(
        fmt::format("periodic orbits: the given orbit has {} coefficients, not a whole number of harmonics "
                    "of the rotor's {} coordinates",
                    start.X.size(), n));
  if (kind == Kind::forced && !rotor.forced())
    throw Error("periodic orbits: no unbalance or synchronous force acts: there is no forced orbit to follow");
  if (kind == Kind::self_excited && !(start.frequency > 0))
    throw Error("periodic orbits: a self-excited orbit needs its frequency (> 0)");
  // The coefficients on the branch's harmonics.
  const Index nx = n * fourier.terms();
  Vector X = Vector::Zero(nx);
  X.head(std::min(nx, start.X.size())) = start.X.head(std::min(nx, start.X.size()));
  Index anchor = -1;
  if (kind == Kind::self_excited) {
    // The phase: θ → θ + φ with tan φ = b₁/a₁ of the coordinate whose first harmonic is
    // largest makes its b₁ 0 (and a₁ > 0); harmonic k turns by kφ.
    Index j = 0;
    (X.segment(n, n).cwiseAbs2() + X.segment(2 * n, n).cwiseAbs2()).maxCoeff(&j);
    const Real phi = std::atan2(X(2 * n + j), X(n + j));
    for (Index k = 1; k <= fourier.harmonics; ++k) {
      const Real c = std::cos(static_cast<Real>(k) * phi), s = std::sin(static_cast<Real>(k) * phi);
      const Vector a = X.segment((2 * k - 1) * n, n), b = X.segment(2 * k * n, n);
      X.segment((2 * k - 1) * n, n) = c * a + s * b;
      X.segment(2 * k * n, n) = c * b - s * a;
    }
    anchor = 2 * n + j;
    X(anchor) = 0.0;
  }
  const Real p0 = start.parameter;
  const Real p_scale = parameter_scale(settings.continuation, p0);
  const BranchProblem problem{.family = family, .fourier = fourier, .kind = kind, .anchor = anchor, .p_scale = p_scale};
  const BranchFunction G = [&](const Vector& u, Real p) { return problem(u, p); };
  const Index m = nx + (kind == Kind::self_excited ? 1 : 0);
  Vector u0(m);
  u0.head(nx) = X;
  if (kind == Kind::self_excited) u0(nx) = start.frequency;
  const BranchPoint first = correct_at_fixed_parameter(G, u0, p0, settings.continuation);
  if (!(first.residual <= settings.continuation.tolerance))
    throw Error(
        fmt::format("periodic orbits: the given orbit at {} = {:.6g} does not converge to an orbit of the "
                    "balance (residual {:.3g}); a start nearer the orbit, or more harmonics, may help",
                    family.name(), p0, first.residual));
  const Real L = length_scale(family, settings);
  Vector u_scale = Vector::Constant(m, L);
  if (kind == Kind::self_excited) u_scale(nx) = first.u(nx);
  return follow(problem, first, Vector(), downwards ? -1.0 : 1.0, u_scale, p_scale, settings);
}

std::vector<SteadyState> states_at(const RotorFamily& family, const OrbitBranch& branch, Real speed,
                                   const OrbitSettings& settings) {
  const BranchProblem problem{.family = family,
                              .fourier = branch.fourier,
                              .kind = branch.kind,
                              .anchor = branch.phase_anchor,
                              .p_scale = parameter_scale(settings.continuation, speed)};
  const bool autonomous = branch.kind == Kind::self_excited;
  const auto u_of = [&](const SteadyState& o) {
    Vector u(o.X.size() + (autonomous ? 1 : 0));
    u.head(o.X.size()) = o.X;
    if (autonomous) u(o.X.size()) = o.frequency;
    return u;
  };
  std::vector<SteadyState> out;
  for (std::size_t i = 1; i < branch.orbits.size(); ++i) {
    const SteadyState &a = branch.orbits[i - 1], &b = branch.orbits[i];
    if ((a.parameter - speed) * (b.parameter - speed) > 0 || a.parameter == b.parameter) continue;
    if (b.parameter == speed && i + 1 < branch.orbits.size()) continue;  // counted with the next interval
    const Real f = (speed - a.parameter) / (b.parameter - a.parameter);
    const Vector u0 = u_of(a) + f * (u_of(b) - u_of(a));
    const BranchPoint p = correct_at_fixed_parameter([&](const Vector& u, Real q) { return problem(u, q); }, u0, speed,
                                                     settings.continuation);
    if (p.residual <= settings.continuation.tolerance) out.push_back(problem.orbit(p.u, speed, settings));
  }
  return out;
}

std::vector<SteadyState> states_at(const CondensedRotor& rotor, const OrbitBranch& branch, Real speed,
                                   const OrbitSettings& settings) {
  return states_at(RotorFamily(rotor), branch, speed, settings);
}

void orbit_state(const CondensedRotor& rotor, const SteadyState& orbit, const FourierBasis& fourier, Real theta,
                 Vector& x, Vector& v) {
  const bool moving = orbit.frequency > 0;
  const FourierBasis f = moving ? fourier : FourierBasis{.harmonics = 0, .samples = 1};
  Vector xr, vr;
  motion_at(f, moving ? orbit.frequency : 1.0, orbit.X, moving ? theta / orbit.frequency : 0.0, xr, vr);
  x = rotor.expand(xr);
  v = moving ? rotor.expand(vr) : Vector::Zero(x.size());
}

}  // namespace feran

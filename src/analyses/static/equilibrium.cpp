#include <feran/analyses/static/equilibrium.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseLU>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <feran/assembly/checks.hpp>
#include <feran/core/error.hpp>

namespace feran {

Vector static_load_vector(const Model& model, const Eigen::Vector3d& gravity, bool loads) {
  Vector f = Vector::Zero(model.n_dofs());
  if (gravity.squaredNorm() > 0) {
    for (const Element& e : model.elements) {
      const LocalMatrices lm = e.local_matrices({});
      if (lm.M.size() == 0) continue;
      const auto n = static_cast<Index>(lm.dofs.size());
      Vector g = Vector::Zero(n);
      for (Index i = 0; i < n; ++i) {
        const Index local = lm.dofs[static_cast<std::size_t>(i)] % dofs_per_node;
        if (local < 3) g(i) = gravity(local);
      }
      const Vector fe = lm.M * g;
      for (Index i = 0; i < n; ++i) f(lm.dofs[static_cast<std::size_t>(i)]) += fe(i);
    }
  }
  if (loads)
    for (const Force& force : model.forces) force.add_static(f);
  return f;
}

void require_unloaded_free_motions(const Model& model, const Assembler& assembler, const Matrix& free,
                                   const Vector& f) {
  if (free.cols() == 0) return;
  const Vector work = free.transpose() * f;  // work of the load along each free motion
  if (work.cwiseAbs().maxCoeff() <= 1e-9 * f.norm() * std::sqrt(free.colwise().squaredNorm().maxCoeff())) return;
  std::vector<std::string> names;
  for (const FreeMotionInfo& m : find_free_motions(model, assembler)) names.push_back(m.description);
  throw Error(
      fmt::format("static analysis: the load drives a free motion of the model ({}); hold it with a "
                  "spring or a fixed DOF",
                  fmt::join(names, "; ")));
}

bool has_supports(const Model& model) {
  return std::any_of(model.forces.begin(), model.forces.end(), [](const Force& f) { return f.supports(); });
}

bool needs_speed(const Model& model) {
  return std::any_of(model.forces.begin(), model.forces.end(),
                     [](const Force& f) { return f.supports() && f.needs_speed(); });
}

namespace {

std::string force_name(const Force& force) {
  std::string kind(force.kind());
  std::replace(kind.begin(), kind.end(), '_', ' ');
  return force.label().empty() ? kind : fmt::format("{} '{}'", kind, force.label());
}

// The residual r = f + Tᵀ·f_s(T·q) − K·q of the equilibrium and, when asked, its
// negative Jacobian J = K − Tᵀ·(∂f_s/∂x)·T; empty when a support cannot be
// evaluated there (a journal at or beyond its wall).
class Residual {
 public:
  Residual(const Model& model, const Assembler& assembler, Real speed, const EquilibriumOptions& options)
      : model_(model), T_(assembler.dof_map().transformation()), state_{.speed = speed} {
    const SystemMatrices sys = assembler.at(speed, options.frequency);
    K_ = sys.stiffness(speed);
    f_ = T_.transpose() * static_load_vector(model, options.gravity, options.loads);
    for (std::size_t i = 0; i < model.forces.size(); ++i)
      if (model.forces[i].supports()) supports_.push_back(i);
    std::vector<Eigen::Triplet<Real>> diagonal;
    for (const std::size_t i : supports_)
      for (const Index d : model.forces[i].dofs()) diagonal.emplace_back(d, d, 1.0);
    SparseMatrix D(model.n_dofs(), model.n_dofs());
    D.setFromTriplets(diagonal.begin(), diagonal.end());
    for (Index k = 0; k < D.outerSize(); ++k)
      for (SparseMatrix::InnerIterator e(D, k); e; ++e) e.valueRef() = 1.0;  // a DOF two supports share: still 1
    S_ = T_.transpose() * D * T_;
    // Motions free even with the supports holding (allowed by free_motions, e.g.
    // torsion): the load must leave them alone, and the Newton steps are kept
    // orthogonal to them (in M), with J shifted by 1e-8·max(K_ii/M_ii)·M to stay regular.
    M_ = sys.M;
    free_ = stiffness_null_space(held_stiffness(model, assembler, K_), M_);
    if (free_.cols() > 0) {
      require_unloaded_free_motions(model, assembler, free_, f_);
      Real lambda_max = 0;
      for (Index i = 0; i < M_.rows(); ++i)
        lambda_max = std::max(lambda_max, std::abs(K_.coeff(i, i)) / M_.coeff(i, i));
      shift_ = 1e-8 * lambda_max;
    }
  }

  const Vector& load() const { return f_; }
  Index size() const { return K_.rows(); }
  // The Newton step J⁻¹·r from a factorisation of J (shifted where there are free
  // motions), with the free motions projected out.
  SparseMatrix regular(const SparseMatrix& J) const { return shift_ > 0 ? SparseMatrix(J + shift_ * M_) : J; }
  void project(Vector& dq) const {
    if (free_.cols() > 0) dq -= free_ * (free_.transpose() * (M_ * dq));
  }
  // The identity on the supports' DOFs, in reduced coordinates.
  const SparseMatrix& support_identity() const { return S_; }

  std::optional<Vector> operator()(const Vector& q, Real load_scale, SparseMatrix* jacobian) const {
    const Vector q_full = T_ * q;
    Vector fs = Vector::Zero(q_full.size());
    std::vector<Eigen::Triplet<Real>> triplets;
    for (const std::size_t i : supports_) {
      const Force& force = model_.forces[i];
      const std::vector<Index> dofs = force.dofs();
      const auto n = static_cast<Index>(dofs.size());
      Vector x(n);
      for (Index k = 0; k < n; ++k) x(k) = q_full(dofs[static_cast<std::size_t>(k)]);
      NonlinearForceValue value;
      try {
        value = force.force(state_, x, Vector::Zero(n));
      } catch (const Error&) {
        return std::nullopt;
      }
      for (Index a = 0; a < n; ++a) {
        fs(dofs[static_cast<std::size_t>(a)]) += value.f(a);
        if (jacobian)
          for (Index b = 0; b < n; ++b)
            if (value.dfdx(a, b) != 0.0)
              triplets.emplace_back(dofs[static_cast<std::size_t>(a)], dofs[static_cast<std::size_t>(b)],
                                    value.dfdx(a, b));
      }
    }
    if (jacobian) {
      SparseMatrix D(q_full.size(), q_full.size());
      D.setFromTriplets(triplets.begin(), triplets.end());
      *jacobian = K_ - SparseMatrix(T_.transpose() * D * T_);
    }
    return Vector(load_scale * f_ + T_.transpose() * fs - K_ * q);
  }

 private:
  const Model& model_;
  const SparseMatrix& T_;
  SparseMatrix K_, M_;
  MotionState state_;
  Vector f_;
  std::vector<std::size_t> supports_;
  Matrix free_;  // M-orthonormal basis of the motions the supports do not hold
  Real shift_ = 0.0;
  SparseMatrix S_;
};

// Newton's method from @p q for the load scaled by @p load_scale, each step cut back
// (halved, down to 2⁻²⁰; a regularised step below, to a quarter) until the residual
// norm decreases. Where the Jacobian is singular or no cut-back step decreases the
// residual (a contact support without contact, whose stiffness is zero, or a Hertzian
// contact at zero deflection), the step is regularised as Levenberg and Marquardt's:
// J + μ·S, S the identity on the supports' DOFs, μ from ‖r‖/(1 mm) (a first step of a
// millimetre, larger than any bearing clearance, which the line search halves) up
// tenfold until a step succeeds (or up to 1e12 of its start: steps of 1e-15 m) and
// down tenfold after each success (to plain Newton below 1e-12 of its start). It gives
// up early where it has stalled, the residual cut by less than a tenth over the last
// 8 steps (where the load cannot be carried, a step of the continuation below then
// costs 8 steps rather than 60). Returns whether it met the tolerance; @p q holds the
// last iterate.
bool newton(const Residual& residual, Real load_scale, Real scale, const EquilibriumOptions& options, Vector& q,
            Equilibrium& out) {
  SparseMatrix J;
  std::optional<Vector> r = residual(q, load_scale, &J);
  if (!r) return false;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  Real mu = 0.0, mu_start = 0.0;
  constexpr int stall_window = 8;
  std::vector<Real> history;
  for (int it = 0; it < options.max_iterations; ++it) {
    out.residual = r->norm() / scale;
    if (out.residual <= options.tolerance) return true;
    history.push_back(r->norm());
    if (it >= stall_window && history.back() > 0.9 * history[history.size() - 1 - stall_window]) break;
    ++out.iterations;
    bool stepped = false;
    for (int attempt = 0; attempt < 40 && !stepped; ++attempt) {
      lu.compute(mu > 0 ? SparseMatrix(residual.regular(J) + mu * residual.support_identity()) : residual.regular(J));
      Vector dq;
      if (lu.info() == Eigen::Success) {
        dq = lu.solve(*r);
        residual.project(dq);
      }
      if (lu.info() == Eigen::Success && dq.allFinite()) {
        // The regularised steps are short already, and μ their control: two cuts each.
        const Real shortest = mu > 0 ? 0.25 : 0x1p-20;
        for (Real t = 1.0; t >= shortest; t *= 0.5) {
          const Vector trial = q + t * dq;
          SparseMatrix J_trial;
          std::optional<Vector> r_trial = residual(trial, load_scale, &J_trial);
          if (!r_trial || r_trial->norm() >= (1.0 - 1e-4 * t) * r->norm()) continue;
          q = trial;
          r = std::move(r_trial);
          J.swap(J_trial);  // Eigen's sparse matrices copy on assignment
          stepped = true;
          break;
        }
      }
      if (stepped) {
        mu = mu * 0.1 < 1e-12 * mu_start ? 0.0 : mu * 0.1;
      } else {
        if (mu_start == 0.0) mu_start = r->norm() / 1e-3;
        mu = mu > 0 ? 10.0 * mu : mu_start;
        if (mu > 1e12 * mu_start) break;  // steps below a nanometre's millionth: none
      }
    }
    if (!stepped) break;
  }
  out.residual = r->norm() / scale;
  return out.residual <= options.tolerance;
}

}  // namespace

void require_running(const std::vector<Force>& forces, Real speed) {
  for (const Force& force : forces)
    if (force.supports() && force.needs_speed() && !(speed > 0))
      throw Error(
          fmt::format("the {} carries no load at rest (an oil film has no stiffness at speed 0): the "
                      "equilibrium and the linear analyses need a speed above 0 (start a sweep above "
                      "0), got {:.6g} rad/s",
                      force_name(force), speed));
}

Equilibrium solve_equilibrium(const Model& model, const Assembler& assembler, Real speed,
                              const EquilibriumOptions& options) {
  require_running(model.forces, speed);
  Equilibrium out;
  out.info.method = SolverMethod::sparse_lu;
  const Residual residual(model, assembler, speed, options);
  const Vector& f = residual.load();
  Vector q = Vector::Zero(residual.size());
  const Real scale = f.norm();
  if (scale == 0.0) {  // no load: the journals stay centred, where the supports' force is zero
    out.q = assembler.dof_map().transformation() * q;
    out.info.n_converged = 1;
    return out;
  }
  // Newton on the full load; when it stalls (a heavy load pushing a journal far out
  // from the centre), continuation: the load grows in steps, each solved from the
  // last, the step halved where Newton fails and doubled where it succeeds.
  bool done = newton(residual, 1.0, scale, options, q, out);
  Real reached = 1.0;
  if (!done) {
    q.setZero();
    reached = 0.0;
    Real step = 0.125;
    while (reached < 1.0 && step > 1e-6) {
      const Real next = std::min(1.0, reached + step);
      Vector trial = q;
      Equilibrium part;
      if (newton(residual, next, scale * next, options, trial, part)) {
        q = std::move(trial);
        reached = next;
        out.iterations += part.iterations;
        out.residual = part.residual;
        step *= 2.0;
      } else {
        out.iterations += part.iterations;
        step *= 0.5;
      }
    }
    done = reached == 1.0;
  }
  out.q = assembler.dof_map().transformation() * q;
  if (!done) {
    // The likely cause, by support: one that has no stiffness where the journal
    // stopped (a rolling bearing's clearance not yet closed), else the one whose
    // journal moved furthest (a bearing too weak for its load, or pressed to its wall).
    std::string cause;
    Real furthest = -1;
    std::string far_name;
    for (const Force& force : model.forces) {
      if (!force.supports()) continue;
      const std::vector<Index> dofs = force.dofs();
      Vector x(static_cast<Index>(dofs.size()));
      for (std::size_t k = 0; k < dofs.size(); ++k) x(static_cast<Index>(k)) = out.q(dofs[k]);
      try {
        const NonlinearForceValue value = force.force({.speed = speed}, x, Vector::Zero(x.size()));
        if (value.dfdx.size() == 0 || value.dfdx.cwiseAbs().maxCoeff() == 0)
          cause += fmt::format(
              "{}the {} has no stiffness where its journal is (a clearance not closed, or "
              "nothing to carry the load there)",
              cause.empty() ? "" : "; ", force_name(force));
      } catch (const Error& e) {
        cause += fmt::format("{}the {}: {}", cause.empty() ? "" : "; ", force_name(force), e.what());
      }
      if (x.norm() > furthest) furthest = x.norm(), far_name = force_name(force);
    }
    if (cause.empty() && furthest >= 0)
      cause = fmt::format(
          "the {} moved furthest ({:.3g} m): too weak for its load, or its journal pressed to its "
          "wall",
          far_name, furthest);
    out.info.fail(SolverStatus::not_converged,
                  fmt::format("the static equilibrium at {:.6g} rad/s was not found: Newton's method with load "
                              "continuation carried {:.3g} % of the load; likely cause: {}",
                              speed, 100.0 * reached, cause));
  }
  if (done) out.info.n_converged = 1;
  return out;
}

EquilibriumPath::EquilibriumPath(Model model, EquilibriumOptions options)
    : model_(std::move(model)), options_(std::move(options)), assembler_(model_) {}

const Vector& EquilibriumPath::at(Real speed) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = solved_.find(speed); it != solved_.end()) return it->second;
  }
  Equilibrium e = solve_equilibrium(model_, assembler_, speed, options_);
  if (!e.info.converged()) throw Error(e.info.message);
  const std::lock_guard<std::mutex> lock(mutex_);
  return solved_.try_emplace(speed, std::move(e.q)).first->second;
}

namespace {

// A support replaced by its tangent about the equilibrium at each speed.
class LinearisedSupport {
 public:
  LinearisedSupport(std::shared_ptr<const EquilibriumPath> path, std::size_t force)
      : path_(std::move(path)), force_(force) {}

  std::string_view kind() const { return "linearised_support"; }
  bool speed_dependent() const { return true; }
  std::vector<Index> dofs() const { return path_->model().forces[force_].dofs(); }
  Connection connection() const {
    const std::vector<Index> nodes = path_->model().forces[force_].nodes();
    return {nodes.front(), nodes.size() > 1 ? std::optional<Index>(nodes[1]) : std::nullopt};
  }

  // Zero at rest for a film, which has no stiffness then (the analyses refuse speed 0
  // with require_running(); the assembly asks at rest only for the pattern).
  LocalMatrices local_matrices(const OperatingPoint& op) const {
    const Force& force = path_->model().forces[force_];
    LocalMatrices lm;
    lm.dofs = force.dofs();
    const auto n = static_cast<Index>(lm.dofs.size());
    if (!(op.speed > 0) && force.needs_speed()) {
      lm.K = lm.C = Matrix::Zero(n, n);
      return lm;
    }
    const Vector& q = path_->at(op.speed);
    Vector x(n);
    for (Index k = 0; k < n; ++k) x(k) = q(lm.dofs[static_cast<std::size_t>(k)]);
    const NonlinearForceValue value = force.force({.speed = op.speed}, x, Vector::Zero(n));
    lm.K = -value.dfdx;
    lm.C = -value.dfdv;
    return lm;
  }

  // The support's state at the equilibrium at @p speed (none at rest for a film,
  // which carries nothing then).
  std::vector<OperatingValue> operating_data(Real speed) const {
    const Force& force = path_->model().forces[force_];
    const std::vector<Index> dofs = force.dofs();
    const auto n = static_cast<Index>(dofs.size());
    if (!(speed > 0) && force.needs_speed()) return {};
    Vector x(n);
    const Vector& q = path_->at(speed);
    for (Index k = 0; k < n; ++k) x(k) = q(dofs[static_cast<std::size_t>(k)]);
    return force.operating_data({.speed = speed}, x, Vector::Zero(n));
  }

  // The block of the tangent on the first node's own DOFs, as 6×6 matrices of the
  // relative motion (the force depends on the journal's motion relative to its housing).
  Transmission transmission(Real speed) const {
    const Force& force = path_->model().forces[force_];
    const std::vector<Index> nodes = force.nodes();
    const LocalMatrices lm = local_matrices({speed});
    Transmission t{.node_a = nodes.front(),
                   .node_b = {},
                   .K = Matrix::Zero(dofs_per_node, dofs_per_node),
                   .C = Matrix::Zero(dofs_per_node, dofs_per_node),
                   .loss_factor = 0.0,
                   .M = {}};
    if (nodes.size() > 1) t.node_b = nodes[1];
    for (std::size_t i = 0; i < lm.dofs.size(); ++i)
      for (std::size_t j = 0; j < lm.dofs.size(); ++j) {
        if (lm.dofs[i] / dofs_per_node != t.node_a || lm.dofs[j] / dofs_per_node != t.node_a) continue;
        const auto a = static_cast<Index>(lm.dofs[i] % dofs_per_node),
                   b = static_cast<Index>(lm.dofs[j] % dofs_per_node);
        t.K(a, b) = lm.K(static_cast<Index>(i), static_cast<Index>(j));
        t.C(a, b) = lm.C(static_cast<Index>(i), static_cast<Index>(j));
      }
    return t;
  }

 private:
  std::shared_ptr<const EquilibriumPath> path_;
  std::size_t force_;
};

}  // namespace

Model linearised(const Model& model) {
  return linearised(model, EquilibriumOptions{.gravity = model.gravity, .loads = true});
}

Model linearised(const Model& model, const EquilibriumOptions& about) {
  if (!has_supports(model)) return model;
  auto path = std::make_shared<const EquilibriumPath>(model, about);
  Model out = model;
  out.forces.clear();
  for (std::size_t i = 0; i < model.forces.size(); ++i) {
    const Force& force = model.forces[i];
    if (force.supports())
      out.elements.emplace_back(LinearisedSupport(path, i), force.label());
    else
      out.forces.push_back(force);
  }
  return out;
}

std::optional<std::size_t> linearised_support_force(const Model& model, Index element) {
  const auto n = static_cast<Index>(model.elements.size());
  if (element < n) return std::nullopt;
  Index k = element - n;
  for (std::size_t i = 0; i < model.forces.size(); ++i)
    if (model.forces[i].supports() && k-- == 0) return i;
  throw Error(fmt::format("no element {} in the linearised model", element + 1));
}

std::string linearised_element_name(const Model& model, Index element) {
  if (const auto force = linearised_support_force(model, element)) {
    const Force& f = model.forces[*force];
    if (!f.label().empty()) return f.label();
    std::string kind(f.kind());
    std::replace(kind.begin(), kind.end(), '_', ' ');
    return fmt::format("{} {}", kind, *force + 1);
  }
  const std::string& label = model.elements[static_cast<std::size_t>(element)].label();
  return label.empty() ? fmt::format("element {}", element + 1) : label;
}

}  // namespace feran

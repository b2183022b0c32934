#include <feran/analyses/api684/critical_speed_map.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Cholesky>
#include <fmt/format.h>

#include <feran/analyses/modal/whirl.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/error.hpp>
#include <feran/core/parallel.hpp>
#include <feran/core/root_finding.hpp>
#include <feran/elements/spring_damper.hpp>

#include "../modal/state_eigen.hpp"

namespace feran {

namespace {

constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();

bool lateral(Dof d) { return d == Dof::v || d == Dof::w || d == Dof::ry || d == Dof::rz; }

// The reduced DOFs that are lateral (v, w, ry, rz of their node), in order.
std::vector<Index> lateral_dofs(const DofMap& map) {
  std::vector<Index> out;
  for (Index r = 0; r < map.n_reduced(); ++r)
    if (lateral(static_cast<Dof>(map.full_dof(r) % dofs_per_node))) out.push_back(r);
  return out;
}

// The dense lateral block of @p A, after checking that A couples lateral DOFs with
// no other DOF (a straight rotor's lateral motion is uncoupled from its axial and
// torsional motion; a model that couples them has no lateral critical speed map).
Matrix lateral_block(const SparseMatrix& A, const std::vector<Index>& dofs, const std::vector<Index>& position,
                     const char* what) {
  const Index n = static_cast<Index>(dofs.size());
  Matrix out = Matrix::Zero(n, n);
  Real largest = 0, coupling = 0;
  for (Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const Index pi = position[static_cast<std::size_t>(it.row())];
      const Index pj = position[static_cast<std::size_t>(it.col())];
      largest = std::max(largest, std::abs(it.value()));
      if (pi >= 0 && pj >= 0)
        out(pi, pj) = it.value();
      else if ((pi >= 0) != (pj >= 0))
        coupling = std::max(coupling, std::abs(it.value()));
    }
  if (coupling > 1e-9 * largest)
    throw Error(
        fmt::format("the {} matrix couples the lateral motion with axial or torsional motion; undamped "
                    "critical speeds are defined for lateral motion alone",
                    what));
  return out;
}

// The synchronous whirl speeds of K·x = Ω²·(M − i·G)·x with K Hermitian positive
// definite: with K = L·Lᴴ, μ = 1/Ω² are the eigenvalues of L⁻¹(M − iG)L⁻ᴴ; a μ ≤ 0
// has no synchronous whirl (a disk whose polar inertia exceeds its diametral one).
struct Synchronous {
  std::vector<Real> speeds;      // increasing
  std::vector<ComplexVector> x;  // reduced lateral shapes
};

Synchronous synchronous_whirl(const Matrix& M, const Matrix& G, const Matrix& K) {
  const Eigen::LLT<Matrix> llt(K);
  if (llt.info() != Eigen::Success)
    throw Error("the lateral stiffness is singular: the rotor is not held laterally (give its bearings stiffness)");
  // L⁻¹(M − iG)L⁻ᵀ = P − iQ with the real P = L⁻¹ M L⁻ᵀ and Q = L⁻¹ G L⁻ᵀ.
  const auto L = llt.matrixL();
  const auto congruent = [&](const Matrix& A) {
    const Matrix X = L.solve(A);
    return Matrix(L.solve(Matrix(X.transpose())).transpose());
  };
  const Matrix P = congruent(M), Q = congruent(G);
  ComplexMatrix C(P.rows(), P.cols());
  C.real() = 0.5 * (P + P.transpose());
  C.imag() = -0.5 * (Q - Q.transpose());
  Vector mu;
  ComplexMatrix y;
  if (!detail::hermitian_eigen(std::move(C), mu, y)) throw Error("the synchronous whirl eigenproblem did not converge");
  Synchronous out;
  // Eigenvalues ascend: the largest μ is the lowest speed.
  const Real mu_max = mu.cwiseAbs().maxCoeff();
  const auto Lt = llt.matrixU();
  for (Index i = mu.size() - 1; i >= 0; --i) {
    if (!(mu(i) > 1e-13 * mu_max)) break;
    out.speeds.push_back(1.0 / std::sqrt(mu(i)));
    ComplexVector x(y.rows());  // x = L⁻ᵀ·y, real and imaginary parts apart
    x.real() = Lt.solve(Vector(y.col(i).real()));
    x.imag() = Lt.solve(Vector(y.col(i).imag()));
    out.x.push_back(std::move(x));
  }
  return out;
}

// The lateral matrices of a model at one speed and the map from reduced to lateral.
struct LateralSystem {
  explicit LateralSystem(const Model& model) : assembler(model) {
    dofs = lateral_dofs(assembler.dof_map());
    position.assign(static_cast<std::size_t>(assembler.dof_map().n_reduced()), -1);
    for (std::size_t i = 0; i < dofs.size(); ++i) position[static_cast<std::size_t>(dofs[i])] = static_cast<Index>(i);
    const SystemMatrices& c = assembler.constant();
    M = lateral_block(c.M, dofs, position, "mass");
    G = lateral_block(c.G, dofs, position, "gyroscopic");
  }
  Matrix stiffness(Real speed) const {
    return lateral_block(assembler.speed_dependent() ? assembler.at(speed).K : assembler.constant().K, dofs, position,
                         "stiffness");
  }
  // The forward solutions at stiffness K, the lowest first.
  std::vector<UndampedCritical> forward(const Matrix& K, bool gyroscopic) const {
    const Synchronous s = synchronous_whirl(M, gyroscopic ? G : Matrix::Zero(M.rows(), M.cols()), K);
    const Index n_full = assembler.dof_map().n_full();
    ComplexMatrix shapes(n_full, static_cast<Index>(s.speeds.size()));
    for (std::size_t i = 0; i < s.speeds.size(); ++i) {
      ComplexVector reduced = ComplexVector::Zero(assembler.dof_map().n_reduced());
      for (std::size_t j = 0; j < dofs.size(); ++j) reduced(dofs[j]) = s.x[i](static_cast<Index>(j));
      shapes.col(static_cast<Index>(i)) = assembler.dof_map().expand(reduced);
    }
    // A repeated speed (an isotropic rotor without gyroscopic coupling: a point mass,
    // or any rotor at rest) has a plane of shapes; its forward and backward circles
    // are the eigenvectors of the whirl form within that plane.
    for (std::size_t a = 0; a < s.speeds.size();) {
      std::size_t b = a + 1;
      while (b < s.speeds.size() && s.speeds[b] - s.speeds[a] <= 1e-9 * s.speeds[b]) ++b;
      if (b - a > 1) {
        const auto block = shapes.middleCols(static_cast<Index>(a), static_cast<Index>(b - a));
        Vector values;
        ComplexMatrix vectors;
        if (detail::hermitian_eigen(whirl_form(block), values, vectors))
          shapes.middleCols(static_cast<Index>(a), static_cast<Index>(b - a)) = ComplexMatrix(block * vectors);
      }
      a = b;
    }
    std::vector<UndampedCritical> out;
    for (std::size_t i = 0; i < s.speeds.size(); ++i) {
      ComplexVector shape = shapes.col(static_cast<Index>(i));
      Index at = 0;
      shape.cwiseAbs().maxCoeff(&at);
      shape /= shape(at);
      const WhirlResult w = classify_whirl(shape);
      // At rest (no gyroscopic moments) every mode whirls either way: each
      // frequency appears as a forward and a backward pair, or as planar modes of an
      // anisotropic rotor; keep each frequency once.
      if (!gyroscopic ? w.directivity < -0.05 : !(w.directivity > 0.05)) continue;
      out.push_back({s.speeds[i], w.directivity, std::move(shape)});
    }
    if (!gyroscopic)  // a repeated pair of planar modes: keep one of the two
      out.erase(std::unique(out.begin(), out.end(),
                            [](const UndampedCritical& a, const UndampedCritical& b) {
                              return std::abs(a.speed - b.speed) <= 1e-9 * b.speed;
                            }),
                out.end());
    return out;
  }

  Assembler assembler;
  std::vector<Index> dofs;
  std::vector<Index> position;
  Matrix M, G;
};

// The connection of bearing @p e of @p model, checked.
Connection bearing_at(const Model& model, Index e) {
  if (e < 0 || e >= static_cast<Index>(model.elements.size()))
    throw Error(fmt::format("no element {} in the model", e));
  const Element& element = model.elements[static_cast<std::size_t>(e)];
  const std::optional<Connection> c = element.connection();
  if (!c)
    throw Error(fmt::format("element {} ('{}') is a {}, not a bearing: only bearings can be varied", e + 1,
                            element.label(), element.kind()));
  return *c;
}

// The direct lateral stiffness k_yy or k_zz of bearing @p e at @p speed; NaN where it
// cannot be evaluated (a journal bearing whose equilibrium is not found there).
Real direct_stiffness(const Model& model, Index e, Dof d, Real speed) {
  try {
    const auto t = model.elements[static_cast<std::size_t>(e)].transmission(speed);
    return t ? (*t).K(static_cast<Index>(d), static_cast<Index>(d)) : nan;
  } catch (const Error&) {
    return nan;
  }
}

// The n lowest forward criticals at one stiffness, speed-dependent coefficients of
// the other elements at each critical itself.
std::vector<Real> criticals_of(const LateralSystem& system, int n, bool gyroscopic, SolverInfo& info,
                               Real start = 0.0) {
  std::vector<UndampedCritical> at_rest = system.forward(system.stiffness(start), gyroscopic);
  std::vector<Real> out(static_cast<std::size_t>(n), nan);
  for (int i = 0; i < n && i < static_cast<int>(at_rest.size()); ++i)
    out[static_cast<std::size_t>(i)] = at_rest[static_cast<std::size_t>(i)].speed;
  if (!system.assembler.speed_dependent()) return out;
  for (int i = 0; i < n; ++i) {
    Real& speed = out[static_cast<std::size_t>(i)];
    if (std::isnan(speed)) continue;
    bool converged = false;
    for (int it = 0; it < 100 && !converged; ++it) {
      std::vector<UndampedCritical> found;
      try {
        found = system.forward(system.stiffness(speed), gyroscopic);
      } catch (const Error& e) {  // a support not evaluable there (no journal equilibrium)
        if (info.converged())
          info.fail(SolverStatus::numerical_failure,
                    fmt::format("the {}. critical speed: the supports at {:.6g} rad/s: {}", i + 1, speed, e.what()));
        speed = nan;
        converged = true;
        break;
      }
      const Real next = i < static_cast<int>(found.size()) ? found[static_cast<std::size_t>(i)].speed : nan;
      if (std::isnan(next)) break;
      converged = std::abs(next - speed) <= 1e-10 * next;
      speed = next;
    }
    if (!converged && info.converged())
      info.fail(SolverStatus::not_converged,
                fmt::format("the speed-dependent coefficients gave no self-consistent {}. critical speed (fixed-point "
                            "iteration: 100 steps)",
                            i + 1));
  }
  return out;
}

}  // namespace

std::vector<Index> bearing_elements(const Model& model) {
  std::vector<Index> out;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const std::optional<Connection> c = model.elements[e].connection();
    if (!c) continue;
    const bool a = model.nodes[static_cast<std::size_t>(c->node_a)].rotating;
    const bool b = c->node_b && model.nodes[static_cast<std::size_t>(*c->node_b)].rotating;
    if (a != b) out.push_back(static_cast<Index>(e));
  }
  return out;
}

Index journal_node(const Model& model, Index element) {
  const Connection c = bearing_at(model, element);
  if (model.nodes[static_cast<std::size_t>(c.node_a)].rotating) return c.node_a;
  if (c.node_b && model.nodes[static_cast<std::size_t>(*c.node_b)].rotating) return *c.node_b;
  throw Error(fmt::format("element {} ('{}') holds no rotating node: it is not a bearing", element + 1,
                          model.elements[static_cast<std::size_t>(element)].label()));
}

Model with_bearing_stiffness(const Model& model, const std::vector<Index>& springs, Real k) {
  Model out = model;
  for (const Index e : springs) {
    const Connection connection = bearing_at(model, e);
    const Element& element = model.elements[static_cast<std::size_t>(e)];
    if (std::optional<Element> changed = element.with_lateral_stiffness(k)) {
      out.elements[static_cast<std::size_t>(e)] = std::move(*changed);
      continue;
    }
    // A bearing without the ability (the linearised journal and rolling bearings):
    // the lateral stiffness alone.
    SpringDamperCoefficients c;
    c.k[static_cast<std::size_t>(Dof::v)] = k;
    c.k[static_cast<std::size_t>(Dof::w)] = k;
    out.elements[static_cast<std::size_t>(e)] =
        Element(SpringDamper(connection.node_a, connection.node_b, c), element.label());
  }
  return out;
}

namespace {

// A bearing's direct stiffness alone: the terms of its stiffness that join a DOF to
// the same direction (k_yy, k_zz, and between its two nodes), without cross-coupling
// or damping, at each speed as the bearing gives it.
class DirectStiffness {
 public:
  explicit DirectStiffness(std::shared_ptr<const Element> bearing) : bearing_(std::move(bearing)) {}
  std::string_view kind() const { return "direct_stiffness"; }
  bool speed_dependent() const { return bearing_->speed_dependent(); }
  std::vector<Index> dofs() const { return bearing_->dofs(); }
  Connection connection() const { return *bearing_->connection(); }
  LocalMatrices local_matrices(const OperatingPoint& op) const {
    const LocalMatrices full = bearing_->local_matrices(op);
    LocalMatrices out;
    out.dofs = full.dofs;
    if (full.K.size() == 0) return out;
    out.K = Matrix::Zero(full.K.rows(), full.K.cols());
    for (std::size_t i = 0; i < full.dofs.size(); ++i)
      for (std::size_t j = 0; j < full.dofs.size(); ++j)
        if (full.dofs[i] % dofs_per_node == full.dofs[j] % dofs_per_node)
          out.K(static_cast<Index>(i), static_cast<Index>(j)) = full.K(static_cast<Index>(i), static_cast<Index>(j));
    return out;
  }
  Transmission transmission(Real speed) const {
    Transmission t = *bearing_->transmission(speed);
    for (Index i = 0; i < dofs_per_node; ++i)
      for (Index j = 0; j < dofs_per_node; ++j)
        if (i != j) t.K(i, j) = 0;
    t.C.setZero();
    return t;
  }

 private:
  std::shared_ptr<const Element> bearing_;
};

}  // namespace

Model with_direct_bearing_stiffness(const Model& model, const std::vector<Index>& bearings) {
  Model out = model;
  for (const Index e : bearings) {
    bearing_at(model, e);
    const Element& element = model.elements[static_cast<std::size_t>(e)];
    out.elements[static_cast<std::size_t>(e)] =
        Element(DirectStiffness(std::make_shared<const Element>(element)), element.label());
  }
  return out;
}

std::vector<UndampedCritical> undamped_critical_speeds(const Model& model, int n, bool gyroscopic, SolverInfo* info,
                                                       Real start) {
  const LateralSystem system(model);
  SolverInfo local;
  SolverInfo& record = info ? *info : local;
  const std::vector<Real> speeds = criticals_of(system, n, gyroscopic, record, start);
  std::vector<UndampedCritical> out;
  for (const Real s : speeds) {
    if (std::isnan(s)) break;
    // The shape at the converged speed: the mode whose speed it is.
    auto found = system.forward(system.stiffness(s), gyroscopic);
    auto best = std::min_element(found.begin(), found.end(), [s](const auto& a, const auto& b) {
      return std::abs(a.speed - s) < std::abs(b.speed - s);
    });
    UndampedCritical c = *best;
    c.speed = s;
    out.push_back(std::move(c));
  }
  return out;
}

CriticalSpeedMapResult run_critical_speed_map(const Model& model, const CriticalSpeedMapOptions& options) {
  if (!(options.k_low > 0) || !(options.k_high > options.k_low))
    throw Error(
        fmt::format("the stiffness range must have 0 < low < high, got {} to {} N/m", options.k_low, options.k_high));
  if (options.points < 2) throw Error(fmt::format("the map needs at least 2 stiffness values, got {}", options.points));
  if (options.criticals < 1)
    throw Error(fmt::format("the map needs at least 1 critical speed, got {}", options.criticals));
  CriticalSpeedMapResult result;
  result.springs = options.springs.empty() ? bearing_elements(model) : options.springs;
  if (result.springs.empty())
    throw Error(
        "the model has no bearings to vary: no spring–damper or bearing holds a rotating node to the ground "
        "or to a non-rotating node");
  for (const Index e : result.springs) bearing_at(model, e);

  const std::size_t np = static_cast<std::size_t>(options.points);
  result.stiffness.resize(np);
  result.criticals.assign(np, std::vector<Real>(static_cast<std::size_t>(options.criticals), nan));
  const Real l0 = std::log(options.k_low), l1 = std::log(options.k_high);
  for (std::size_t i = 0; i < np; ++i)
    result.stiffness[i] = std::exp(l0 + (l1 - l0) * static_cast<Real>(i) / static_cast<Real>(np - 1));

  std::vector<SolverInfo> infos(np);
  std::vector<char> done(np, 0);
  parallel_for(static_cast<Index>(np), options.n_threads, [&](Index i, int) {
    if (options.stop.requested()) return;
    const std::size_t k = static_cast<std::size_t>(i);
    const LateralSystem system(with_bearing_stiffness(model, result.springs, result.stiffness[k]));
    result.criticals[k] = criticals_of(system, options.criticals, options.gyroscopic, infos[k]);
    done[k] = 1;
  });
  for (std::size_t k = 0; k < np; ++k) {
    if (!done[k]) {
      result.info.fail(SolverStatus::interrupted, fmt::format("stopped after {} of {} stiffness values", k, np));
      result.stiffness.resize(k);
      result.criticals.resize(k);
      return result;
    }
    if (!infos[k].converged() && result.info.converged()) result.info = infos[k];
  }

  // The bearings' own curves, and where each meets each critical speed line.
  if (!(options.curve_stop > 0)) return result;
  const int nc = std::max(2, options.curve_points);
  for (const Index e : result.springs) {
    for (const Dof d : {Dof::v, Dof::w}) {
      BearingCurve curve{e, d == Dof::v ? "y" : "z", {}, {}};
      for (int j = 0; j < nc; ++j) {
        const Real speed = options.curve_stop * j / (nc - 1);
        curve.speeds.push_back(speed);
        curve.stiffness.push_back(direct_stiffness(model, e, d, speed));
      }
      result.curves.push_back(std::move(curve));
    }
  }
  for (const BearingCurve& curve : result.curves) {
    const Dof d = curve.direction == "y" ? Dof::v : Dof::w;
    // Ω_n(k(Ω)) for every n at once, the other elements at Ω itself.
    const auto criticals_at = [&](Real speed) {
      std::vector<Real> out(static_cast<std::size_t>(options.criticals), nan);
      const Real k = direct_stiffness(model, curve.element, d, speed);
      if (!(k > 0)) return out;
      const LateralSystem system(with_bearing_stiffness(model, result.springs, k));
      const auto found = system.forward(system.stiffness(speed), options.gyroscopic);
      for (std::size_t n = 0; n < out.size() && n < found.size(); ++n) out[n] = found[n].speed;
      return out;
    };
    std::vector<std::vector<Real>> grid;
    for (const Real speed : curve.speeds) grid.push_back(criticals_at(speed));
    for (int n = 1; n <= options.criticals; ++n) {
      const std::size_t i = static_cast<std::size_t>(n - 1);
      // h(Ω) = Ω_n(k(Ω)) − Ω falls once along the curve: the lines cross once.
      const auto h = [&](Real speed) { return criticals_at(speed)[i] - speed; };
      for (std::size_t j = 1; j < curve.speeds.size(); ++j) {
        const Real a = curve.speeds[j - 1], b = curve.speeds[j];
        const Real fa = grid[j - 1][i] - a, fb = grid[j][i] - b;
        if (!(std::isfinite(fa) && std::isfinite(fb) && fa * fb <= 0 && fa != 0)) continue;
        const RootResult r = brent_root(h, a, b, fa, fb, 1e-9 * b);
        result.intersections.push_back(
            {curve.element, curve.direction, n, r.x, direct_stiffness(model, curve.element, d, r.x)});
        break;
      }
    }
  }
  return result;
}

}  // namespace feran

#include <feran/analyses/modal/modal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <tuple>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/analyses/modal/whirl.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/components.hpp>

#include "solver_choice.hpp"
#include "state_eigen.hpp"

namespace feran {

const char* to_string(Whirl w) {
  switch (w) {
    case Whirl::forward:
      return "forward";
    case Whirl::backward:
      return "backward";
    case Whirl::mixed:
      return "mixed";
    case Whirl::planar:
      return "planar";
    case Whirl::none:
      return "none";
  }
  return "?";
}

const char* to_string(ModeType t) {
  switch (t) {
    case ModeType::lateral:
      return "lateral";
    case ModeType::axial:
      return "axial";
    case ModeType::torsional:
      return "torsional";
    case ModeType::coupled:
      return "coupled";
  }
  return "?";
}

const char* to_string(ModeShape s) {
  switch (s) {
    case ModeShape::none:
      return "none";
    case ModeShape::cylindrical:
      return "cylindrical";
    case ModeShape::conical:
      return "conical";
    case ModeShape::bending:
      return "bending";
  }
  return "?";
}

namespace {

int family_of(Index full_dof) {
  switch (static_cast<Dof>(full_dof % dofs_per_node)) {
    case Dof::u:
      return 1;
    case Dof::rx:
      return 2;
    default:
      return 0;  // lateral
  }
}

// Re-splits repeated eigenvalues (e.g. the forward/backward pairs of an isotropic
// rotor at rest, which the eigen solver returns in an arbitrary basis) into the
// combinations of extreme directivity: pure forward and backward circles.
void split_repeated(ComplexVector& values, ComplexMatrix& vectors, const DofMap& dofs) {
  const Index m = values.size();
  std::vector<Index> order(static_cast<std::size_t>(m));
  for (Index i = 0; i < m; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return values(a).imag() < values(b).imag(); });
  std::size_t start = 0;
  while (start < order.size()) {
    std::size_t end = start + 1;
    const Complex p0 = values(order[start]);
    // Repeated when equal to 1e-7 relative: far above round-off of the QR
    // algorithm (~1e-13 here), far below any physical split.
    while (end < order.size() &&
           magnitude(values(order[end]) - p0) <= tolerance::repeated_eigenvalue * std::max(magnitude(p0), 1e-300))
      ++end;
    if (end - start >= 2 && p0.imag() > 0.0) {
      ComplexMatrix phi(vectors.rows(), static_cast<Index>(end - start));
      for (std::size_t k = start; k < end; ++k) phi.col(static_cast<Index>(k - start)) = vectors.col(order[k]);
      const ComplexMatrix full = dofs.transformation().cast<Complex>() * phi;
      const ComplexMatrix hn = lateral_form(full);
      const ComplexMatrix hs = whirl_form(full);
      if (Eigen::LLT<ComplexMatrix>(hn).info() == Eigen::Success) {
        Eigen::GeneralizedSelfAdjointEigenSolver<ComplexMatrix> ges(hs, hn);
        if (ges.info() == Eigen::Success) {
          const ComplexMatrix split = phi * ges.eigenvectors();
          for (std::size_t k = start; k < end; ++k) {
            const auto c = static_cast<Index>(k - start);
            vectors.col(order[k]) = split.col(c).normalized();
          }
        }
      }
    }
    start = end;
  }
}

// Scales a full shape so that its largest component of the dominant family is 1.
ComplexVector normalise(const ComplexVector& full, ModeType type) {
  Index best = -1;
  Real best_abs = 0.0;
  for (Index i = 0; i < full.size(); ++i) {
    const auto d = static_cast<Dof>(i % dofs_per_node);
    const bool wanted = type == ModeType::axial       ? d == Dof::u
                        : type == ModeType::torsional ? d == Dof::rx
                                                      : (d == Dof::v || d == Dof::w);
    if (wanted && magnitude(full(i)) > best_abs) best = i, best_abs = magnitude(full(i));
  }
  if (best_abs == 0.0)
    for (Index i = 0; i < full.size(); ++i)
      if (magnitude(full(i)) > best_abs) best = i, best_abs = magnitude(full(i));
  if (best < 0) return full;
  return full / full(best);
}

// Groups of reduced DOFs that no nonzero entry of M, D or K couples, each in
// increasing order, the groups ordered by their first DOF (union–find).
std::vector<std::vector<Index>> decoupled_blocks(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K) {
  const std::vector<Index> component = connected_components(M.rows(), {&M, &D, &K}, true);
  std::vector<std::vector<Index>> blocks;
  for (Index i = 0; i < M.rows(); ++i) {
    const auto c = static_cast<std::size_t>(component[static_cast<std::size_t>(i)]);
    if (c == blocks.size()) blocks.emplace_back();
    blocks[c].push_back(i);
  }
  return blocks;
}

// The rows and columns @p dofs of @p A (@p local maps a DOF to its position in
// @p dofs, −1 outside).
SparseMatrix submatrix(const SparseMatrix& A, const std::vector<Index>& dofs, const std::vector<Index>& local) {
  std::vector<Eigen::Triplet<Real>> t;
  for (std::size_t c = 0; c < dofs.size(); ++c)
    for (SparseMatrix::InnerIterator it(A, dofs[c]); it; ++it) {
      const Index r = local[static_cast<std::size_t>(it.row())];
      if (r >= 0) t.emplace_back(r, static_cast<Index>(c), it.value());
    }
  const auto nb = static_cast<Index>(dofs.size());
  SparseMatrix out(nb, nb);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

// y = A·x for a real sparse A and a complex vector x.
ComplexVector times(const SparseMatrix& A, const ComplexVector& x) {
  ComplexVector y(A.rows());
  detail::real_times_complex(A, x.data(), y.data());
  return y;
}

}  // namespace

namespace detail {

// The complex (forward/backward) form of a block whose DOFs pair up (v with w, ry
// with rz) and whose matrices commute with the quarter turn J about the spin axis
// (J: v → w → −v, ry → rz → −ry), i.e. an axisymmetric rotor: on the subspace
// J·x = i·x, spanned by the columns (e_a − i·e_b)/√2 of U for each pair (a, b), the
// problem is Uᴴ(p²M + pD + K)U·y = 0, half the size (state_eigen.hpp). Sparse
// matrices for Arnoldi, dense ones for the dense solvers.
struct ComplexForm {
  std::vector<Index> a, b;  // the block's DOFs of each complex coordinate (v or ry, w or rz)
  detail::ComplexSparseMatrix M, D, K;
  ComplexMatrix Md, Dd, Kd;

  // x = U·y.
  ComplexVector expand(const ComplexVector& y) const {
    const Real r = 1.0 / std::sqrt(2.0);
    ComplexVector x(static_cast<Index>(2 * a.size()));
    for (std::size_t c = 0; c < a.size(); ++c) {
      const Complex yc = y(static_cast<Index>(c));
      x(a[c]) = r * yc;
      x(b[c]) = Complex(0.0, -r) * yc;
    }
    return x;
  }
};

}  // namespace detail

namespace {

using detail::ComplexForm;

// The pairing of the block's DOFs (empty unless every DOF has its twin in the block).
std::optional<ComplexForm> complex_pairs(const std::vector<Index>& dofs, const std::vector<Index>& local,
                                         const std::vector<Index>& twin) {
  const auto nb = static_cast<Index>(dofs.size());
  if (nb < 2 || nb % 2 != 0) return std::nullopt;
  ComplexForm f;
  for (Index i = 0; i < nb; ++i) {
    const Index t = twin[static_cast<std::size_t>(dofs[static_cast<std::size_t>(i)])];
    if (t == -1) continue;  // the second of a pair
    if (t < 0) return std::nullopt;
    const Index j = local[static_cast<std::size_t>(t)];
    if (j < 0) return std::nullopt;  // its twin is in another block
    f.a.push_back(i);
    f.b.push_back(j);
  }
  if (static_cast<Index>(2 * f.a.size()) != nb) return std::nullopt;
  return f;
}

// Commuting with J to round-off (an exactly axisymmetric model gives zero or a few
// ulps): the entries of AJ − JA, which are A(a,a') − A(b,b') and A(a,b') + A(b,a')
// over the pairs, at most 1e-12 of A's largest entry. Uᴴ·A·U has the entries
// (A(a,a') + A(b,b'))/2 − i·(A(a,b') − A(b,a'))/2, built here entry by entry from the
// nonzeros of A.
std::optional<ComplexForm> complex_form(const std::vector<Index>& dofs, const std::vector<Index>& local,
                                        const std::vector<Index>& twin, const SparseMatrix& M, const SparseMatrix& D,
                                        const SparseMatrix& K) {
  std::optional<ComplexForm> f = complex_pairs(dofs, local, twin);
  if (!f) return std::nullopt;
  const auto nb = static_cast<Index>(dofs.size()), nc = static_cast<Index>(f->a.size());
  // Each DOF's complex coordinate, and whether it is the second of its pair.
  std::vector<Index> coord(static_cast<std::size_t>(nb));
  std::vector<char> second(static_cast<std::size_t>(nb), 0);
  for (Index c = 0; c < nc; ++c) {
    coord[static_cast<std::size_t>(f->a[static_cast<std::size_t>(c)])] = c;
    coord[static_cast<std::size_t>(f->b[static_cast<std::size_t>(c)])] = c;
    second[static_cast<std::size_t>(f->b[static_cast<std::size_t>(c)])] = 1;
  }
  auto transform = [&](const SparseMatrix& A, detail::ComplexSparseMatrix& Ac) {
    std::vector<Eigen::Triplet<Complex>> t;
    std::vector<Eigen::Triplet<Real>> p, q;  // A(a,a') − A(b,b') and A(a,b') + A(b,a')
    t.reserve(static_cast<std::size_t>(A.nonZeros()));
    Real a_max = 0.0;
    for (Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
        const Index i = it.row(), ci = coord[static_cast<std::size_t>(i)], cj = coord[static_cast<std::size_t>(j)];
        const Real v = it.value();
        a_max = std::max(a_max, std::abs(v));
        const bool bi = second[static_cast<std::size_t>(i)] != 0, bj = second[static_cast<std::size_t>(j)] != 0;
        if (bi == bj) {
          t.emplace_back(ci, cj, Complex(0.5 * v, 0.0));
          p.emplace_back(ci, cj, bi ? -v : v);
        } else {
          t.emplace_back(ci, cj, Complex(0.0, bj ? -0.5 * v : 0.5 * v));
          q.emplace_back(ci, cj, v);
        }
      }
    SparseMatrix P(nc, nc), Q(nc, nc);
    P.setFromTriplets(p.begin(), p.end());
    Q.setFromTriplets(q.begin(), q.end());
    const Real c_max = std::max(P.nonZeros() > 0 ? P.coeffs().cwiseAbs().maxCoeff() : 0.0,
                                Q.nonZeros() > 0 ? Q.coeffs().cwiseAbs().maxCoeff() : 0.0);
    if (c_max > tolerance::symmetry * a_max) return false;
    Ac.resize(nc, nc);
    Ac.setFromTriplets(t.begin(), t.end());
    return true;
  };
  if (!transform(M, f->M) || !transform(D, f->D) || !transform(K, f->K)) return std::nullopt;
  return f;
}

// The same from dense matrices, entry by entry (for the dense solvers: 7 % less work
// per solve of a small rotor than forming the sparse form and converting it).
std::optional<ComplexForm> dense_complex_form(const std::vector<Index>& dofs, const std::vector<Index>& local,
                                              const std::vector<Index>& twin, const Matrix& M, const Matrix& D,
                                              const Matrix& K) {
  std::optional<ComplexForm> f = complex_pairs(dofs, local, twin);
  if (!f) return std::nullopt;
  const auto nc = static_cast<Index>(f->a.size());
  auto transform = [&](const Matrix& A, ComplexMatrix& Ac) {
    const Real tol = tolerance::symmetry * (A.size() > 0 ? A.cwiseAbs().maxCoeff() : 0.0);
    Ac.resize(nc, nc);
    for (Index j = 0; j < nc; ++j) {
      const Index a2 = f->a[static_cast<std::size_t>(j)], b2 = f->b[static_cast<std::size_t>(j)];
      for (Index i = 0; i < nc; ++i) {
        const Index a1 = f->a[static_cast<std::size_t>(i)], b1 = f->b[static_cast<std::size_t>(i)];
        const Real aa = A(a1, a2), bb = A(b1, b2), ab = A(a1, b2), ba = A(b1, a2);
        if (std::abs(aa - bb) > tol || std::abs(ab + ba) > tol) return false;
        Ac(i, j) = Complex(0.5 * (aa + bb), -0.5 * (ab - ba));
      }
    }
    return true;
  };
  if (!transform(M, f->Md) || !transform(D, f->Dd) || !transform(K, f->Kd)) return std::nullopt;
  return f;
}

// The real problem's eigenpairs (Im p ≥ 0) from the complex form's: w with Im w > 0
// is the mode (w, U·y); Im w < 0 the mode (w̄, conj(U·y)) on the conjugate subspace;
// a real w (within round-off of the complex arithmetic, 1e-10 relative) or a
// rigid-body one (|w| < @p zero_tol and strain energy below @p rigid_tol times the
// kinetic, of the block's real @p M and @p K, the criterion of ModalSolver) a double
// real eigenvalue with the real vectors Re(U·y) and Im(U·y).
detail::StateEigenpairs real_pairs(const detail::StateEigenpairs& c, const ComplexForm& f, const SparseMatrix& M,
                                   const SparseMatrix& K, Real zero_tol, Real rigid_tol) {
  detail::StateEigenpairs out;
  out.info = c.info;
  std::vector<Complex> values;
  std::vector<ComplexVector> vectors;
  for (Index j = 0; j < c.values.size(); ++j) {
    const Complex w = c.values(j);
    const ComplexVector phi = f.expand(c.vectors.col(j));
    auto rigid = [&] {
      const Real kinetic = std::real(phi.dot(times(M, phi))), strain = std::real(phi.dot(times(K, phi)));
      return kinetic > 0.0 && strain < rigid_tol * kinetic;
    };
    if (std::abs(w.imag()) <= tolerance::real_eigenvalue * magnitude(w) || (magnitude(w) < zero_tol && rigid())) {
      for (const Vector& part : {Vector(phi.real()), Vector(phi.imag())}) {
        const Real norm = part.norm();
        if (norm == 0.0) continue;
        values.emplace_back(w.real(), 0.0);
        vectors.emplace_back((part / norm).cast<Complex>());
      }
    } else if (w.imag() > 0.0) {
      values.push_back(w);
      vectors.push_back(phi.normalized());
    } else {
      values.push_back(std::conj(w));
      vectors.push_back(phi.conjugate().normalized());
    }
  }
  out.values.resize(static_cast<Index>(values.size()));
  out.vectors.resize(static_cast<Index>(2 * f.a.size()), static_cast<Index>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) {
    out.values(static_cast<Index>(k)) = values[k];
    out.vectors.col(static_cast<Index>(k)) = vectors[k];
  }
  return out;
}

// The most general method any decoupled block needed names the solve.
int method_rank(SolverMethod method) {
  switch (method) {
    case SolverMethod::dense_hermitian:
      return 0;
    case SolverMethod::dense_qr:
      return 1;
    case SolverMethod::shift_invert_lanczos:
      return 2;
    default:
      return 3;
  }
}

}  // namespace

// Modes of DOF groups whose matrices do not depend on speed, keyed by (first DOF,
// size, modes asked for, Arnoldi or dense). Filled on first use; concurrent solves
// may both compute an entry (the same values), the first stored is kept.
struct ModalSolver::BlockCache {
  std::mutex mutex;
  std::map<std::tuple<Index, Index, Index, bool>, detail::StateEigenpairs> parts;
};

ModalSolver::ModalSolver(const Model& model, ModalOptions options) : ModalSolver(model, options, nullptr) {}

ModalSolver::ModalSolver(const Model& model, ModalOptions options, std::shared_ptr<const Assembler> assembled)
    : options_(options),
      // Supports (fluid-film bearings) enter as their tangent about the equilibrium at
      // each speed, which an assembly of the model itself does not hold.
      linear_(has_supports(model) ? std::make_shared<const Model>(linearised(model)) : nullptr),
      assembler_(linear_     ? std::make_shared<const Assembler>(*linear_)
                 : assembled ? std::move(assembled)
                             : std::make_shared<const Assembler>(model)),
      operating_(operating_series(model)),
      cache_(std::make_shared<BlockCache>()) {
  for (const Force& f : model.forces)
    if (f.supports()) supports_.push_back(f);
  for (Index i = 0; i < model.n_nodes(); ++i)
    if (model.nodes[static_cast<std::size_t>(i)].rotating)
      rotor_nodes_.emplace_back(i, model.nodes[static_cast<std::size_t>(i)].x);
  const SystemMatrices sys = assembler_->at(0.0);
  lambda_max_ = 0.0;
  for (Index i = 0; i < sys.M.rows(); ++i)
    if (sys.M.coeff(i, i) > 0) lambda_max_ = std::max(lambda_max_, sys.K.coeff(i, i) / sys.M.coeff(i, i));
  if (lambda_max_ <= 0.0) lambda_max_ = 1.0;
  // DOFs reached by Ω·G, Ω·K_i or a speed-dependent element (the pattern of every
  // entry such elements can touch, explicit zeros included).
  speed_touched_.assign(static_cast<std::size_t>(sys.M.rows()), 0);
  SystemMatrices variable;
  assembler_->variable_values(0.0, variable);
  // Complex pairs: the reduced DOFs whose full DOFs are v–w or ry–rz of one node (a
  // rigid link's master DOFs included). The pairing only proposes J; whether the
  // split is exact is decided by J commuting with the block's matrices.
  const DofMap& map = assembler_->dof_map();
  const SparseMatrix& T = map.transformation();
  const Index n = T.cols();
  std::vector<Index> reduced_of(static_cast<std::size_t>(T.rows()), -1);
  for (Index i = 0; i < n; ++i) reduced_of[static_cast<std::size_t>(map.full_dof(i))] = i;
  twin_.assign(static_cast<std::size_t>(n), -2);
  for (Index i = 0; i < n; ++i) {
    const Index full = map.full_dof(i);
    if (reduced_of[static_cast<std::size_t>(full)] != i) continue;
    const auto d = static_cast<Dof>(full % dofs_per_node);
    if (d != Dof::v && d != Dof::ry) continue;
    const Index partner = reduced_of[static_cast<std::size_t>(full + 1)];  // w after v, rz after ry
    if (partner < 0) continue;
    twin_[static_cast<std::size_t>(i)] = partner;
    twin_[static_cast<std::size_t>(partner)] = -1;
  }

  for (const SparseMatrix* A : {&sys.G, &sys.Ki, static_cast<const SparseMatrix*>(&variable.M)})
    for (Index j = 0; j < A->outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(*A, j); it; ++it) {
        if (A != &variable.M && it.value() == 0.0) continue;
        speed_touched_[static_cast<std::size_t>(it.row())] = 1;
        speed_touched_[static_cast<std::size_t>(j)] = 1;
      }
}

namespace {

// A real sparse matrix equal to s times its transpose, to round-off
// (tolerance::symmetry of its largest entry).
bool symmetric(const SparseMatrix& A, Real s) {
  const Real scale = A.nonZeros() > 0 ? A.coeffs().cwiseAbs().maxCoeff() : 0.0;
  const SparseMatrix At = A.transpose();
  const SparseMatrix diff = A - s * At;
  return diff.nonZeros() == 0 || diff.coeffs().cwiseAbs().maxCoeff() <= tolerance::symmetry * scale;
}

}  // namespace

ModalSolver::Choice ModalSolver::choice() const {
  if (options_.solver == EigenSolver::dense) return Choice::dense;
  if (options_.solver == EigenSolver::sparse) return Choice::sparse;
  // All modes of a model up to dense_limit: the dense solver is the one that gives
  // them all; otherwise each block by the cost model (12 modes when none are asked).
  if (options_.n_modes == 0 && assembler_->dof_map().n_reduced() <= options_.dense_limit) return Choice::dense;
  return Choice::by_cost;
}

ModalResult ModalSolver::solve(Real speed) const {
  require_running(supports_, speed);
  return assembler_->frequency_dependent() ? solve_self_consistent(speed) : solve_at(speed, std::nullopt);
}

ModalResult ModalSolver::solve_self_consistent(Real speed) const {
  // The modes with synchronous coefficients (ω₀ = |Ω|, those a run-up integrates) fix
  // how many modes are wanted. The oscillatory ones are then taken slot by slot: the
  // i-th lowest frequency f_i(ω) of the solve with the coefficients at ω is a
  // continuous function of ω (ordered values are, where modes cross too), and its
  // fixed point ω = f_i(ω) is the i-th mode at its own frequency — one fixed point per
  // slot while the coefficients vary slowly enough (|f_i'| < 1), so a degenerate start
  // (an isotropic rotor at rest whose supports then part its pair) cannot lose a mode.
  // One fixed-point step, then secant steps on h(ω) = f_i(ω) − ω. Non-oscillatory
  // modes (Im p = 0) are taken with the coefficients at ω = 0.
  const Real omega0 = std::abs(speed);
  ModalResult result = solve_at(speed, omega0);
  result.frequency_dependent = true;
  if (!result.info.converged()) return result;
  const Real zero_tol = this->zero_tol();
  constexpr Real rtol = 1e-9;  // on |f_i(ω) − ω| relative to ω
  constexpr int max_iterations = 40;
  std::map<Real, ModalResult> solved;  // the solves at each trial frequency, shared by the slots
  solved.emplace(omega0, result);
  const auto at = [&](Real omega) -> const ModalResult& {
    auto it = solved.find(omega);
    if (it == solved.end()) it = solved.emplace(omega, solve_at(speed, omega)).first;
    return it->second;
  };
  // The oscillatory modes of a solve, by frequency (ModalResult lists them so).
  const auto oscillatory = [](const ModalResult& r) {
    std::vector<const Mode*> out;
    for (const Mode& m : r.modes)
      if (m.oscillatory) out.push_back(&m);
    return out;
  };

  std::vector<Mode> settled;
  std::size_t n_still = 0;
  for (const Mode& m : result.modes) n_still += m.oscillatory ? 0 : 1;
  if (n_still > 0) {
    const ModalResult& r0 = at(0.0);
    for (const Mode& m : r0.modes)
      if (!m.oscillatory && settled.size() < n_still) settled.push_back(m);
  }
  const std::vector<const Mode*> starts = oscillatory(result);  // result.modes stays as it is until the end
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Mode start = *starts[i];
    Mode mode = start;
    Real w_prev = omega0, h_prev = mode.eigenvalue.imag() - omega0;
    Real w = mode.eigenvalue.imag();
    Index iterations = 0;
    bool converged = std::abs(h_prev) <= rtol * std::max(omega0, zero_tol);
    std::string trouble;
    while (!converged && iterations < max_iterations) {
      const ModalResult& r = at(w);
      ++iterations;
      if (!r.info.converged()) {
        trouble = r.info.message;
        break;
      }
      const std::vector<const Mode*> modes = oscillatory(r);
      if (modes.size() <= i) {
        trouble =
            fmt::format("with the coefficients at {:.6g} Hz it has no oscillatory mode of its rank", rad_to_hz(w));
        break;
      }
      mode = *modes[i];
      const Real h = mode.eigenvalue.imag() - w;
      if (std::abs(h) <= rtol * std::max(w, zero_tol)) {
        converged = true;
        break;
      }
      Real next = h != h_prev ? w - h * (w - w_prev) / (h - h_prev) : mode.eigenvalue.imag();
      if (!std::isfinite(next) || next < 0.0) next = mode.eigenvalue.imag();
      w_prev = w;
      h_prev = h;
      w = next;
    }
    result.frequency_iterations = std::max(result.frequency_iterations, iterations);
    if (!converged && result.info.converged())
      result.info.fail(
          SolverStatus::not_converged,
          fmt::format("the mode near {:.6g} Hz at {:.6g} Hz did not settle on its own frequency "
                      "(frequency-dependent coefficients) {}; its last iterate is kept",
                      start.frequency_hz, rad_to_hz(speed),
                      trouble.empty() ? fmt::format("in {} eigen solves", max_iterations) : "— " + trouble));
    settled.push_back(std::move(mode));
  }
  result.info.iterations = 0;
  for (const auto& [w, r] : solved) result.info.iterations += r.info.iterations;
  std::stable_sort(settled.begin(), settled.end(),
                   [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
  result.modes = std::move(settled);
  return result;
}

// One decoupled block of a solve: its matrices, the solver it takes and the forms that
// solver needs.
struct ModalSolver::Block {
  // The submatrices of (M, D, K) on @p dofs_ (local: each DOF's index in the block).
  Block(const std::vector<Index>& dofs_, const std::vector<Index>& local, const SparseMatrix& M_,
        const SparseMatrix& D_, const SparseMatrix& K_)
      : dofs(dofs_), M(submatrix(M_, dofs_, local)), D(submatrix(D_, dofs_, local)), K(submatrix(K_, dofs_, local)) {}
  const std::vector<Index>& dofs;  // its reduced DOFs
  SparseMatrix M, D, K;
  Matrix Md, Dd, Kd;                      // dense copies, for the dense solvers
  std::optional<detail::ComplexForm> cf;  // forward/backward coordinates, where they apply
  Index wanted = 0;                       // modes wanted of it
  bool arnoldi = false;                   // Arnoldi (else a dense solver)
  bool constant = false;                  // no speed-dependent entry touches it: its modes are cached
};

Real ModalSolver::zero_tol() const { return 1e-6 * std::sqrt(lambda_max_); }

Index ModalSolver::wanted() const {
  return options_.n_modes > 0 ? options_.n_modes : choice() != Choice::dense ? 12 : 0;
}

ModalResult ModalSolver::solve_at(Real speed, std::optional<Real> frequency) const {
  // The assembled matrices themselves when no element depends on speed (no copy).
  const SystemMatrices varying = assembler_->speed_dependent() ? assembler_->at(speed, frequency) : SystemMatrices{};
  const SystemMatrices& sys = assembler_->speed_dependent() ? varying : assembler_->constant();
  const SparseMatrix D = sys.damping(speed);
  const SparseMatrix K = sys.stiffness(speed);

  ModalResult result;
  result.speed = speed;
  if (!sys.M.coeffs().allFinite() || !D.coeffs().allFinite() || !K.coeffs().allFinite()) {
    result.info.fail(SolverStatus::numerical_failure,
                     fmt::format("the matrices at {:.6g} Hz hold non-finite values (overflow: check the model's "
                                 "magnitudes)",
                                 rad_to_hz(speed)));
    return result;
  }
  detail::StateEigenpairs pairs = eigenpairs(sys.M, D, K, result.complex_form);
  result.info = pairs.info;
  if (!pairs.values.allFinite() || !pairs.vectors.allFinite()) {
    // Overflow in the matrices or the solve: no mode is to be trusted.
    result.info.fail(SolverStatus::numerical_failure,
                     fmt::format("the eigen solve at {:.6g} Hz gave non-finite values (overflow: check the "
                                 "model's magnitudes)",
                                 rad_to_hz(speed)));
    return result;
  }
  split_repeated(pairs.values, pairs.vectors, assembler_->dof_map());
  add_modes(pairs, sys, result);
  keep_lowest(result);
  return result;
}

detail::StateEigenpairs ModalSolver::eigenpairs(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K,
                                                bool& any_complex) const {
  // Each decoupled block on its own; the lowest modes of the whole are among the
  // lowest `wanted` of each block. The largest block goes first: its `wanted`-th
  // lowest |p| is the cutoff the other blocks' modes must beat to count.
  const Index n = M.rows();
  detail::StateEigenpairs pairs;
  pairs.info.method = SolverMethod::dense_qr;
  pairs.vectors = ComplexMatrix::Zero(n, 0);
  std::vector<Index> local(static_cast<std::size_t>(n), -1);
  std::vector<std::vector<Index>> blocks = decoupled_blocks(M, D, K);
  std::stable_sort(blocks.begin(), blocks.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  Real cutoff = std::numeric_limits<Real>::infinity();
  any_complex = false;
  for (const std::vector<Index>& dofs : blocks) {
    const Block b = block(dofs, local, M, D, K);
    any_complex = any_complex || b.cf.has_value();
    const bool first = &dofs == &blocks.front();
    const detail::StateEigenpairs part =
        b.arnoldi ? lowest_by_arnoldi(b, first, cutoff) : block_modes(b, b.wanted, false);
    if (first || method_rank(part.info.method) > method_rank(pairs.info.method)) pairs.info.method = part.info.method;
    pairs.info.iterations += part.info.iterations;
    pairs.info.n_converged += part.info.n_converged;
    if (!part.info.converged() && pairs.info.converged()) pairs.info.fail(part.info.status, part.info.message);
    const Index m0 = pairs.values.size(), m = part.values.size(), nb = static_cast<Index>(dofs.size());
    pairs.values.conservativeResize(m0 + m);
    pairs.values.tail(m) = part.values;
    pairs.vectors.conservativeResize(n, m0 + m);
    pairs.vectors.rightCols(m).setZero();
    for (Index i = 0; i < nb; ++i) pairs.vectors.row(dofs[static_cast<std::size_t>(i)]).tail(m) = part.vectors.row(i);
  }
  return pairs;
}

ModalSolver::Block ModalSolver::block(const std::vector<Index>& dofs, std::vector<Index>& local, const SparseMatrix& M,
                                      const SparseMatrix& D, const SparseMatrix& K) const {
  const auto nb = static_cast<Index>(dofs.size());
  for (Index i = 0; i < nb; ++i) local[static_cast<std::size_t>(dofs[static_cast<std::size_t>(i)])] = i;
  Block b(dofs, local, M, D, K);
  const Choice choice = this->choice();
  b.wanted = std::min(wanted(), nb - 1);
  // Arnoldi pays only when its subspace is smaller than the block's state space;
  // the automatic choice takes it where the cost model expects it to be cheaper.
  b.arnoldi = choice != Choice::dense && b.wanted > 0 && detail::arnoldi_subspace_size(nb, b.wanted) < 2 * nb;
  const bool sparse_form = b.arnoldi && options_.complex_form;  // tried on the sparse matrices
  if (sparse_form) b.cf = complex_form(dofs, local, twin_, b.M, b.D, b.K);
  if (b.arnoldi && choice == Choice::by_cost) {
    const detail::BlockForm form{b.cf.has_value(),
                                 options_.hermitian_form && symmetric(b.D, -1.0) && symmetric(b.K, 1.0)};
    b.arnoldi = detail::arnoldi_cheaper(nb, b.wanted, form);
  }
  if (!b.arnoldi) {
    b.Md = b.M;
    b.Dd = b.D;
    b.Kd = b.K;
    if (b.cf) {
      b.cf->Md = ComplexMatrix(b.cf->M);
      b.cf->Dd = ComplexMatrix(b.cf->D);
      b.cf->Kd = ComplexMatrix(b.cf->K);
    } else if (options_.complex_form && !sparse_form) {
      b.cf = dense_complex_form(dofs, local, twin_, b.Md, b.Dd, b.Kd);
    }
  }
  for (Index d : dofs) local[static_cast<std::size_t>(d)] = -1;
  b.constant =
      std::none_of(dofs.begin(), dofs.end(), [&](Index d) { return speed_touched_[static_cast<std::size_t>(d)] != 0; });
  return b;
}

detail::StateEigenpairs ModalSolver::lowest_by_arnoldi(const Block& b, bool first, Real& cutoff) const {
  // Past the largest block, a few modes first and more only while all of them lie
  // below the cutoff: fewer wanted modes converge faster, and a block whose higher
  // modes cluster (e.g. torsion between heavy disks) does not stall the iteration.
  detail::StateEigenpairs part;
  for (Index k = first ? b.wanted : std::min<Index>(b.wanted, 4);; k = std::min(b.wanted, 2 * k)) {
    part = block_modes(b, k, true);
    const bool beyond = part.values.size() > 0 && part.values.cwiseAbs().maxCoeff() > cutoff;
    if (!part.info.converged() || k == b.wanted || beyond) break;
  }
  if (first) {
    std::vector<Real> magnitudes;
    for (const Complex& p : part.values)
      if (!options_.oscillatory_only || p.imag() > 0.0) magnitudes.push_back(magnitude(p));
    std::sort(magnitudes.begin(), magnitudes.end());
    const Index all = wanted();
    if (static_cast<Index>(magnitudes.size()) >= all) cutoff = magnitudes[static_cast<std::size_t>(all - 1)];
  }
  return part;
}

detail::StateEigenpairs ModalSolver::block_modes(const Block& b, Index count, bool arnoldi) const {
  const auto key = std::make_tuple(b.dofs.front(), static_cast<Index>(b.dofs.size()), count, arnoldi);
  if (b.constant) {
    const std::lock_guard<std::mutex> lock(cache_->mutex);
    const auto it = cache_->parts.find(key);
    if (it != cache_->parts.end()) return it->second;
  }
  const Real zero_tol = this->zero_tol(), rigid_tol = tolerance::rigid_body * lambda_max_;
  // Automatic shift: just below zero, so that rigid-body modes (p = 0) do not make
  // K + σD + σ²M singular, yet close enough to find the lowest modes first.
  const Real sigma = std::isnan(options_.shift) ? -std::max(1.0, 1e-6 * std::sqrt(lambda_max_)) : options_.shift;
  const std::optional<detail::ComplexForm>& cf = b.cf;
  detail::StateEigenpairs computed;
  bool solved = false;
  const detail::DenseSelection selection{count, options_.oscillatory_only, zero_tol};
  if (!arnoldi && options_.hermitian_form) {
    // An undamped gyroscopic block: the Hermitian-definite form (either form of
    // coordinates); the general QR when it does not apply.
    const std::optional<detail::StateEigenpairs> h =
        cf ? detail::dense_gyroscopic_eigen(cf->Md, cf->Dd, cf->Kd, selection, true)
           : detail::dense_gyroscopic_eigen(b.Md.cast<Complex>(), b.Dd.cast<Complex>(), b.Kd.cast<Complex>(), selection,
                                            false);
    if (h) {
      computed = cf ? real_pairs(*h, *cf, b.M, b.K, zero_tol, rigid_tol) : *h;
      solved = true;
    }
  }
  if (arnoldi && !cf && options_.hermitian_form) {
    // No damping or gyroscopic terms (axial, torsional, bending at rest):
    // symmetric Lanczos on a problem of half the state order.
    if (std::optional<detail::StateEigenpairs> u = detail::sparse_undamped_eigen(b.M, b.D, b.K, count, sigma)) {
      computed = std::move(*u);
      solved = true;
    }
  }
  if (!solved && cf) {
    // Forward/backward complex coordinates: half the order (the real form if it fails).
    computed = arnoldi ? detail::sparse_complex_eigen(cf->M, cf->D, cf->K, count, sigma)
                       : detail::dense_complex_eigen(cf->Md, cf->Dd, cf->Kd, selection);
    solved = computed.info.converged();
    if (solved) computed = real_pairs(computed, *cf, b.M, b.K, zero_tol, rigid_tol);
  }
  if (!solved)
    computed = arnoldi ? detail::sparse_state_eigen(b.M, b.D, b.K, count, sigma)
                       : detail::dense_state_eigen(b.Md, b.Dd, b.Kd, selection);
  if (b.constant && computed.info.converged()) {
    const std::lock_guard<std::mutex> lock(cache_->mutex);
    cache_->parts.emplace(key, computed);
  }
  return computed;
}

void ModalSolver::add_modes(const detail::StateEigenpairs& pairs, const SystemMatrices& sys,
                            ModalResult& result) const {
  const Real rigid_tol = tolerance::rigid_body * lambda_max_, zero_tol = this->zero_tol();
  // A free rigid-body motion is a double zero eigenvalue of the state matrix (a Jordan
  // block): a solver of the state problem may return it twice as a real zero with the
  // same shape. It is one mode; these are the M-weighted shapes of the real rigid-body
  // zeros listed so far.
  std::vector<std::pair<ComplexVector, Real>> rigid_shapes;  // (M·φ, φᴴMφ)
  const auto listed_rigid = [&](const ComplexVector& phi, const ComplexVector& Mphi, Real kinetic) {
    for (const auto& [Mq, kq] : rigid_shapes)
      if (abs2(phi.dot(Mq)) > (1.0 - tolerance::repeated_eigenvalue) * kinetic * kq) return true;
    rigid_shapes.emplace_back(Mphi, kinetic);
    return false;
  };
  for (Index j = 0; j < pairs.values.size(); ++j) {
    Mode mode;
    const ComplexVector phi = pairs.vectors.col(j);
    const ComplexVector Mphi = times(sys.M, phi);
    const Real kinetic = phi.dot(Mphi).real();
    const Real strain = phi.dot(times(sys.K, phi)).real();  // of K's symmetric part
    // |strain|: a negative stiffness (divergence) stores negative strain energy and is
    // no rigid-body mode.
    mode.rigid_body = kinetic > 0 && std::abs(strain) / kinetic < rigid_tol;
    Complex p = pairs.values(j);
    if (mode.rigid_body && magnitude(p) < zero_tol) {
      // Only real zeros: a tiny conjugate pair stands for two real motions at once.
      if (p.imag() == 0.0 && listed_rigid(phi, Mphi, kinetic)) continue;
      p = 0.0;
    }
    mode.eigenvalue = p;
    mode.oscillatory = p.imag() > 0.0;
    mode.frequency_hz = p.imag() / (2.0 * pi);
    // A zero eigenvalue (rigid-body motion) has no damping ratio.
    mode.damping_ratio = magnitude(p) > 0 ? -p.real() / magnitude(p) : std::numeric_limits<Real>::quiet_NaN();
    if (mode.oscillatory) mode.log_decrement = 2.0 * pi * (-p.real()) / p.imag();
    if (options_.oscillatory_only && !mode.oscillatory) {
      if (!mode.rigid_body && p.imag() == 0.0 && p.real() > result.divergence) result.divergence = p.real();
      continue;
    }
    describe(mode, phi, Mphi);
    result.modes.push_back(std::move(mode));
  }
}

void ModalSolver::describe(Mode& mode, const ComplexVector& phi, const ComplexVector& Mphi) const {
  const DofMap& map = assembler_->dof_map();
  Real fam[3] = {0, 0, 0};
  for (Index i = 0; i < phi.size(); ++i) fam[family_of(map.full_dof(i))] += (std::conj(phi(i)) * Mphi(i)).real();
  const Real total = fam[0] + fam[1] + fam[2];
  const int dominant = static_cast<int>(std::max_element(fam, fam + 3) - fam);
  // A family holding 80 % of the kinetic energy names the mode.
  mode.type = total > 0 && fam[dominant] < 0.8 * total ? ModeType::coupled
              : dominant == 0                          ? ModeType::lateral
              : dominant == 1                          ? ModeType::axial
                                                       : ModeType::torsional;
  const ComplexVector full = times(map.transformation(), phi);
  const WhirlResult whirl = classify_whirl(full);
  mode.whirl = whirl.whirl;
  mode.directivity = whirl.directivity;
  if (mode.type == ModeType::axial || mode.type == ModeType::torsional) {
    mode.whirl = Whirl::none;
    mode.directivity = std::numeric_limits<Real>::quiet_NaN();
  } else {
    const ShapeResult shape = classify_shape(full, rotor_nodes_);
    mode.bending = shape.bending;
    mode.shape_kind = shape.kind;
  }
  mode.reduced_shape = phi;
  if (options_.shapes) mode.shape = normalise(full, mode.type);
}

void ModalSolver::keep_lowest(ModalResult& result) const {
  // The lowest modes are those nearest the origin of the complex plane: sorting by
  // |p| keeps heavily overdamped modes (p far out on the negative real axis, with a
  // small imaginary part under rotating damping) from displacing the physical ones.
  auto by_magnitude = [](const Mode& a, const Mode& b) { return abs2(a.eigenvalue) < abs2(b.eigenvalue); };
  std::stable_sort(result.modes.begin(), result.modes.end(), by_magnitude);
  const Index limit = wanted();
  if (limit > 0 && static_cast<Index>(result.modes.size()) > limit) {
    auto keep = static_cast<std::size_t>(limit);
    // Keep a repeated pair whole (isotropic rotors at rest), as split_repeated does.
    while (options_.oscillatory_only && keep < result.modes.size() &&
           magnitude(result.modes[keep].eigenvalue - result.modes[keep - 1].eigenvalue) <=
               tolerance::repeated_eigenvalue * magnitude(result.modes[keep].eigenvalue))
      ++keep;
    result.modes.resize(keep);
  }
  std::stable_sort(result.modes.begin(), result.modes.end(),
                   [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
}

Real mac(const ComplexVector& a, const ComplexVector& b) {
  const Real na = a.squaredNorm(), nb = b.squaredNorm();
  if (na == 0.0 || nb == 0.0) return 0.0;
  return abs2(a.dot(b)) / (na * nb);
}

std::vector<OperatingSeries> ModalSolver::operating_at(const std::vector<Real>& speeds) const {
  std::vector<OperatingSeries> out = operating_;
  if (linear_)
    for (const Real speed : speeds) append_at_equilibrium(out, *linear_, speed);
  return out;
}

ModalResult run_modal(const Model& model, Real speed, const ModalOptions& options,
                      std::shared_ptr<const Assembler> assembled) {
  const ModalSolver solver(model, options, std::move(assembled));
  ModalResult result = solver.solve(speed);
  if (result.info.converged()) result.operating = solver.operating_at({speed});
  return result;
}

}  // namespace feran

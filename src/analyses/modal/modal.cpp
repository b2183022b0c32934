#include <feran/analyses/modal/modal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include <feran/analyses/modal/whirl.hpp>

#include "state_eigen.hpp"

namespace feran {

const char* to_string(Whirl w) {
  switch (w) {
    case Whirl::forward: return "forward";
    case Whirl::backward: return "backward";
    case Whirl::mixed: return "mixed";
    case Whirl::planar: return "planar";
    case Whirl::none: return "none";
  }
  return "?";
}

const char* to_string(ModeType t) {
  switch (t) {
    case ModeType::lateral: return "lateral";
    case ModeType::axial: return "axial";
    case ModeType::torsional: return "torsional";
    case ModeType::coupled: return "coupled";
  }
  return "?";
}

namespace {

int family_of(Index full_dof) {
  switch (static_cast<Dof>(full_dof % dofs_per_node)) {
    case Dof::u: return 1;
    case Dof::rx: return 2;
    default: return 0;  // lateral
  }
}

// Re-splits repeated eigenvalues (e.g. the forward/backward pairs of an isotropic
// rotor at rest, which the eigen solver returns in an arbitrary basis) into the
// combinations of extreme directivity: pure forward and backward circles.
void split_repeated(ComplexVector& values, ComplexMatrix& vectors, const DofMap& dofs) {
  const Index m = values.size();
  std::vector<Index> order(static_cast<std::size_t>(m));
  for (Index i = 0; i < m; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    return values(a).imag() < values(b).imag();
  });
  std::size_t start = 0;
  while (start < order.size()) {
    std::size_t end = start + 1;
    const Complex p0 = values(order[start]);
    // Repeated when equal to 1e-7 relative: far above round-off of the QR
    // algorithm (~1e-13 here), far below any physical split.
    while (end < order.size() &&
           std::abs(values(order[end]) - p0) <= 1e-7 * std::max(std::abs(p0), 1e-300))
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
    if (wanted && std::abs(full(i)) > best_abs) best = i, best_abs = std::abs(full(i));
  }
  if (best_abs == 0.0)
    for (Index i = 0; i < full.size(); ++i)
      if (std::abs(full(i)) > best_abs) best = i, best_abs = std::abs(full(i));
  if (best < 0) return full;
  return full / full(best);
}

}  // namespace

ModalSolver::ModalSolver(const Model& model, ModalOptions options)
    : options_(options), assembler_(model) {
  const SystemMatrices sys = assembler_.at(0.0);
  lambda_max_ = 0.0;
  for (Index i = 0; i < sys.M.rows(); ++i)
    if (sys.M.coeff(i, i) > 0) lambda_max_ = std::max(lambda_max_, sys.K.coeff(i, i) / sys.M.coeff(i, i));
  if (lambda_max_ <= 0.0) lambda_max_ = 1.0;
}

EigenSolver ModalSolver::resolved_solver() const {
  if (options_.solver != EigenSolver::automatic) return options_.solver;
  const Index n = assembler_.dof_map().n_reduced();
  if (n <= options_.dense_limit) return EigenSolver::dense;
  if (options_.n_modes > 0 && 3 * options_.n_modes >= n) return EigenSolver::dense;
  return EigenSolver::sparse;
}

ModalResult ModalSolver::solve(Real speed) const {
  const SystemMatrices sys = assembler_.at(speed);
  const SparseMatrix D = sys.damping(speed);
  const SparseMatrix K = sys.stiffness(speed);
  const Index n = sys.M.rows();

  ModalResult result;
  result.speed = speed;
  detail::StateEigenpairs pairs;
  if (resolved_solver() == EigenSolver::dense) {
    pairs = detail::dense_state_eigen(Matrix(sys.M), Matrix(D), Matrix(K));
  } else {
    const Index wanted = options_.n_modes > 0 ? options_.n_modes : 12;
    // Automatic shift: just below zero, so that rigid-body modes (p = 0) do not make
    // K + σD + σ²M singular, yet close enough to find the lowest modes first.
    const Real sigma = std::isnan(options_.shift) ? -std::max(1.0, 1e-6 * std::sqrt(lambda_max_))
                                                  : options_.shift;
    pairs = detail::sparse_state_eigen(sys.M, D, K, std::min(wanted, n - 1), sigma);
  }
  result.info = pairs.info;
  split_repeated(pairs.values, pairs.vectors, assembler_.dof_map());

  // Strain energy of rigid-body motion is round-off: below 1e-12·λ_max (see checks.cpp).
  const Real rigid_tol = 1e-12 * lambda_max_;
  const Real zero_tol = 1e-6 * std::sqrt(lambda_max_);
  const SparseMatrix Ksym = 0.5 * (sys.K + SparseMatrix(sys.K.transpose()));
  const SparseMatrix& T = assembler_.dof_map().transformation();

  for (Index j = 0; j < pairs.values.size(); ++j) {
    Mode mode;
    const ComplexVector phi = pairs.vectors.col(j);
    const ComplexVector Mphi = sys.M.cast<Complex>() * phi;
    const Real kinetic = (phi.adjoint() * Mphi)(0).real();
    const Real strain = (phi.adjoint() * (Ksym.cast<Complex>() * phi))(0).real();
    mode.rigid_body = kinetic > 0 && strain / kinetic < rigid_tol;
    Complex p = pairs.values(j);
    if (mode.rigid_body && std::abs(p) < zero_tol) p = 0.0;
    mode.eigenvalue = p;
    mode.oscillatory = p.imag() > 0.0;
    mode.frequency_hz = p.imag() / (2.0 * pi);
    // A zero eigenvalue (rigid-body motion) has no damping ratio.
    mode.damping_ratio = std::abs(p) > 0 ? -p.real() / std::abs(p) : std::numeric_limits<Real>::quiet_NaN();
    if (mode.oscillatory) mode.log_decrement = 2.0 * pi * (-p.real()) / p.imag();

    Real fam[3] = {0, 0, 0};
    for (Index i = 0; i < n; ++i)
      fam[family_of(assembler_.dof_map().full_dof(i))] += (std::conj(phi(i)) * Mphi(i)).real();
    const Real total = fam[0] + fam[1] + fam[2];
    const int dominant = static_cast<int>(std::max_element(fam, fam + 3) - fam);
    // A family holding 80 % of the kinetic energy names the mode.
    mode.type = total > 0 && fam[dominant] < 0.8 * total ? ModeType::coupled
                : dominant == 0                          ? ModeType::lateral
                : dominant == 1                          ? ModeType::axial
                                                         : ModeType::torsional;

    const ComplexVector full = T.cast<Complex>() * phi;
    const WhirlResult whirl = classify_whirl(full);
    mode.whirl = whirl.whirl;
    mode.directivity = whirl.directivity;
    if (mode.type == ModeType::axial || mode.type == ModeType::torsional) {
      mode.whirl = Whirl::none;
      mode.directivity = std::numeric_limits<Real>::quiet_NaN();
    }
    mode.reduced_shape = phi;
    if (options_.shapes) mode.shape = normalise(full, mode.type);
    result.modes.push_back(std::move(mode));
  }

  // The lowest modes are those nearest the origin of the complex plane: sorting by
  // |p| keeps heavily overdamped modes (p far out on the negative real axis, with a
  // small imaginary part under rotating damping) from displacing the physical ones.
  auto by_magnitude = [](const Mode& a, const Mode& b) {
    return std::abs(a.eigenvalue) < std::abs(b.eigenvalue);
  };
  std::stable_sort(result.modes.begin(), result.modes.end(), by_magnitude);
  const Index limit = options_.n_modes > 0 ? options_.n_modes
                      : resolved_solver() == EigenSolver::sparse ? 12 : 0;
  if (limit > 0 && static_cast<Index>(result.modes.size()) > limit)
    result.modes.resize(static_cast<std::size_t>(limit));
  std::stable_sort(result.modes.begin(), result.modes.end(), [](const Mode& a, const Mode& b) {
    return a.frequency_hz < b.frequency_hz;
  });
  return result;
}

ModalResult run_modal(const Model& model, Real speed, const ModalOptions& options) {
  return ModalSolver(model, options).solve(speed);
}

}  // namespace feran

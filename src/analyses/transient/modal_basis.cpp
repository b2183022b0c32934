#include <feran/analyses/transient/modal_basis.hpp>

#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// Φ = A·V·Λ^{-1/2} from the Gram matrix AᵀMA = VΛVᵀ, dropping directions with
// Λ below @p cut times the largest.
Matrix m_orthonormalise(const Matrix& a, const Matrix& M, Real cut) {
  const Matrix gram = a.transpose() * M * a;
  const Eigen::SelfAdjointEigenSolver<Matrix> g(0.5 * (gram + gram.transpose()));
  const Vector& lambda = g.eigenvalues();
  const Real limit = cut * lambda.maxCoeff();
  Index keep = 0;
  for (Index j = 0; j < lambda.size(); ++j) keep += lambda(j) > limit ? 1 : 0;
  Matrix basis(a.rows(), keep);
  Index c = 0;
  for (Index j = lambda.size() - 1; j >= 0; --j)
    if (lambda(j) > limit) basis.col(c++) = a * g.eigenvectors().col(j) / std::sqrt(lambda(j));
  return basis;
}

}  // namespace

Matrix undamped_mode_basis(const Assembler& assembler, const std::vector<Real>& speeds, Index modes,
                           const Matrix& loads) {
  const Index n = assembler.dof_map().n_reduced();
  if (modes < 1 || modes > n)
    throw Error(fmt::format("modal reduction: the number of modes must be between 1 and {} (got {})", n, modes));
  if (n > modal_basis_max_dofs)
    throw Error(
        fmt::format("modal reduction: the model has {} DOFs; the dense eigensolver used for the basis "
                    "takes at most {}",
                    n, modal_basis_max_dofs));
  if (speeds.empty()) throw Error("modal reduction: no speed to compute modes at");
  if (loads.size() != 0 && loads.rows() != n)
    throw Error(fmt::format("modal reduction: load vectors need {} rows (got {})", n, loads.rows()));
  const Matrix M = Matrix(assembler.constant().M);
  const Index per_speed = modes + loads.cols();
  Matrix all(n, per_speed * static_cast<Index>(speeds.size()));
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const SystemMatrices s = assembler.at(speeds[i]);
    const Matrix K = Matrix(s.K);
    const Matrix Ks = 0.5 * (K + K.transpose());
    const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(Ks, Matrix(s.M));
    if (eig.info() != Eigen::Success)
      throw Error(fmt::format("modal reduction: the undamped eigenproblem failed at {:.6g} rad/s", speeds[i]));
    const Index first = per_speed * static_cast<Index>(i);
    all.middleCols(first, modes) = eig.eigenvectors().leftCols(modes);
    if (loads.cols() > 0) {
      // Static responses; with allowed free motions K_s is singular, so it is
      // shifted by the lowest elastic eigenvalue's millionth times M.
      const Vector& lambda = eig.eigenvalues();
      Real shift = 0.0;
      if (!(lambda(0) > 1e-9 * lambda(n - 1)))
        for (Index j = 0; j < n && shift == 0.0; ++j)
          if (lambda(j) > 1e-9 * lambda(n - 1)) shift = 1e-6 * lambda(j);
      const Eigen::LDLT<Matrix> k(Ks + shift * Matrix(s.M));
      all.middleCols(first + modes, loads.cols()) = k.solve(loads);
    }
  }
  // Each vector to unit M-norm first (static deflections are tiny beside the
  // normalised modes and would fall below the cut), then M-orthonormalise the union;
  // the second pass (all directions kept) restores the
  // orthonormality that the first loses when nearly dependent vectors are scaled up.
  for (Index j = 0; j < all.cols(); ++j) {
    const Real norm2 = all.col(j).dot(M * all.col(j));
    if (norm2 > 0) all.col(j) /= std::sqrt(norm2);
  }
  return m_orthonormalise(m_orthonormalise(all, M, 1e-10), M, 0.0);
}

}  // namespace feran

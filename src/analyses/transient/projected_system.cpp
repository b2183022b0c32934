#include <feran/analyses/transient/projected_system.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include <feran/core/error.hpp>

namespace feran {

ProjectedSystem::ProjectedSystem(SecondOrderSystem& full, Matrix basis) : full_(full), basis_(std::move(basis)) {
  if (basis_.rows() != full_.size() || basis_.cols() < 1)
    throw Error("projected system: the basis must have one row per unknown and at least one column");
  const Index m = basis_.cols();
  mass_.resize(m, m);
  Vector y(full_.size());
  for (Index j = 0; j < m; ++j) {
    full_.mass_times(basis_.col(j), y);
    mass_.col(j) = basis_.transpose() * y;
  }
  mass_ = 0.5 * (mass_ + mass_.transpose()).eval();
  mass_llt_.compute(mass_);
  if (mass_llt_.info() != Eigen::Success)
    throw Error("projected system: the basis is linearly dependent (projected mass not positive definite)");
  stiffness_ = Matrix::Zero(m, m);
  damping_ = Matrix::Zero(m, m);
}

void ProjectedSystem::rhs(Real t, const Vector& x, const Vector& v, Vector& r) {
  x_full_.noalias() = basis_ * x;
  v_full_.noalias() = basis_ * v;
  full_.rhs(t, x_full_, v_full_, r_full_);
  r.noalias() = basis_.transpose() * r_full_;
}

Matrix ProjectedSystem::project(bool stiffness) const {
  const Index m = basis_.cols();
  Matrix out(m, m);
  Vector y(full_.size());
  for (Index j = 0; j < m; ++j) {
    if (stiffness)
      full_.stiffness_times(basis_.col(j), y);
    else
      full_.damping_times(basis_.col(j), y);
    out.col(j) = basis_.transpose() * y;
  }
  return out;
}

void ProjectedSystem::set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) {
  full_.set_jacobian(t, basis_ * x, basis_ * v, exact);
  stiffness_ = project(true);
  damping_ = project(false);
}

bool ProjectedSystem::factor_tangent(Real c_x, Real c_v, Real c_a) {
  lu_.compute(c_a * mass_ + c_v * damping_ + c_x * stiffness_);
  return lu_.isInvertible();
}

Real ProjectedSystem::highest_frequency() {
  const Index m = basis_.cols();
  set_jacobian(0.0, Vector::Zero(m), Vector::Zero(m), false);
  const Matrix k = 0.5 * (stiffness_ + stiffness_.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> eig(k, mass_, Eigen::EigenvaluesOnly);
  if (eig.info() != Eigen::Success) throw Error("projected system: the eigenvalues of the projected pencil failed");
  return 1.1 * std::sqrt(std::max(eig.eigenvalues().maxCoeff(), 0.0));
}

}  // namespace feran

#include <feran/analyses/transient/rotor_system.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

RotorSystem::RotorSystem(const Model& model, SpeedProfile profile, Vector constant_load)
    : model_(model),
      assembler_(model),
      profile_(std::move(profile)),
      constant_load_(std::move(constant_load)),
      cached_speed_(std::numeric_limits<Real>::quiet_NaN()),
      jacobian_speed_(std::numeric_limits<Real>::quiet_NaN()) {
  const SystemMatrices& c = assembler_.constant();
  M_ = c.M, C_ = c.C, K_ = c.K, G_ = c.G, Ci_ = c.Ci, Ki_ = c.Ki;
  Cc_ = C_ + Ci_;
  Cc_.prune(0.0);
  mass_.compute(M_);
  if (mass_.info() != Eigen::Success) throw Error("transient: the mass matrix is not positive definite");
  // The rows of T for a force's DOFs map reduced coordinates to its local ones.
  const Eigen::SparseMatrix<Real, Eigen::RowMajor> Tr = assembler_.dof_map().transformation();
  for (const Force& f : model.forces) {
    if (!f.is_nonlinear()) continue;
    const std::vector<Index> dofs = f.dofs();
    SparseMatrix sel(static_cast<Index>(dofs.size()), Tr.cols());
    std::vector<Eigen::Triplet<Real>> trip;
    for (std::size_t i = 0; i < dofs.size(); ++i)
      for (Eigen::SparseMatrix<Real, Eigen::RowMajor>::InnerIterator it(Tr, dofs[i]); it; ++it)
        trip.emplace_back(static_cast<Index>(i), it.col(), it.value());
    sel.setFromTriplets(trip.begin(), trip.end());
    selectors_.push_back(sel);
    forces_.push_back(f);
  }
  f_full_.resize(model.n_dofs());
  update_speed(profile_.speed(0.0));
}

void RotorSystem::update_speed(Real speed) {
  if (!assembler_.speed_dependent() || speed == cached_speed_) return;
  assembler_.variable_values(speed, variable_);
  cached_speed_ = speed;
}

void RotorSystem::external_forces(Real t, Vector& f) const {
  f.setZero();
  const MotionState state{t, profile_.speed(t), profile_.acceleration(t), profile_.angle(t)};
  for (const Force& force : model_.forces) force.add_transient(state, f);
  if (constant_load_.size() > 0) f += constant_load_;
}

void RotorSystem::rhs(Real t, const Vector& x, const Vector& v, Vector& r) {
  const Real W = profile_.speed(t);
  update_speed(W);
  external_forces(t, f_full_);
  // Products accumulate in place (noalias): no temporaries in the step loop.
  r.noalias() = assembler_.dof_map().transformation().transpose() * f_full_;
  r.noalias() -= K_ * x;
  r.noalias() -= Cc_ * v;
  work_.noalias() = G_ * v;
  work_.noalias() += Ki_ * x;
  r -= W * work_;
  if (assembler_.speed_dependent()) {
    r.noalias() -= variable_.C * v;
    r.noalias() -= variable_.K * x;
  }
  const MotionState state{t, W, profile_.acceleration(t), profile_.angle(t)};
  for (std::size_t i = 0; i < forces_.size(); ++i) r += selectors_[i].transpose() * evaluate(i, state, x, v).f;
}

NonlinearForceValue RotorSystem::evaluate(std::size_t i, const MotionState& state, const Vector& x,
                                          const Vector& v) const {
  try {
    return forces_[i].force(state, selectors_[i] * x, selectors_[i] * v);
  } catch (const Error& e) {
    // Name the force: "journal bearing 'A': the journal has reached the bearing: …".
    std::string kind(forces_[i].kind());
    std::replace(kind.begin(), kind.end(), '_', ' ');
    const std::string& label = forces_[i].label();
    throw Error(label.empty() ? fmt::format("{}: {}", kind, e.what()) : fmt::format("{} '{}': {}", kind, label, e.what()));
  }
}

void RotorSystem::set_jacobian(Real t, const Vector& x, const Vector& v, bool exact) {
  const Real W = profile_.speed(t);
  update_speed(W);
  jacobian_speed_ = W;
  DT_ = C_ + Ci_ + W * G_;
  KT_ = K_ + W * Ki_;
  if (assembler_.speed_dependent()) {
    DT_ += variable_.C;
    KT_ += variable_.K;
  }
  const MotionState state{t, W, profile_.acceleration(t), profile_.angle(t)};
  for (std::size_t i = 0; i < forces_.size(); ++i) {
    const SparseMatrix& S = selectors_[i];
    NonlinearForceValue f = evaluate(i, state, x, v);
    if (!exact) f.dfdx.setZero(), f.dfdv.setZero();  // keep the pattern, drop the values
    DT_ -= SparseMatrix(S.transpose() * f.dfdv.sparseView(0.0, 0.0) * S);
    KT_ -= SparseMatrix(S.transpose() * f.dfdx.sparseView(0.0, 0.0) * S);
  }
}

bool RotorSystem::factor_tangent(Real c_x, Real c_v, Real c_a) {
  SparseMatrix S = c_a * M_ + c_v * DT_ + c_x * KT_;
  S.makeCompressed();
  if (S.nonZeros() != pattern_nonzeros_) {
    lu_.analyzePattern(S);
    pattern_nonzeros_ = S.nonZeros();
  }
  lu_.factorize(S);
  return lu_.info() == Eigen::Success;
}

Real RotorSystem::highest_frequency() {
  // Power iteration on M⁻¹K_s (K_s the symmetric stiffness at the current speed):
  // 60 iterations from a fixed start vector, then 10 % margin, since the iteration
  // approaches the largest eigenvalue from below.
  SparseMatrix K = K_;
  if (assembler_.speed_dependent()) K += variable_.K;
  const SparseMatrix Ks = 0.5 * (K + SparseMatrix(K.transpose()));
  Vector u = Vector::LinSpaced(size(), 1.0, 2.0);
  Real lambda = 0.0;
  for (int it = 0; it < 60; ++it) {
    Vector w = mass_.solve(Ks * u);
    const Real norm = w.norm();
    if (norm == 0.0) break;
    lambda = u.dot(M_ * w) / u.dot(M_ * u);
    u = w / norm;
  }
  return 1.1 * std::sqrt(std::max(lambda, 0.0));
}

}  // namespace feran

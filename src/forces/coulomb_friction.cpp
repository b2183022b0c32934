#include <feran/forces/coulomb_friction.hpp>

#include <cmath>

#include <Eigen/Dense>

namespace feran {

namespace {

using Mat2 = Eigen::Matrix2d;
using Vec2 = Eigen::Vector2d;

// One friction pair: coordinates P = B·q of a node's pair q (translation (v, w):
// B = I; tilt (ry, rz): P = (rz, −ry)). Relative rotating-frame velocity
// s = Ṗ + Ω·J·P with J = [[0, 1], [−1, 0]] (from s = ṗ − jΩp in complex form).
// Adds the force Bᵀ·F(s), F = −F0·s/√(|s|² + ε²), and its Jacobian into the local
// arrays at offset @p o (node a) and, with @p two_nodes, o + 4 (node b, opposite).
void add_pair(const Mat2& B, Real F0, Real eps, Real speed, const Vector& x, const Vector& v, Index o, bool two_nodes,
              NonlinearForceValue& out) {
  if (F0 == 0.0) return;
  Vec2 dx = B * x.segment<2>(o), dv = B * v.segment<2>(o);
  if (two_nodes) {
    dx -= B * x.segment<2>(o + 4);
    dv -= B * v.segment<2>(o + 4);
  }
  Mat2 J;
  J << 0, 1, -1, 0;
  const Vec2 s = dv + speed * (J * dx);
  const Real rho = std::sqrt(s.squaredNorm() + eps * eps);
  const Vec2 F = -F0 / rho * s;
  // ∂F/∂s = −F0·(I/ρ − s·sᵀ/ρ³)
  const Mat2 dFds = -F0 * (Mat2::Identity() / rho - s * s.transpose() / (rho * rho * rho));
  const Mat2 dfdv = B.transpose() * dFds * B;
  const Mat2 dfdx = B.transpose() * dFds * (speed * J) * B;
  const Vec2 f = B.transpose() * F;
  out.f.segment<2>(o) += f;
  out.dfdv.block<2, 2>(o, o) += dfdv;
  out.dfdx.block<2, 2>(o, o) += dfdx;
  if (two_nodes) {
    out.f.segment<2>(o + 4) -= f;
    out.dfdv.block<2, 2>(o, o + 4) -= dfdv;
    out.dfdv.block<2, 2>(o + 4, o) -= dfdv;
    out.dfdv.block<2, 2>(o + 4, o + 4) += dfdv;
    out.dfdx.block<2, 2>(o, o + 4) -= dfdx;
    out.dfdx.block<2, 2>(o + 4, o) -= dfdx;
    out.dfdx.block<2, 2>(o + 4, o + 4) += dfdx;
  }
}

}  // namespace

std::vector<Index> CoulombFriction::nodes() const {
  if (node_b) return {node_a, *node_b};
  return {node_a};
}

std::vector<Index> CoulombFriction::dofs() const {
  std::vector<Index> d;
  for (Dof dof : {Dof::v, Dof::w, Dof::ry, Dof::rz}) d.push_back(global_dof(node_a, dof));
  if (node_b)
    for (Dof dof : {Dof::v, Dof::w, Dof::ry, Dof::rz}) d.push_back(global_dof(*node_b, dof));
  return d;
}

NonlinearForceValue CoulombFriction::force(const MotionState& s, const Vector& x, const Vector& v) const {
  const Index n = node_b ? 8 : 4;
  NonlinearForceValue out{Vector::Zero(n), Matrix::Zero(n, n), Matrix::Zero(n, n)};
  Mat2 tilt;
  tilt << 0, 1, -1, 0;  // (ry, rz) → (rz, −ry)
  add_pair(Mat2::Identity(), force_amplitude, epsilon_t, s.speed, x, v, 0, node_b.has_value(), out);
  add_pair(tilt, moment_amplitude, epsilon_r, s.speed, x, v, 2, node_b.has_value(), out);
  return out;
}

}  // namespace feran

#pragma once
// A bearing's force on the lateral motion (v, w) of a journal relative to its housing
// (a node, or the ground): the DOFs, the relative motion, and the force and Jacobian
// on both, the housing taking the opposite force. Shared by the bearing types.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran::detail {

inline std::vector<Index> lateral_nodes(Index a, const std::optional<Index>& b) {
  if (b) return {a, *b};
  return {a};
}

/// v, w of the journal, then of the housing when there is one.
inline std::vector<Index> lateral_dofs(Index a, const std::optional<Index>& b) {
  std::vector<Index> d{global_dof(a, Dof::v), global_dof(a, Dof::w)};
  if (b) {
    d.push_back(global_dof(*b, Dof::v));
    d.push_back(global_dof(*b, Dof::w));
  }
  return d;
}

/// The journal's motion relative to the housing from local values on lateral_dofs().
inline Eigen::Vector2d relative(const Vector& values, bool housing) {
  Eigen::Vector2d d = values.head<2>();
  if (housing) d -= values.tail<2>();
  return d;
}

/// The force @p f on the journal with Jacobians @p dfdx, @p dfdv with respect to the
/// relative motion, as a force on lateral_dofs(): the housing's motion enters with
/// the opposite sign and it carries the opposite force.
inline NonlinearForceValue pair_force(const Eigen::Vector2d& f, const Eigen::Matrix2d& dfdx,
                                      const Eigen::Matrix2d& dfdv, bool housing) {
  const Index n = housing ? 4 : 2;
  NonlinearForceValue out{Vector::Zero(n), Matrix::Zero(n, n), Matrix::Zero(n, n)};
  out.f.head<2>() = f;
  out.dfdx.topLeftCorner<2, 2>() = dfdx;
  out.dfdv.topLeftCorner<2, 2>() = dfdv;
  if (housing) {
    out.f.tail<2>() = -f;
    out.dfdx.topRightCorner<2, 2>() = out.dfdx.bottomLeftCorner<2, 2>() = -dfdx;
    out.dfdx.bottomRightCorner<2, 2>() = dfdx;
    out.dfdv.topRightCorner<2, 2>() = out.dfdv.bottomLeftCorner<2, 2>() = -dfdv;
    out.dfdv.bottomRightCorner<2, 2>() = dfdv;
  }
  return out;
}

}  // namespace feran::detail

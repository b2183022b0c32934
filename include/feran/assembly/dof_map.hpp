#pragma once
/// @file
/// Map from the unconstrained DOFs to the reduced (independent) DOFs.

#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Fixed DOFs and rigid links eliminated by a transformation q_full = T·q_reduced.
/// Fixed DOFs get a zero row; a follower node of a rigid link gets the rows of its
/// leader with the small-rotation lever terms v_f = v_l + d·rz_l, w_f = w_l − d·ry_l
/// (d = x_f − x_l). Reduced DOFs keep the order of their full DOFs.
class DofMap {
 public:
  /// Builds the map. Throws ModelStructureError for contradictory constraints
  /// (a node following two leaders, a fixed DOF on a follower node).
  explicit DofMap(const Model& model);

  Index n_full() const { return n_full_; }
  Index n_reduced() const { return static_cast<Index>(reduced_to_full_.size()); }
  /// T, n_full × n_reduced.
  const SparseMatrix& transformation() const { return T_; }
  /// The full DOF each reduced DOF stands for.
  Index full_dof(Index reduced) const { return reduced_to_full_[static_cast<std::size_t>(reduced)]; }
  /// The reduced DOF a full DOF is identical to, or -1 (fixed or follower DOF).
  Index reduced_dof(Index full) const { return full_to_reduced_[static_cast<std::size_t>(full)]; }

  /// q_full = T·q_reduced.
  Vector expand(const Vector& reduced) const { return T_ * reduced; }
  ComplexVector expand(const ComplexVector& reduced) const;

 private:
  Index n_full_ = 0;
  SparseMatrix T_;
  std::vector<Index> reduced_to_full_;
  std::vector<Index> full_to_reduced_;
};

}  // namespace feran

#pragma once
/// @file
/// Checks that a model can be analysed: positive-definite mass and no unintended
/// rigid-body motion.

#include <string>
#include <string_view>
#include <vector>

#include <feran/assembly/assembler.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// A motion along which the stiffness (at zero speed, after constraints) is singular.
struct FreeMotionInfo {
  FreeMotion family = FreeMotion::lateral;
  std::string description;   ///< e.g. "rotation about the x axis (torsion) of nodes 1–7"
  std::vector<Index> nodes;  ///< nodes that take part
};

/// An M-orthonormal basis (reduced coordinates) of the motions along which the
/// symmetric part of @p K is singular: Rayleigh quotient below 1e-12·max(K_ii/M_ii).
/// Zero columns when K is regular. Throws ModelStructureError when more eigenvalues lie
/// below that than six per connected part (the most rigid motions a body has): the
/// spectrum is too wide for double precision to tell rigid motion from vibration.
Matrix stiffness_null_space(const SparseMatrix& K, const SparseMatrix& M);

/// @p K (reduced) with each nonlinear support of @p model (a fluid-film bearing, which
/// has no stiffness at rest) added as a stiff spring on its DOFs (max K_ii): the
/// stiffness whose null space is the motions that stay free when the rotor runs.
SparseMatrix held_stiffness(const Model& model, const Assembler& assembler, const SparseMatrix& K);

/// The rigid-body motions of @p model at zero speed (may be empty), counting its
/// nonlinear supports (fluid-film bearings) as holding their DOFs, as they do when the
/// rotor runs.
std::vector<FreeMotionInfo> find_free_motions(const Model& model, const Assembler& assembler);

/// What check_model() says of a model whose constraints leave no DOF free.
inline constexpr std::string_view no_free_dof_message =
    "the model has no free degree of freedom: every DOF of every node is fixed or rigidly linked to a "
    "fixed one, so nothing can move; free some DOFs in [[fixed]]";

/// Throws ModelStructureError when no DOF is free (every one fixed or rigidly linked
/// to a fixed one), when the mass matrix is not positive definite (naming a node and
/// DOF without mass) or when a rigid-body motion is free that model.free_motions does
/// not allow (naming the motion).
void check_model(const Model& model, const Assembler& assembler);

}  // namespace feran

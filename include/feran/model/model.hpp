#pragma once
/// @file
/// The model: a plain value holding nodes, elements, constraints, loads and options.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/drive.hpp>
#include <feran/model/element.hpp>
#include <feran/model/force.hpp>
#include <feran/model/material.hpp>

namespace feran {

/// A node on the x axis. Its global DOFs are global_dof(index, Dof::...).
struct Node {
  int number = 0;        ///< the number users refer to (unique)
  std::string name;      ///< optional name users refer to (unique when not empty)
  Real x = 0.0;          ///< axial position [m]
  bool rotating = true;  ///< belongs to a rotating body (shaft, rotor) or not (stator)
};

/// How the gyroscopic matrix of shaft elements is formed.
enum class GyroscopicForm { consistent, lumped };

/// A rigid-body motion of the whole model that the user allows to stay free.
enum class FreeMotion { axial, torsion, lateral };

/// DOFs of a node held at zero.
struct FixedDofs {
  Index node = 0;
  std::array<bool, dofs_per_node> dofs{};  ///< indexed by Dof
};

/// Nodes moving together as one rigid body: every DOF of each follower is given by
/// the leader's translations and rotations (small-rotation kinematics along x).
struct RigidLink {
  Index leader = 0;
  std::vector<Index> followers;
};

/// A complete rotor model as the analyses use it: nodes, elements, constraints and
/// loads. Values only: copy it freely. build_model() (spec/build_model.hpp) makes one
/// from a ModelSpec; the model-wide options of a file (shear deformation, gyroscopic
/// form, shaft damping) and its materials are already in the elements.
struct Model {
  std::string name;
  std::vector<Node> nodes;
  std::vector<Element> elements;
  std::vector<FixedDofs> fixed;
  std::vector<RigidLink> links;
  /// What acts on the model: unbalances, harmonic forces, static loads, friction
  /// (forces/), each asked for its abilities by the analyses.
  std::vector<Force> forces;
  /// The gravitational acceleration the machine runs under [m/s²] ([static] gravity
  /// and g): with the static loads, the load that the supports (forces with the
  /// ability supports(): fluid-film bearings) carry in the static equilibrium about
  /// which the linear analyses linearise them (analyses/static/equilibrium.hpp).
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  /// The motor and load torques of torque-driven run-ups ([drive]); empty: none.
  std::optional<Drive> drive;
  /// Rigid-body motions that may remain free (singular stiffness) without an error.
  std::vector<FreeMotion> free_motions;

  Index n_nodes() const { return static_cast<Index>(nodes.size()); }
  /// Number of unconstrained DOFs (6 per node).
  Index n_dofs() const { return dofs_per_node * n_nodes(); }
  /// Number of forces of kind @p kind ("unbalance", "harmonic_force", …).
  std::size_t n_forces(std::string_view kind) const;
  /// Number of forces with the ability @p has asks of them (a predicate on a Force,
  /// e.g. [](const Force& f) { return f.has_static(); }): what analyses count.
  template <class Has>
  std::size_t count_forces(Has&& has) const {
    std::size_t n = 0;
    for (const Force& f : forces) n += has(f) ? 1 : 0;
    return n;
  }
  /// Index of the node with user number @p number, or -1.
  Index find_node(int number) const;
  /// Index of the node named @p name, or -1.
  Index find_node(const std::string& name) const;
  /// "7" or "7 (rotor)": how messages name node @p index.
  std::string node_label(Index index) const;
};

}  // namespace feran

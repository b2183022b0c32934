#pragma once
/// @file
/// The model: a plain value holding nodes, elements, constraints, loads and options.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>
#include <feran/model/material.hpp>

namespace feran {

/// A node on the x axis. Its global DOFs are global_dof(index, Dof::...).
struct Node {
  int number = 0;      ///< the number users refer to (unique)
  std::string name;    ///< optional name users refer to (unique when not empty)
  Real x = 0.0;        ///< axial position [m]
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

/// A point unbalance (paper eq. 5): force m·r·Ω² at angle Ωt + phase in the y–z
/// plane, and the moment of that force about the node through axial lever @p lever.
struct Unbalance {
  Index node = 0;
  Real mass = 0.0;    ///< [kg]
  Real radius = 0.0;  ///< [m]
  Real phase = 0.0;   ///< [rad], measured from +y towards +z at t = 0
  Real lever = 0.0;   ///< axial distance from the node to the unbalance plane [m]
  std::string label;
};

/// A harmonic force or moment at a node. In a speed sweep it acts at the rotor
/// speed (synchronous); in a frequency sweep at the swept frequency.
struct HarmonicForce {
  enum class Kind {
    fixed,            ///< along a fixed DOF direction: F(t) = A·cos(ωt + phase)
    rotating_force,   ///< lateral force rotating with the shaft: F_y + i·F_z = A·e^{i(Ωt + phase)}
    rotating_moment   ///< lateral moment rotating with the shaft: M_y + i·M_z = A·e^{i(Ωt + phase)}
  };
  Index node = 0;
  Kind kind = Kind::fixed;
  Dof direction = Dof::v;  ///< for Kind::fixed
  Real amplitude = 0.0;    ///< [N] or [N m]
  Real phase = 0.0;        ///< [rad]
  std::string label;
};

/// A static load at a node: forces [N] along x, y, z and moments [N m] about x, y, z,
/// indexed by Dof.
struct StaticLoad {
  Index node = 0;
  std::array<Real, dofs_per_node> load{};
  std::string label;
};

/// Coulomb friction between rotating parts (paper eqs. 12–14): a force of magnitude
/// @p force opposing the translational velocity seen in the rotating frame, and a
/// moment of magnitude @p moment opposing the rotational one. Between @p node_a and
/// @p node_b, or between @p node_a and the rotating frame when node_b is empty.
/// Regularised as F = F_c0 · s/√(|s|² + ε²), s the relative rotating-frame velocity.
struct CoulombFriction {
  Index node_a = 0;
  std::optional<Index> node_b;
  Real force = 0.0;         ///< F_ct0 [N]
  Real moment = 0.0;        ///< F_cr0 [N m]
  Real epsilon_t = 1e-4;    ///< regularisation velocity, translation [m/s]
  Real epsilon_r = 1e-3;    ///< regularisation angular velocity, rotation [rad/s]
  std::string label;
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
  std::vector<Unbalance> unbalances;
  std::vector<HarmonicForce> forces;
  std::vector<StaticLoad> static_loads;
  std::vector<CoulombFriction> friction;
  /// Rigid-body motions that may remain free (singular stiffness) without an error.
  std::vector<FreeMotion> free_motions;

  Index n_nodes() const { return static_cast<Index>(nodes.size()); }
  /// Number of unconstrained DOFs (6 per node).
  Index n_dofs() const { return dofs_per_node * n_nodes(); }
  /// Index of the node with user number @p number, or -1.
  Index find_node(int number) const;
  /// Index of the node named @p name, or -1.
  Index find_node(const std::string& name) const;
  /// "7" or "7 (rotor)": how messages name node @p index.
  std::string node_label(Index index) const;
};

}  // namespace feran

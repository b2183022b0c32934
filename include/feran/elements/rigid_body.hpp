#pragma once
/// @file
/// Rigid body (disk, rotor, stator) attached to one node.

#include <string_view>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>

namespace feran {

/// Mass properties of a rigid body. Moments of inertia are about the node; the
/// centre of mass may sit at an axial offset from it.
struct RigidBodyProperties {
  Real mass = 0.0;              ///< m [kg]
  Real transverse_inertia = 0;  ///< J_A about a transverse axis through the node [kg m²]
  Real polar_inertia = 0.0;     ///< J_P about the x axis [kg m²]
  Real offset = 0.0;            ///< axial position of the centre of mass relative to the node [m]
};

/// Rigid body at @p node. Rotating bodies add the gyroscopic matrix of J_P.
/// Matrices: docs/theory/rigid_body.md.
class RigidBody {
 public:
  RigidBody(Index node, RigidBodyProperties props, bool rotating);

  /// Mass properties of a solid or annular disk of uniform density, centred on the node.
  static RigidBodyProperties disk(Real density, Real outer_diameter, Real inner_diameter, Real width);

  LocalMatrices local_matrices(const OperatingPoint& op) const;
  std::string_view kind() const { return "rigid_body"; }
  bool speed_dependent() const { return false; }

  Index node() const { return node_; }
  const RigidBodyProperties& properties() const { return props_; }
  bool rotating() const { return rotating_; }
  /// Ability (model/element.hpp): its mass and inertias at its node.
  MassProperties mass_properties() const {
    return {node_, props_.mass, props_.transverse_inertia, props_.polar_inertia, props_.offset, rotating_};
  }

 private:
  Index node_;
  RigidBodyProperties props_;
  bool rotating_;
};

}  // namespace feran

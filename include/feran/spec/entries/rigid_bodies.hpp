#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/rigid_bodies.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[rigid_bodies]]: given by mass, Ja and Jp, or as a disk by its dimensions.
struct RigidBodySpec {
  std::string name;
  NodeRef node;
  std::optional<Real> mass;            ///< [kg]
  std::optional<Real> Ja;              ///< about a transverse axis through the node [kg m²]
  std::optional<Real> Jp;              ///< polar [kg m²]
  std::optional<Real> outer_diameter;  ///< disk form [m]
  std::optional<Real> inner_diameter;  ///< disk form [m]
  std::optional<Real> width;           ///< disk form [m]
  std::string material;                ///< disk form: material whose density is used
  std::optional<Real> offset;          ///< axial offset of the centre of mass [m]
  std::optional<bool> rotating;        ///< not given: as the node
  bool operator==(const RigidBodySpec&) const = default;
};

}  // namespace feran

#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/rotating_dampers.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[rotating_dampers]]: viscous damping between rotating parts (internal damping).
struct RotatingDamperSpec {
  std::string name;
  NodeRef node;
  std::optional<NodeRef> to;  ///< not given (or "axis"): to the rotating frame's axis
  Real ct = 0.0;              ///< lateral [N s/m]
  Real cr = 0.0;              ///< tilt [N m s/rad]
  Real cx = 0.0;              ///< axial [N s/m]
  Real crx = 0.0;             ///< torsional [N m s/rad]
  bool operator==(const RotatingDamperSpec&) const = default;
};

}  // namespace feran

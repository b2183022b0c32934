#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/unbalances.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[unbalances]]: a point unbalance.
struct UnbalanceSpec {
  std::string name;
  NodeRef node;
  Real mass = 0.0;    ///< [kg]
  Real radius = 0.0;  ///< [m]
  Real phase = 0.0;   ///< [rad]
  Real lever = 0.0;   ///< [m]
  bool operator==(const UnbalanceSpec&) const = default;
};

}  // namespace feran

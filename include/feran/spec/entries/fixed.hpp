#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/fixed.cpp.

#include <optional>
#include <string>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[fixed]]: DOFs of a node held at zero.
struct FixedSpec {
  NodeRef node;
  /// "u", "v", "w", "rx", "ry", "rz", "all", "lateral", "translations", "rotations";
  /// empty: all.
  std::vector<std::string> dofs;
  bool operator==(const FixedSpec&) const = default;
};

}  // namespace feran

#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/rigid_links.cpp.

#include <optional>
#include <string>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[rigid_links]]: nodes moving as one rigid body; the first leads.
struct RigidLinkSpec {
  std::vector<NodeRef> nodes;
  bool operator==(const RigidLinkSpec&) const = default;
};

}  // namespace feran

#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/static_loads.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[static_loads]]: constant forces [N] and moments [N m].
struct StaticLoadSpec {
  std::string name;
  NodeRef node;
  Real fx = 0.0, fy = 0.0, fz = 0.0, mx = 0.0, my = 0.0, mz = 0.0;
  bool operator==(const StaticLoadSpec&) const = default;
};

}  // namespace feran

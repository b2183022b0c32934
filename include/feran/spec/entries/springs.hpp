#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/springs.cpp.

#include <array>
#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/model/speed_coefficient.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[springs]]: a spring–damper from a node to ground or to another node. Absent
/// coefficients are zero.
struct SpringSpec {
  std::string name;
  NodeRef node;
  std::optional<NodeRef> to;  ///< not given (or "ground"): to ground
  /// By spring::Coefficient (kx … czy, spring::names): e.g. coefficients[spring::ky].
  std::array<std::optional<SpeedCoefficient>, spring::count> coefficients{};
  Real loss_factor = 0.0;
  bool operator==(const SpringSpec&) const = default;
};

}  // namespace feran

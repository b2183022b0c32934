#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/springs.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/model/speed_coefficient.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[springs]]: a spring–damper from a node to ground or to another node. Absent
/// coefficients are zero.
struct SpringSpec {
  std::string name;
  NodeRef node;
  std::optional<NodeRef> to;  ///< not given (or "ground"): to ground
  std::optional<SpeedCoefficient> kx, ky, kz, krx, kry, krz, kyz, kzy;
  std::optional<SpeedCoefficient> cx, cy, cz, crx, cry, crz, cyz, czy;
  Real loss_factor = 0.0;
  bool operator==(const SpringSpec&) const = default;
};

}  // namespace feran

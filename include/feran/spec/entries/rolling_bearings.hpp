#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/rolling_bearings.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[rolling_bearings]]: a ball or roller bearing, its elements in Hertzian contact.
struct RollingBearingSpec {
  std::string name;
  NodeRef node;                                       ///< the journal (inner race)
  std::optional<NodeRef> to;                          ///< the housing (outer race); not given (or "ground"): the ground
  int elements = 0;                                   ///< Z
  Real element_diameter = 0.0, pitch_diameter = 0.0;  ///< d, D_p [m]
  Real contact_angle = 0.0;                           ///< α [rad]
  Real clearance = 0.0;                               ///< radial clearance [m]
  Real hertz_constant = 0.0;                          ///< K [N/mⁿ]
  std::string type = "ball";                          ///< "ball" or "roller"
  bool operator==(const RollingBearingSpec&) const = default;
};

}  // namespace feran

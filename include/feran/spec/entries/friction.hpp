#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/friction.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[friction]]: Coulomb friction between rotating parts.
struct FrictionSpec {
  std::string name;
  NodeRef node;
  std::optional<NodeRef> to;  ///< not given (or "axis"): to the rotating frame
  Real force = 0.0;           ///< F_ct0 [N]
  Real moment = 0.0;          ///< F_cr0 [N m]
  Real epsilon_t = 1e-4;      ///< regularisation velocity [m/s]
  Real epsilon_r = 1e-3;      ///< regularisation angular velocity [rad/s]
  bool operator==(const FrictionSpec&) const = default;
};

}  // namespace feran

#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/forces.cpp.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[forces]]: a harmonic force or moment.
struct ForceSpec {
  std::string name;
  NodeRef node;
  std::string kind = "fixed";     ///< "fixed", "rotating_force" or "rotating_moment"
  std::string direction;          ///< "x", "y", "z", "rx", "ry", "rz" (kind "fixed")
  std::optional<Real> amplitude;  ///< [N] or [N m]; required unless time_table
  Real phase = 0.0;               ///< [rad]
  std::optional<Real> frequency;  ///< [Hz]: a fixed force at its own frequency (run-ups)
  /// (time [s], force [N] or moment [N m]): a fixed force given in time (run-ups)
  std::vector<std::pair<Real, Real>> time_table;
  bool operator==(const ForceSpec&) const = default;
};

}  // namespace feran

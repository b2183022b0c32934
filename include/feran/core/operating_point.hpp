#pragma once
/// @file
/// The operating point at which element matrices are evaluated.

#include <feran/core/types.hpp>

namespace feran {

/// State of the machine that element matrices may depend on.
struct OperatingPoint {
  /// Rotor speed Ω in rad/s (spin about +x).
  Real speed = 0.0;
};

}  // namespace feran

#pragma once
/// @file
/// The operating point at which element matrices are evaluated.

#include <optional>
#include <string>

#include <feran/core/types.hpp>

namespace feran {

/// State of the machine that element matrices may depend on.
struct OperatingPoint {
  OperatingPoint() = default;
  /// At speed @p speed, for motion at @p frequency (both rad/s; see the members).
  OperatingPoint(Real at_speed, std::optional<Real> at_frequency = std::nullopt)  // NOLINT(google-explicit-constructor)
      : speed(at_speed), frequency(at_frequency) {}

  /// Rotor speed Ω in rad/s (spin about +x).
  Real speed = 0.0;
  /// Frequency ω [rad/s] of the motion that frequency-dependent coefficients see: the
  /// excitation frequency of a harmonic response, a mode's own damped frequency, 0 for
  /// a static deflection. Empty: synchronous motion, ω = Ω (run-ups, critical speed
  /// maps).
  std::optional<Real> frequency;

  /// ω, or Ω when no frequency is given.
  Real motion_frequency() const { return frequency.value_or(speed); }
};

/// One number of a support's operating state: a machine-readable name that carries its
/// unit ("min_film_thickness_m", "eccentricity_ratio"), and its value (NaN where the
/// support's theory does not give it).
struct OperatingValue {
  std::string name;
  Real value = 0.0;
};

}  // namespace feran

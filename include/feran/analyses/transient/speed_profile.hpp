#pragma once
/// @file
/// Rotor speed as a function of time for run-ups and run-downs.

#include <utility>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// A piecewise-linear speed Ω(t) through (t_i, Ω_i), held constant before the first
/// and after the last point. Constant speeds and linear ramps are special cases. The
/// rotation angle φ(t) = ∫₀ᵗ Ω dt is integrated exactly (piecewise quadratic).
class SpeedProfile {
 public:
  /// Through @p points (time [s], speed [rad/s]); times strictly increasing.
  /// Throws feran::Error for an empty or unordered table.
  explicit SpeedProfile(std::vector<std::pair<Real, Real>> points);
  static SpeedProfile constant(Real speed) { return SpeedProfile({{0.0, speed}}); }
  /// From @p from to @p to in @p time seconds, then held.
  static SpeedProfile ramp(Real from, Real to, Real time) { return SpeedProfile({{0.0, from}, {time, to}}); }

  Real speed(Real t) const;         ///< Ω(t) [rad/s]
  Real acceleration(Real t) const;  ///< Ω'(t) [rad/s²] (right derivative at a breakpoint)
  Real angle(Real t) const;         ///< φ(t) = ∫₀ᵗ Ω dτ [rad]
  const std::vector<std::pair<Real, Real>>& points() const { return points_; }

 private:
  std::vector<std::pair<Real, Real>> points_;
  std::vector<Real> angle_at_;  // φ at each point's time
};

}  // namespace feran

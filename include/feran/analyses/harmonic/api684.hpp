#pragma once
/// @file
/// The API 684 reading of an unbalance response: the resonance peaks of an amplitude
/// curve, each critical speed's amplification factor by the half-power method, and
/// the separation margin API 617 requires for it (docs/theory/harmonic_and_static.md,
/// "Amplification factors and separation margins").

#include <optional>
#include <span>
#include <vector>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// A local maximum of a response amplitude against speed.
struct ResponsePeak {
  Real speed = 0;      ///< N_c: the peak's speed, refined by a parabola through its three points [rad/s]
  Real amplitude = 0;  ///< the amplitude there (that parabola's top)
  /// N_1 < N_c < N_2 where the amplitude has fallen to 1/√2 of the peak's, by linear
  /// interpolation between the points; none when the curve leaves the sweep, or rises
  /// above the peak again, before it falls that far.
  std::optional<Real> lower_half_power, upper_half_power;
  /// The amplification factor N_c / (N_2 − N_1), by the half-power method of API 684;
  /// NaN unless both half-power points exist.
  Real amplification_factor = 0;
  bool resolved() const { return lower_half_power.has_value() && upper_half_power.has_value(); }
};

/// The peaks of @p amplitude (at the increasing @p speeds), in order of speed: points
/// higher than the point before and at least as high as the one after (the first of
/// a flat top); the first point when the curve falls from it, the last when it rose
/// to it. Throws feran::Error for sizes that differ or speeds not increasing.
std::vector<ResponsePeak> response_peaks(std::span<const Real> speeds, std::span<const Real> amplitude);

/// The separation margin API 617 (8th ed.) and API 684 (2nd ed.) require of a
/// critical speed @p critical with amplification factor @p af from the operating range
/// [@p low, @p high], as a fraction: none (0) for af < 2.5; below the range
/// min(0.16, 0.17·(1 − 1/(af − 1.5))); above it min(0.26, 0.10 + 0.17·(1 − 1/(af − 1.5)));
/// inside it, the rule of the nearer end.
Real required_separation_margin(Real af, Real critical, Real low, Real high);

/// Relative distance of @p critical from the operating range [low, high]:
/// (low − c)/low below it, (c − high)/high above it, and minus the smaller of the two
/// inside it (API 684's separation margin, as a fraction).
Real separation_margin(Real critical, Real low, Real high);

/// A resonance peak read against the operating range.
struct SeparationCheck {
  ResponsePeak peak;
  Real actual_margin = 0;  ///< separation_margin() of the peak's speed
  /// required_separation_margin(); none when the peak has no half-power points.
  std::optional<Real> required_margin;
  /// actual ≥ required; none for a peak without an amplification factor (a peak the
  /// sweep cuts or that rides on another's shoulder: it cannot be judged); false when
  /// the rotor is unstable at the peak (unstable).
  std::optional<bool> passes;
  /// The rotor is unstable at the peak's speed: the peak is no steady state the rotor
  /// reaches, and it fails whatever its margin.
  bool unstable = false;
};

/// Every peak of @p amplitude over @p speeds with its margins from [@p low, @p high].
std::vector<SeparationCheck> separation_checks(std::span<const Real> speeds, std::span<const Real> amplitude, Real low,
                                               Real high);

/// The peaks of probe @p probe of the speed sweep @p response, checked as above, each
/// marked unstable (and failing) when the rotor is unstable at a response point on
/// either side of its speed (HarmonicResult::stability).
std::vector<SeparationCheck> separation_checks(const HarmonicResult& response, std::size_t probe, Real low, Real high);

}  // namespace feran

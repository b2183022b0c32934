#pragma once
/// @file
/// A coefficient (stiffness or damping) that may depend on the rotor speed and on the
/// frequency of the motion.

#include <string>
#include <variant>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// A coefficient c(Ω) or c(Ω, ω) of a spring–damper. All speeds and frequencies are in
/// rad/s.
///
/// Laws:
/// - Constant: c = value.
/// - Table: piecewise-linear interpolation in speed, held constant outside the table.
/// - Step: c = below for Ω < at, above for Ω ≥ at.
/// - Arctan (paper eq. 15): c = value·s(f), s(f) = c0 − (c1/π)·arctan(c2·(f − f_as)),
///   f = Ω/2π in Hz, c2 in 1/Hz. With c0 = 0.55, c1 = 0.9, c2 = 0.1 the factor runs from
///   100 % well below f_as to 10 % well above it.
/// - Frequency table: bilinear interpolation in speed Ω and in the frequency ω of the
///   motion (harmonic excitation, a mode's own damped frequency), each held constant
///   outside its range; c(Ω, −ω) = c(Ω, ω). Seals, squeeze films and support structures
///   whose dynamic stiffness k(ω) + jω·c(ω) varies with the excitation frequency.
class SpeedCoefficient {
 public:
  struct Constant {
    Real value = 0.0;
    bool operator==(const Constant&) const = default;
  };
  struct Table {
    std::vector<Real> speeds;  ///< strictly increasing [rad/s]
    std::vector<Real> values;
    bool operator==(const Table&) const = default;
  };
  struct Step {
    Real below = 0.0;
    Real above = 0.0;
    Real at = 0.0;  ///< switching speed [rad/s]
    bool operator==(const Step&) const = default;
  };
  struct Arctan {
    Real value = 0.0;
    Real f_as = 0.0;  ///< average switching frequency [Hz]
    Real c0 = 0.55;
    Real c1 = 0.9;
    Real c2 = 0.1;  ///< [1/Hz]
    bool operator==(const Arctan&) const = default;
  };
  struct FrequencyTable {
    std::vector<Real> speeds;       ///< strictly increasing [rad/s]; empty: the same at every speed
    std::vector<Real> frequencies;  ///< strictly increasing, ≥ 0 [rad/s]
    /// values[i·frequencies.size() + j] at speeds[i] and frequencies[j] (one row when
    /// speeds is empty)
    std::vector<Real> values;
    bool operator==(const FrequencyTable&) const = default;
  };
  using Law = std::variant<Constant, Table, Step, Arctan, FrequencyTable>;

  SpeedCoefficient() = default;
  /// A constant coefficient (implicit so that plain numbers read naturally).
  SpeedCoefficient(Real value) : law_(Constant{value}) {}  // NOLINT(google-explicit-constructor)
  explicit SpeedCoefficient(Law law) : law_(std::move(law)) {}

  /// Value at speed @p speed for motion at frequency @p frequency [rad/s].
  Real at(Real speed, Real frequency) const;
  /// Value at speed @p speed [rad/s] for synchronous motion (frequency = speed): what a
  /// caller without a frequency of its own sees (run-ups, critical speed maps).
  Real at(Real speed) const { return at(speed, speed); }
  /// True when the value is the same at every speed.
  bool is_constant() const { return std::holds_alternative<Constant>(law_); }
  /// True when the value depends on the frequency of the motion.
  bool frequency_dependent() const { return std::holds_alternative<FrequencyTable>(law_); }
  /// True when the coefficient is zero at every speed.
  bool is_zero() const;
  const Law& law() const { return law_; }
  bool operator==(const SpeedCoefficient&) const = default;

 private:
  Law law_ = Constant{};
};

}  // namespace feran

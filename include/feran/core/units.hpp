#pragma once
/// @file
/// Physical quantities written with units: "68 mm", "6e7 N/m", "30 Hz", "2000 rpm".
///
/// feran computes in SI units only (m, kg, s, N, rad, rad/s; frequencies in Hz).
/// Input (model files, command-line options) may state a quantity either as a bare
/// number, taken to be in the SI unit of its kind, or as a number followed by a
/// unit, with or without a space ("30 Hz", "30Hz"). Units are case-sensitive.
/// Before a unit is looked up it is normalised: surrounding spaces are dropped,
/// spaces around '*', '/' and '^' are removed, the remaining runs of spaces mean
/// multiplication ("kg m^2" reads as "kg*m^2"), '·' and '⋅' read as '*', '²' and '³'
/// as "^2" and "^3", and 'µm'/'μm' as "um".

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/error.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// The kind of a physical quantity; it fixes the SI unit and the accepted units.
enum class Quantity {
  length,                ///< m; also mm, cm, um
  mass,                  ///< kg; also g
  inertia,               ///< moment of inertia, kg*m^2; also kg*mm^2
  pressure,              ///< Pa (elastic moduli); also kPa, MPa, GPa, N/mm^2
  density,               ///< kg/m^3; also g/cm^3
  stiffness,             ///< N/m; also kN/m, MN/m, N/mm, kN/mm
  rotational_stiffness,  ///< N*m/rad; also Nm/rad, N*m
  damping,               ///< N*s/m; also Ns/m, kN*s/m
  rotational_damping,    ///< N*m*s/rad; also Nms/rad, N*m*s, Nms
  speed,                 ///< rotor speed, rad/s; also Hz (rev/s) and rpm
  frequency,             ///< Hz (the SI unit of this kind is Hz, not rad/s)
  angle,                 ///< rad; also deg
  force,                 ///< N; also kN
  moment,                ///< N*m; also Nm
  time,                  ///< s; also ms
  velocity,              ///< m/s; also mm/s
  angular_velocity,      ///< rad/s
  acceleration,          ///< m/s^2; also mm/s^2 (appended: keep the order of the others)
  inverse_time,          ///< 1/s (a rate: the mass-proportional damping α)
  viscosity,             ///< dynamic viscosity, Pa*s; also mPa*s and cP
};

/// The magnitudes of a kind that any rotor model can hold, in SI: beyond `largest`
/// (a 10 km shaft, a 10¹³ Pa modulus, 10⁶ rad/s) a value is a mistake or an attack
/// on the numerics, not a design; a value that must be positive is at least
/// `smallest_positive` (a 1 nm section, a 1 ps step). Generous by orders of
/// magnitude on both sides of real machines.
struct PhysicalRange {
  Real largest = 0;
  Real smallest_positive = 0;
};
PhysicalRange physical_range(Quantity kind);

/// Name of the kind with its article, for messages: "a length", "an angle".
std::string_view quantity_name(Quantity kind);
/// Name of the kind without article: "length", "speed".
std::string_view quantity_noun(Quantity kind);
/// The unit a bare number of this kind is in: "m", "rad/s", "Hz" (frequency).
std::string_view si_unit(Quantity kind);
/// The units accepted for @p kind, SI unit first, in their normalised spelling.
std::vector<std::string_view> accepted_units(Quantity kind);
/// The accepted units as a list for messages: "m, mm, cm or um".
std::string accepted_units_text(Quantity kind);
/// A typical value written with a unit, for messages: "68 mm".
std::string_view unit_example(Quantity kind);
/// The same typical value as a bare SI number, for messages: "0.068".
std::string_view si_example(Quantity kind);

/// Normalises the spelling of a unit as described in the file comment.
std::string normalize_unit(std::string_view unit);

/// Converts @p value in unit @p unit (any accepted spelling) to the SI unit of
/// @p kind; std::nullopt when @p unit is not accepted for @p kind.
std::optional<Real> to_si(Quantity kind, Real value, std::string_view unit);

/// Converts an SI value of @p kind to unit @p unit; std::nullopt when the unit is
/// not accepted for the kind.
std::optional<Real> from_si(Quantity kind, Real si, std::string_view unit);

/// "68 mm": @p si written in @p unit when that text reads back as exactly @p si
/// (shortest round-trip digits), else in the SI unit ("0.068 m"). An empty @p unit
/// means the SI unit.
std::string format_quantity(Real si, Quantity kind, std::string_view unit = {});

/// @p si in @p unit to 6 significant digits ("1.59155e+05 Hz"), else in the SI unit:
/// how messages echo a limit in the unit the user wrote.
std::string approximate_quantity(Real si, Quantity kind, std::string_view unit = {});

/// "'length' must be a length (a number in m, or a string such as "68 mm")".
std::string must_be_quantity(std::string_view name, Quantity kind);
/// "a length, e.g. 0.068 or "68 mm"" (for missing-key messages).
std::string expected_quantity(Quantity kind);

/// A quantity as written: its number and its unit text (trimmed, not normalised;
/// empty for a bare number).
struct QuantityText {
  Real value = 0.0;
  std::string unit;
};

/// Splits "68 mm", "30Hz" or "-1.5e3" into number and unit. Accepts an optional
/// sign, decimal and exponent notation, "inf" and "nan" (callers reject them).
/// std::nullopt when @p text does not start with a number.
std::optional<QuantityText> split_quantity(std::string_view text);

/// What is wrong with a quantity text.
class QuantityError : public Error {
 public:
  enum class Reason {
    not_a_number,  ///< the text does not start with a number
    not_finite,    ///< the number is infinite or NaN
    wrong_unit,    ///< the unit is not accepted for the kind
  };
  QuantityError(Reason reason, Quantity kind, std::string text, std::string unit, const std::string& message)
      : Error(message), reason_(reason), kind_(kind), text_(std::move(text)), unit_(std::move(unit)) {}
  Reason reason() const { return reason_; }
  Quantity kind() const { return kind_; }
  /// The text that was parsed.
  const std::string& text() const { return text_; }
  /// The unit as written (for Reason::wrong_unit).
  const std::string& unit() const { return unit_; }

 private:
  Reason reason_;
  Quantity kind_;
  std::string text_;
  std::string unit_;
};

/// Parses a quantity of kind @p kind written as "value unit", "valueunit" or a bare
/// number (SI), and returns it in the SI unit of the kind (speeds in rad/s,
/// frequencies in Hz). Throws QuantityError, whose message reads e.g.
/// "\"5 kg\" has unit 'kg', expected a length in m, mm, cm or um".
Real parse_quantity(std::string_view text, Quantity kind);

/// A unit-related hint for a unit that is not accepted for @p kind, or "":
/// "units are case-sensitive: did you mean 'rpm'?" or "'kg' is a unit of mass".
std::string unit_hint(Quantity kind, std::string_view unit);

}  // namespace feran

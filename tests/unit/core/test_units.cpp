// Tests of core/units: parsing "value unit" quantities into SI.
//
// Tolerances: conversions are one multiplication and one division of exactly
// representable factors (or of 2π), so results are compared with
// EXPECT_DOUBLE_EQ (4 ulp) against the same arithmetic written out; where the
// expected value is a decimal literal (0.068), the reader divides by 1000 so the
// result is the correctly rounded double of that literal.

#include <feran/core/units.hpp>

#include <gtest/gtest.h>

#include <string>

namespace feran::test_units {
namespace {

TEST(Units, LengthInEveryUnit) {
  EXPECT_DOUBLE_EQ(parse_quantity("0.068 m", Quantity::length), 0.068);
  EXPECT_DOUBLE_EQ(parse_quantity("68 mm", Quantity::length), 0.068);
  EXPECT_DOUBLE_EQ(parse_quantity("6.8 cm", Quantity::length), 0.068);
  EXPECT_DOUBLE_EQ(parse_quantity("68000 um", Quantity::length), 0.068);
  EXPECT_DOUBLE_EQ(parse_quantity("68000 µm", Quantity::length), 0.068);  // micro sign
  EXPECT_DOUBLE_EQ(parse_quantity("68000 μm", Quantity::length), 0.068);  // Greek mu
}

TEST(Units, MassInertiaPressureDensity) {
  EXPECT_DOUBLE_EQ(parse_quantity("1.93 kg", Quantity::mass), 1.93);
  EXPECT_DOUBLE_EQ(parse_quantity("3 g", Quantity::mass), 0.003);
  EXPECT_DOUBLE_EQ(parse_quantity("0.0063 kg*m^2", Quantity::inertia), 0.0063);
  EXPECT_DOUBLE_EQ(parse_quantity("0.0063 kg m^2", Quantity::inertia), 0.0063);
  EXPECT_DOUBLE_EQ(parse_quantity("0.0063 kg·m²", Quantity::inertia), 0.0063);
  EXPECT_DOUBLE_EQ(parse_quantity("0.0063 kg m²", Quantity::inertia), 0.0063);
  EXPECT_DOUBLE_EQ(parse_quantity("6300 kg*mm^2", Quantity::inertia), 0.0063);
  EXPECT_DOUBLE_EQ(parse_quantity("210 GPa", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("210000 MPa", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("210000 N/mm^2", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("210000 N/mm²", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("2.1e8 kPa", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("2.1e11 Pa", Quantity::pressure), 210e9);
  EXPECT_DOUBLE_EQ(parse_quantity("7850 kg/m^3", Quantity::density), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7850 kg/m³", Quantity::density), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7.85 g/cm^3", Quantity::density), 7850.0);
}

TEST(Units, StiffnessAndDamping) {
  EXPECT_DOUBLE_EQ(parse_quantity("6e7 N/m", Quantity::stiffness), 6e7);
  EXPECT_DOUBLE_EQ(parse_quantity("6e4 kN/m", Quantity::stiffness), 6e7);
  EXPECT_DOUBLE_EQ(parse_quantity("60 MN/m", Quantity::stiffness), 6e7);
  EXPECT_DOUBLE_EQ(parse_quantity("6e4 N/mm", Quantity::stiffness), 6e7);
  EXPECT_DOUBLE_EQ(parse_quantity("60 kN/mm", Quantity::stiffness), 6e7);
  EXPECT_DOUBLE_EQ(parse_quantity("180 N*m/rad", Quantity::rotational_stiffness), 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("180 Nm/rad", Quantity::rotational_stiffness), 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("180 N·m", Quantity::rotational_stiffness), 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("180 N m / rad", Quantity::rotational_stiffness), 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("75 N*s/m", Quantity::damping), 75.0);
  EXPECT_DOUBLE_EQ(parse_quantity("75 Ns/m", Quantity::damping), 75.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.075 kN*s/m", Quantity::damping), 75.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.06 N*m*s/rad", Quantity::rotational_damping), 0.06);
  EXPECT_DOUBLE_EQ(parse_quantity("0.06 Nms/rad", Quantity::rotational_damping), 0.06);
  EXPECT_DOUBLE_EQ(parse_quantity("0.06 N*m*s", Quantity::rotational_damping), 0.06);
  EXPECT_DOUBLE_EQ(parse_quantity("0.06 Nms", Quantity::rotational_damping), 0.06);
}

TEST(Units, SpeedIsStoredInRadPerSecond) {
  EXPECT_DOUBLE_EQ(parse_quantity("30 Hz", Quantity::speed), 2.0 * pi * 30.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2000 rpm", Quantity::speed), 2000.0 * 2.0 * pi / 60.0);
  EXPECT_DOUBLE_EQ(parse_quantity("100 rad/s", Quantity::speed), 100.0);
  // Command-line style: no space between number and unit.
  EXPECT_DOUBLE_EQ(parse_quantity("30Hz", Quantity::speed), 2.0 * pi * 30.0);
  EXPECT_DOUBLE_EQ(parse_quantity("2000rpm", Quantity::speed), 2000.0 * 2.0 * pi / 60.0);
}

TEST(Units, FrequencyIsStoredInHz) {
  EXPECT_DOUBLE_EQ(parse_quantity("3.98 Hz", Quantity::frequency), 3.98);
  EXPECT_DOUBLE_EQ(parse_quantity("3.98", Quantity::frequency), 3.98);
  EXPECT_THROW(parse_quantity("3.98 rpm", Quantity::frequency), QuantityError);
}

TEST(Units, AngleForceMomentTimeVelocity) {
  EXPECT_DOUBLE_EQ(parse_quantity("90 deg", Quantity::angle), pi / 2.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.5 rad", Quantity::angle), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity("5.2 N", Quantity::force), 5.2);
  EXPECT_DOUBLE_EQ(parse_quantity("0.0052 kN", Quantity::force), 5.2);
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 N*m", Quantity::moment), 0.1);
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 Nm", Quantity::moment), 0.1);
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 ms", Quantity::time), 1e-4);
  EXPECT_DOUBLE_EQ(parse_quantity("2 s", Quantity::time), 2.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 mm/s", Quantity::velocity), 1e-4);
  EXPECT_DOUBLE_EQ(parse_quantity("1e-4 m/s", Quantity::velocity), 1e-4);
  EXPECT_DOUBLE_EQ(parse_quantity("0.001 rad/s", Quantity::angular_velocity), 0.001);
}

// 1 cP (centipoise) = 1 mPa·s; an ISO VG 32 oil at 40 °C is about 28 mPa·s.
TEST(Units, Viscosity) {
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 Pa*s", Quantity::viscosity), 0.1);
  EXPECT_DOUBLE_EQ(parse_quantity("0.1 Pa s", Quantity::viscosity), 0.1);
  EXPECT_DOUBLE_EQ(parse_quantity("28 mPa*s", Quantity::viscosity), 0.028);
  EXPECT_DOUBLE_EQ(parse_quantity("28 cP", Quantity::viscosity), 0.028);
  EXPECT_EQ(si_unit(Quantity::viscosity), "Pa*s");
  EXPECT_EQ(accepted_units_text(Quantity::viscosity), "Pa*s, mPa*s or cP (any SI prefix on Pa*s too: kPa*s, mPa*s, …)");
  EXPECT_THROW(parse_quantity("0.1 Pa", Quantity::viscosity), QuantityError);
}

TEST(Units, Acceleration) {
  EXPECT_DOUBLE_EQ(parse_quantity("9.81 m/s^2", Quantity::acceleration), 9.81);
  EXPECT_DOUBLE_EQ(parse_quantity("9.81 m/s²", Quantity::acceleration), 9.81);
  EXPECT_DOUBLE_EQ(parse_quantity("9810 mm/s^2", Quantity::acceleration), 9.81);
  EXPECT_DOUBLE_EQ(parse_quantity("9810mm/s²", Quantity::acceleration), 9.81);
  EXPECT_DOUBLE_EQ(parse_quantity("9.81", Quantity::acceleration), 9.81);
  EXPECT_EQ(si_unit(Quantity::acceleration), "m/s^2");
  EXPECT_EQ(quantity_name(Quantity::acceleration), "an acceleration");
  EXPECT_EQ(accepted_units_text(Quantity::acceleration),
            "m/s^2 or mm/s^2 (any SI prefix on m/s^2 too: km/s^2, mm/s^2, …)");
  // A velocity unit is not an acceleration, and the message says what it is.
  try {
    parse_quantity("9.81 m/s", Quantity::acceleration);
    FAIL() << "expected a QuantityError";
  } catch (const QuantityError& e) {
    EXPECT_EQ(e.reason(), QuantityError::Reason::wrong_unit);
    EXPECT_STREQ(e.what(),
                 "\"9.81 m/s\" has unit 'm/s', expected an acceleration in m/s^2 or mm/s^2 (any SI prefix on "
                 "m/s^2 too: km/s^2, mm/s^2, …) ('m/s' is a unit of velocity)");
  }
  EXPECT_THROW(parse_quantity("1 g", Quantity::acceleration), QuantityError);  // g is grams
  EXPECT_THROW(parse_quantity("1 m/s^2", Quantity::velocity), QuantityError);
}

TEST(Units, EnumOrderIsStable) {
  // Quantity values may be stored or passed as integers; new kinds are appended.
  EXPECT_EQ(static_cast<int>(Quantity::length), 0);
  EXPECT_EQ(static_cast<int>(Quantity::angular_velocity), 16);
  EXPECT_EQ(static_cast<int>(Quantity::acceleration), 17);
}

TEST(Units, NumbersWithoutUnitAreSi) {
  EXPECT_DOUBLE_EQ(parse_quantity("0.068", Quantity::length), 0.068);
  EXPECT_DOUBLE_EQ(parse_quantity("  -1.5e3 ", Quantity::force), -1500.0);
  EXPECT_DOUBLE_EQ(parse_quantity("+30", Quantity::speed), 30.0);
  EXPECT_DOUBLE_EQ(parse_quantity("30", Quantity::speed), 30.0);
  EXPECT_DOUBLE_EQ(parse_quantity(".5", Quantity::length), 0.5);
}

TEST(Units, EverySiPrefixWorksOnTheCoherentUnitsAndTheGram) {
  // The BIPM's prefixes before the coherent SI unit of each quantity, exact to the
  // double nearest the decimal value (sub-multiples divide, as the listed "mm" does).
  EXPECT_EQ(parse_quantity("2 MN", Quantity::force), 2e6);
  EXPECT_EQ(parse_quantity("3 mN", Quantity::force), 3e-3);
  EXPECT_EQ(parse_quantity("68 nm", Quantity::length), 68e-9);
  EXPECT_EQ(parse_quantity("1.5 km", Quantity::length), 1500);
  EXPECT_EQ(parse_quantity("250 mg", Quantity::mass), 250e-6);
  EXPECT_EQ(parse_quantity("4 GN/m", Quantity::stiffness), 4e9);
  EXPECT_EQ(parse_quantity("5 kN*m", Quantity::rotational_stiffness), 5e3);
  EXPECT_EQ(parse_quantity("20 us", Quantity::time), 20e-6);
  EXPECT_EQ(parse_quantity("2 kHz", Quantity::frequency), 2e3);
  EXPECT_EQ(parse_quantity("2 kHz", Quantity::speed), 2e3 * 2 * pi);
  EXPECT_EQ(parse_quantity("3 hPa", Quantity::pressure), 300);
  EXPECT_EQ(parse_quantity("10 mrad", Quantity::angle), 10e-3);
  EXPECT_EQ(parse_quantity("7 kN*m", Quantity::moment), 7e3);
  // Not on kg (already prefixed), rpm, deg or cP, and one prefix only.
  for (const auto& [text, kind] : {std::pair{"1 kkg", Quantity::mass},
                                   {"1 krpm", Quantity::speed},
                                   {"1 mdeg", Quantity::angle},
                                   {"1 kcP", Quantity::viscosity},
                                   {"1 kmm", Quantity::length},
                                   {"1 MM", Quantity::length}})
    EXPECT_THROW(parse_quantity(text, kind), QuantityError) << text;
  EXPECT_EQ(format_quantity(2e6, Quantity::force, "MN"), "2 MN");
}

TEST(Units, RejectsUnitsOfOtherKinds) {
  try {
    parse_quantity("5 kg", Quantity::length);
    FAIL() << "expected a QuantityError";
  } catch (const QuantityError& e) {
    EXPECT_EQ(e.reason(), QuantityError::Reason::wrong_unit);
    EXPECT_EQ(e.unit(), "kg");
    EXPECT_STREQ(e.what(),
                 "\"5 kg\" has unit 'kg', expected a length in m, mm, cm or um (any SI prefix on m "
                 "too: km, mm, …) ('kg' is a unit of mass)");
  }
  EXPECT_THROW(parse_quantity("30 Hz", Quantity::length), QuantityError);
  EXPECT_THROW(parse_quantity("5 N/m", Quantity::damping), QuantityError);
  EXPECT_THROW(parse_quantity("5 rad/s", Quantity::velocity), QuantityError);
  EXPECT_THROW(parse_quantity("5 kN*m*s", Quantity::rotational_stiffness), QuantityError);
  EXPECT_THROW(parse_quantity("5 m extra", Quantity::length), QuantityError);
}

TEST(Units, UnitsAreCaseSensitiveWithAHint) {
  try {
    parse_quantity("3000 RPM", Quantity::speed);
    FAIL() << "expected a QuantityError";
  } catch (const QuantityError& e) {
    EXPECT_EQ(e.reason(), QuantityError::Reason::wrong_unit);
    EXPECT_NE(std::string(e.what()).find("did you mean 'rpm'?"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_quantity("5 MM", Quantity::length), QuantityError);
  EXPECT_THROW(parse_quantity("30 hz", Quantity::speed), QuantityError);
}

TEST(Units, RejectsTextThatIsNotANumber) {
  for (const char* text : {"", "mm", "abc", "- 5 mm", "--5", "e5"}) {
    try {
      parse_quantity(text, Quantity::length);
      FAIL() << "expected a QuantityError for \"" << text << "\"";
    } catch (const QuantityError& e) {
      EXPECT_EQ(e.reason(), QuantityError::Reason::not_a_number) << text;
    }
  }
}

TEST(Units, RejectsNonFiniteNumbers) {
  for (const char* text : {"inf", "-inf m", "nan", "1e400 mm"}) {
    try {
      parse_quantity(text, Quantity::length);
      FAIL() << "expected a QuantityError for \"" << text << "\"";
    } catch (const QuantityError& e) {
      EXPECT_EQ(e.reason(), QuantityError::Reason::not_finite) << text;
    }
  }
  // Underflow is zero, not an error.
  EXPECT_EQ(parse_quantity("1e-400 m", Quantity::length), 0.0);
}

TEST(Units, NormalisesSpellings) {
  EXPECT_EQ(normalize_unit(" kg m^2 "), "kg*m^2");
  EXPECT_EQ(normalize_unit("kg·m²"), "kg*m^2");
  EXPECT_EQ(normalize_unit("kg⋅m²"), "kg*m^2");
  EXPECT_EQ(normalize_unit("N * m * s / rad"), "N*m*s/rad");
  EXPECT_EQ(normalize_unit("g/cm³"), "g/cm^3");
  EXPECT_EQ(normalize_unit("µm"), "um");
}

TEST(Units, SplitsNumberAndUnit) {
  const auto a = split_quantity("68 mm");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->value, 68.0);
  EXPECT_EQ(a->unit, "mm");
  const auto b = split_quantity("30Hz");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->value, 30.0);
  EXPECT_EQ(b->unit, "Hz");
  const auto c = split_quantity("-1e-3");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->value, -1e-3);
  EXPECT_EQ(c->unit, "");
  EXPECT_FALSE(split_quantity("Hz"));
}

TEST(Units, DescribesKinds) {
  EXPECT_EQ(quantity_name(Quantity::length), "a length");
  EXPECT_EQ(quantity_name(Quantity::angle), "an angle");
  EXPECT_EQ(si_unit(Quantity::speed), "rad/s");
  EXPECT_EQ(si_unit(Quantity::frequency), "Hz");
  EXPECT_EQ(accepted_units_text(Quantity::length), "m, mm, cm or um (any SI prefix on m too: km, mm, …)");
  EXPECT_EQ(accepted_units_text(Quantity::speed), "rad/s, Hz or rpm (any SI prefix on rad/s too: krad/s, mrad/s, …)");
  EXPECT_EQ(accepted_units_text(Quantity::inertia), "kg*m^2, kg*mm^2 or kg m^2");
  // Every accepted unit converts, and its example parses.
  for (int k = 0; k <= static_cast<int>(Quantity::acceleration); ++k) {
    const auto kind = static_cast<Quantity>(k);
    for (const auto unit : accepted_units(kind)) EXPECT_TRUE(to_si(kind, 1.0, unit)) << unit;
    EXPECT_NO_THROW(parse_quantity(unit_example(kind), kind)) << unit_example(kind);
    EXPECT_NO_THROW(parse_quantity(si_example(kind), kind)) << si_example(kind);
    // The SI example and the example with a unit state the same value to 0.5 %
    // (the SI examples are rounded, e.g. 188.5 rad/s for 30 Hz).
    EXPECT_NEAR(parse_quantity(si_example(kind), kind), parse_quantity(unit_example(kind), kind),
                5e-3 * parse_quantity(unit_example(kind), kind))
        << quantity_name(kind);
  }
}

}  // namespace
}  // namespace feran::test_units

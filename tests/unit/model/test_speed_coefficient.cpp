// Unit tests of speed-dependent coefficients (docs/theory/spring_damper.md): constant,
// table, step and the arctan law of paper eq. 15. Speeds are in rad/s throughout;
// the arctan law works in Hz, f = Ω/(2π).
#include <gtest/gtest.h>

#include <cmath>

#include <feran/core/error.hpp>
#include <feran/model/speed_coefficient.hpp>

namespace feran::test_speed_coefficient {
namespace {

using SC = SpeedCoefficient;

// Converts Hz to rad/s by hand, not through the library's helper.
constexpr Real rad_per_s(Real hz) { return 2.0 * 3.14159265358979323846 * hz; }

TEST(SpeedCoefficient, Constant) {
  const SC c = 4.5e6;
  EXPECT_TRUE(c.is_constant());
  for (const Real w : {0.0, 10.0, 1e4}) EXPECT_EQ(c.at(w), 4.5e6);
  EXPECT_FALSE(c.is_zero());
  EXPECT_TRUE(SC().is_zero());
  EXPECT_TRUE(SC(0.0).is_zero());
  EXPECT_EQ(SC().at(123.0), 0.0);
}

// Piecewise-linear inside, held at the end values outside. Hand values: between
// (10, 1) and (20, 3) at 15 → 2; between (20, 3) and (40, −1) at 30 → 1 and at 35 → 0.
// Tolerance 1e-15: one linear interpolation of O(1) values.
TEST(SpeedCoefficient, TableInterpolatesAndHoldsOutside) {
  const SC t(SC::Table{{10.0, 20.0, 40.0}, {1.0, 3.0, -1.0}});
  EXPECT_FALSE(t.is_constant());
  EXPECT_NEAR(t.at(15.0), 2.0, 1e-15);
  EXPECT_NEAR(t.at(30.0), 1.0, 1e-15);
  EXPECT_NEAR(t.at(35.0), 0.0, 1e-15);
  EXPECT_NEAR(t.at(12.5), 1.5, 1e-15);
  EXPECT_EQ(t.at(10.0), 1.0);  // at the knots: the table values
  EXPECT_EQ(t.at(20.0), 3.0);
  EXPECT_EQ(t.at(40.0), -1.0);
  EXPECT_EQ(t.at(0.0), 1.0);  // below the table: first value
  EXPECT_EQ(t.at(-5.0), 1.0);
  EXPECT_EQ(t.at(1e6), -1.0);  // above: last value
  EXPECT_FALSE(t.is_zero());

  const SC single(SC::Table{{50.0}, {7.0}});
  for (const Real w : {0.0, 50.0, 1e3}) EXPECT_EQ(single.at(w), 7.0);

  EXPECT_TRUE(SC(SC::Table{{0.0, 1.0}, {0.0, 0.0}}).is_zero());
  EXPECT_FALSE(SC(SC::Table{{0.0, 1.0}, {0.0, 1e-9}}).is_zero());
}

// Step: the lower value below the switching speed, the upper value at and above it.
TEST(SpeedCoefficient, Step) {
  const SC s(SC::Step{6e6, 6e5, rad_per_s(60.0)});
  EXPECT_FALSE(s.is_constant());
  EXPECT_EQ(s.at(0.0), 6e6);
  EXPECT_EQ(s.at(rad_per_s(59.999)), 6e6);
  EXPECT_EQ(s.at(rad_per_s(60.0)), 6e5);
  EXPECT_EQ(s.at(rad_per_s(60.001)), 6e5);
  EXPECT_EQ(s.at(rad_per_s(1000.0)), 6e5);
  EXPECT_FALSE(s.is_zero());
  EXPECT_FALSE(SC(SC::Step{0.0, 1.0, 5.0}).is_zero());
  EXPECT_FALSE(SC(SC::Step{1.0, 0.0, 5.0}).is_zero());
  EXPECT_TRUE(SC(SC::Step{0.0, 0.0, 5.0}).is_zero());
}

// Arctan law (paper eq. 15): c = value·s(f), s(f) = 0.55 − (0.9/π)·arctan(0.1·(f − f_as)),
// f in Hz. Hand values: s(f_as) = 0.55; s(f_as ± 10 Hz) = 0.55 ∓ 0.9/4 = 0.325 / 0.775
// (arctan 1 = π/4). Tolerance 1e-14 relative: one arctan and a few products.
TEST(SpeedCoefficient, ArctanLawPaperConstants) {
  const Real value = 6e6, f_as = 3.98;
  const SC a(SC::Arctan{value, f_as});
  EXPECT_FALSE(a.is_constant());
  EXPECT_NEAR(a.at(rad_per_s(f_as)), 0.55 * value, 1e-14 * value);
  EXPECT_NEAR(a.at(rad_per_s(f_as + 10.0)), 0.325 * value, 1e-14 * value);
  EXPECT_NEAR(a.at(rad_per_s(f_as - 10.0)), 0.775 * value, 1e-14 * value);
  // f is in Hz: the same numbers as rad/s would put the midpoint elsewhere.
  EXPECT_GT(std::abs(a.at(f_as) - 0.55 * value), 0.01 * value);

  // Far from f_as the factor tends to c0 ± c1/2 = 1.0 and 0.1. 1e6 Hz away the
  // arctan is π/2 − 1e-5, so s is within 0.9/π·1e-5 ≈ 2.9e-6 of its limit; 5e-6.
  const SC far(SC::Arctan{1.0, 1e6});
  EXPECT_NEAR(far.at(0.0), 1.0, 5e-6);
  EXPECT_NEAR(a.at(rad_per_s(1e6)), 0.1 * value, 5e-6 * value);
  // Monotone decreasing in speed.
  Real previous = a.at(0.0);
  for (Real f = 1.0; f <= 200.0; f += 1.0) {
    const Real now = a.at(rad_per_s(f));
    EXPECT_LT(now, previous) << f << " Hz";
    previous = now;
  }
  // With the paper's c2 = 0.1/Hz the law is broad: at standstill, f_as = 3.98 Hz,
  // s(0) = 0.55 + 0.9/π·arctan(0.398) = 0.6585 (hand value, four digits), and at
  // 100 Hz s = 0.1297: the paper's "100 % below, 10 % above f_as" is asymptotic.
  EXPECT_NEAR(a.at(0.0) / value, 0.6585, 5e-5);
  EXPECT_NEAR(a.at(rad_per_s(100.0)) / value, 0.1297, 5e-5);

  EXPECT_TRUE(SC(SC::Arctan{0.0, 3.98}).is_zero());
  EXPECT_FALSE(a.is_zero());
}

// The law's constants are parameters: s = c0 − (c1/π)·arctan(c2·(f − f_as)).
// Hand value: c0 = 0.5, c1 = 0.8, c2 = 1/Hz at f = f_as + 1 Hz: 0.5 − 0.8/4 = 0.3.
TEST(SpeedCoefficient, ArctanLawConstantsAreParameters) {
  const SC a(SC::Arctan{2.0, 10.0, 0.5, 0.8, 1.0});
  EXPECT_NEAR(a.at(rad_per_s(11.0)), 2.0 * 0.3, 1e-14);
  EXPECT_NEAR(a.at(rad_per_s(10.0)), 2.0 * 0.5, 1e-14);
}

// Bilinear interpolation reproduces a bilinear function c = a + bΩ + cω + dΩω exactly
// inside the table (reference: the function itself, to round-off 1e-12 of its size),
// holds the edge values outside it, and is even in ω (c(Ω, −ω) = c(Ω, ω)).
TEST(SpeedCoefficient, FrequencyTableIsBilinearInSpeedAndFrequency) {
  const auto f = [](Real speed, Real omega) { return 3e6 + 2e3 * speed - 4e2 * omega + 1.5 * speed * omega; };
  SC::FrequencyTable t;
  t.speeds = {100.0, 250.0, 600.0};
  t.frequencies = {0.0, 80.0, 300.0, 1000.0};
  for (const Real s : t.speeds)
    for (const Real w : t.frequencies) t.values.push_back(f(s, w));
  const SC c(SC::Law{t});
  EXPECT_TRUE(c.frequency_dependent());
  EXPECT_FALSE(c.is_constant());
  for (const Real s : {100.0, 173.0, 250.0, 512.5, 600.0})
    for (const Real w : {0.0, 33.0, 80.0, 299.0, 777.0, 1000.0}) {
      EXPECT_NEAR(c.at(s, w), f(s, w), 1e-12 * std::abs(f(s, w))) << s << " " << w;
      EXPECT_EQ(c.at(s, -w), c.at(s, w));
    }
  // Beyond the table the edge is held, in either direction.
  EXPECT_NEAR(c.at(50.0, 2000.0), f(100.0, 1000.0), 1e-12 * f(100.0, 1000.0));
  EXPECT_NEAR(c.at(900.0, 500.0), f(600.0, 500.0), 1e-12 * f(600.0, 500.0));
  // Synchronous use (callers without a frequency): ω = Ω.
  EXPECT_EQ(c.at(250.0), c.at(250.0, 250.0));

  // Without speeds: one row, the same at every speed; one frequency: a constant.
  SC::FrequencyTable row{{}, {0.0, 100.0}, {1e6, 3e6}};
  EXPECT_EQ(SC(SC::Law{row}).at(0.0, 25.0), 1.5e6);
  EXPECT_EQ(SC(SC::Law{row}).at(1e4, 25.0), 1.5e6);
  EXPECT_EQ(SC(SC::Law{SC::FrequencyTable{{}, {10.0}, {7.0}}}).at(3.0, 99.0), 7.0);
  EXPECT_TRUE(SC(SC::Law{SC::FrequencyTable{{}, {0.0, 1.0}, {0.0, 0.0}}}).is_zero());
  // A table whose values do not fill its grid is refused, not read past its end.
  EXPECT_THROW((void)SC(SC::Law{SC::FrequencyTable{{0.0, 1.0}, {0.0, 1.0}, {1.0, 2.0}}}).at(0.5, 0.5), Error);
}

TEST(SpeedCoefficient, Equality) {
  EXPECT_EQ(SC(3.0), SC(SC::Constant{3.0}));
  EXPECT_NE(SC(3.0), SC(SC::Step{3.0, 3.0, 0.0}));
  EXPECT_EQ(SC(SC::Arctan{1.0, 2.0}), SC(SC::Arctan{1.0, 2.0, 0.55, 0.9, 0.1}));
}

}  // namespace
}  // namespace feran::test_speed_coefficient

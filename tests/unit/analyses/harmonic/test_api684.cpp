// The API 684 reading of a response curve: peaks and half-power points on curves whose
// answer is known by construction, and API 617's required separation margins at the
// breakpoints of their rules.
#include <cmath>

#include <gtest/gtest.h>

#include <feran/analyses/harmonic/api684.hpp>
#include <feran/core/error.hpp>

namespace feran {
namespace {

TEST(ResponsePeaks, APiecewiseLinearPeakHasItsHalfPowerPointsWhereTheLinesCross) {
  // A tent from 0 at speed 0 to 1 at speed 10 and back to 0 at 20, sampled every unit:
  // the half-power points lie on the lines, at 10/√2 and 20 − 10/√2, whatever the
  // sampling; N_c = 10 (a symmetric top: the parabola's top is the middle point).
  std::vector<Real> s, a;
  for (int i = 0; i <= 20; ++i) {
    s.push_back(i);
    a.push_back(1 - std::abs(i - 10) / 10.0);
  }
  const auto peaks = response_peaks(s, a);
  ASSERT_EQ(peaks.size(), 1u);
  const auto& p = peaks[0];
  EXPECT_DOUBLE_EQ(p.speed, 10.0);
  EXPECT_DOUBLE_EQ(p.amplitude, 1.0);
  ASSERT_TRUE(p.resolved());
  EXPECT_NEAR(*p.lower_half_power, 10 / std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(*p.upper_half_power, 20 - 10 / std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(p.amplification_factor, 10 / (10 - 20 / std::sqrt(2.0) + 10), 1e-14);
}

TEST(ResponsePeaks, TheParabolaFindsTheTopBetweenPoints) {
  // a = 1 − (s − 3.3)² sampled at the integers: the top at 3.3 exactly, on unevenly
  // spaced points too.
  const std::vector<Real> s{1, 2, 3, 4.5, 6};
  std::vector<Real> a;
  for (const Real x : s) a.push_back(1 - (x - 3.3) * (x - 3.3));
  const auto peaks = response_peaks(s, a);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_NEAR(peaks[0].speed, 3.3, 1e-14);
  EXPECT_NEAR(peaks[0].amplitude, 1.0, 1e-14);
}

TEST(ResponsePeaks, APeakThatDoesNotFallFarEnoughHasNoFactor) {
  // Two resonances and a small peak between them: the peak at 6 falls to 1/√2 of
  // itself below (between 3 and 4) but not above before the curve rises past it; the
  // peak at the sweep's end has no upper half-power point.
  const std::vector<Real> s{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  const std::vector<Real> a{0.1, 0.5, 2.0, 0.5, 0.7, 0.8, 0.9, 0.8, 1.0, 1.5, 3.0};
  const auto peaks = response_peaks(s, a);
  ASSERT_EQ(peaks.size(), 3u);
  EXPECT_DOUBLE_EQ(peaks[0].speed, 2.0);
  ASSERT_TRUE(peaks[0].resolved());
  EXPECT_NEAR(*peaks[0].lower_half_power, 1 + (std::sqrt(2.0) - 0.5) / 1.5, 1e-14);
  EXPECT_NEAR(*peaks[0].upper_half_power, 3 - (std::sqrt(2.0) - 0.5) / 1.5, 1e-14);
  EXPECT_DOUBLE_EQ(peaks[1].speed, 6.0);
  ASSERT_TRUE(peaks[1].lower_half_power.has_value());
  EXPECT_NEAR(*peaks[1].lower_half_power, 3 + (0.9 / std::sqrt(2.0) - 0.5) / 0.2, 1e-14);
  EXPECT_EQ(peaks[1].upper_half_power, std::nullopt);  // 1.0 at 8 comes first
  EXPECT_TRUE(std::isnan(peaks[1].amplification_factor));
  EXPECT_DOUBLE_EQ(peaks[2].speed, 10.0);
  EXPECT_EQ(peaks[2].upper_half_power, std::nullopt);
}

TEST(ResponsePeaks, AFlatTopIsOnePeakAndBadCurvesAreRefused) {
  const std::vector<Real> s{0, 1, 2, 3, 4};
  const auto peaks = response_peaks(s, std::vector<Real>{0, 1, 1, 1, 0});
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_DOUBLE_EQ(peaks[0].speed, 1.0);  // the first point of the top
  EXPECT_TRUE(response_peaks(std::vector<Real>{}, std::vector<Real>{}).empty());
  EXPECT_THROW(response_peaks(s, std::vector<Real>{1, 2}), Error);
  EXPECT_THROW(response_peaks(std::vector<Real>{0, 2, 1}, std::vector<Real>{0, 1, 0}), Error);
}

TEST(RequiredSeparationMargin, TheRulesAtTheirBreakpoints) {
  const Real low = 100, high = 120;
  // Below AF 2.5 none is required, on either side, and 0 at 2.5 where the rule starts.
  EXPECT_EQ(required_separation_margin(2.4, 50, low, high), 0.0);
  EXPECT_EQ(required_separation_margin(2.4, 200, low, high), 0.0);
  EXPECT_NEAR(required_separation_margin(2.5, 50, low, high), 0.0, 1e-15);
  EXPECT_NEAR(required_separation_margin(2.5, 200, low, high), 0.10, 1e-15);
  // AF 3.5: 17 % · (1 − 1/2) = 8.5 % below, 18.5 % above.
  EXPECT_NEAR(required_separation_margin(3.5, 50, low, high), 0.085, 1e-15);
  EXPECT_NEAR(required_separation_margin(3.5, 200, low, high), 0.185, 1e-15);
  // The caps 16 % and 26 % are reached at AF = 18.5 (17·(1 − 1/17) = 16) and hold above.
  EXPECT_NEAR(required_separation_margin(18.5, 50, low, high), 0.16, 1e-15);
  EXPECT_NEAR(required_separation_margin(18.5, 200, low, high), 0.26, 1e-15);
  EXPECT_NEAR(required_separation_margin(18.0, 50, low, high), 0.17 * (1 - 1 / 16.5), 1e-15);
  EXPECT_EQ(required_separation_margin(1e6, 50, low, high), 0.16);
  EXPECT_EQ(required_separation_margin(1e6, 200, low, high), 0.26);
  // Inside the range: the rule of the nearer end.
  EXPECT_NEAR(required_separation_margin(3.5, 104, low, high), 0.085, 1e-15);
  EXPECT_NEAR(required_separation_margin(3.5, 116, low, high), 0.185, 1e-15);
  EXPECT_EQ(required_separation_margin(std::nan(""), 50, low, high), 0.0);
}

}  // namespace
}  // namespace feran

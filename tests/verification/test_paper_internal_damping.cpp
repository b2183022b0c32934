// The paper's internal-damping rotor (Fischer & Strackeljan 2006, sec. 3.2, Fig. 4),
// shipped as examples/01_internal_damping, swept from 0 to 80 Hz in 161 speeds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/io/model_reader.hpp>

#include "campbell_lookup.hpp"

namespace feran::test_paper_internal_damping {
namespace {

struct Sweep {
  CampbellResult with, without;
  CampbellOptions options;
};

const Sweep& sweep() {
  static const Sweep s = [] {
    Sweep out;
    const std::string dir = std::string(FERAN_SOURCE_DIR) + "/examples/01_internal_damping/";
    for (int i = 0; i <= 160; ++i) out.options.speeds.push_back(hz_to_rad(0.5 * i));
    out.options.n_modes = 6;
    out.with = run_campbell(read_model_file(dir + "model.toml").model, out.options);
    out.without = run_campbell(read_model_file(dir + "model_without_internal_damping.toml").model, out.options);
    return out;
  }();
  return s;
}

using test::critical_hz;
using test::mode;

TEST(PaperInternalDamping, FirstCriticalSpeedNearThePapers33_4Hz) {
  // The paper does not give E; with 210 GPa the undamped-like rotor (external damping
  // only) reaches 33.24 Hz. ±1 % covers E between 206 and 214 GPa (f ∝ √E).
  EXPECT_NEAR(critical_hz(sweep().without, "forward 1"), 33.4, 0.01 * 33.4);
  // Internal damping adds 638 N s/m: the damped frequency, and with it the critical
  // speed, drops to 32.5 Hz; still within 3 % of the paper's value.
  EXPECT_NEAR(critical_hz(sweep().with, "forward 1"), 33.4, 0.03 * 33.4);
}

TEST(PaperInternalDamping, InternalDampingDestabilisesAboveTheCriticalSpeed) {
  const Sweep& s = sweep();
  ASSERT_FALSE(s.without.stability_threshold.has_value());
  ASSERT_TRUE(s.with.stability_threshold.has_value());
  const StabilityThreshold& t = *s.with.stability_threshold;
  EXPECT_EQ(whirl_name(s.with, t.mode), "forward 1");
  const Real critical = critical_hz(s.with, "forward 1");
  EXPECT_GT(rad_to_hz(t.speed), critical);
  EXPECT_LT(rad_to_hz(t.speed), 80.0);
  // Regression value (this implementation, 53.58 Hz), 0.1 %: the threshold is a
  // simple root refined to 1e-8 rad/s, so only a change of model or method moves it.
  EXPECT_NEAR(rad_to_hz(t.speed), 53.58, 0.001 * 53.58);
}

// Rotating damping adds c_i(1 − Ω/ω) to the effective damping of a forward whirl at
// frequency ω: it stabilises below the speed where Ω = ω (the critical speed) and
// destabilises above it. The damping-ratio curves with and without internal damping
// therefore cross at the critical speed (exactly for a Jeffcott rotor; here the
// tilt motion shifts it slightly: within 3 %).
TEST(PaperInternalDamping, DampingCurvesCrossAtTheCriticalSpeed) {
  const Sweep& s = sweep();
  const TrackedMode& with = mode(s.with, "forward 1");
  const TrackedMode& without = mode(s.without, "forward 1");
  Real crossing = NAN;
  for (std::size_t i = 1; i < s.options.speeds.size(); ++i) {
    const Real d0 = with.damping_ratio[i - 1] - without.damping_ratio[i - 1];
    const Real d1 = with.damping_ratio[i] - without.damping_ratio[i];
    EXPECT_FALSE(std::isnan(d1));
    if (d0 > 0 && d1 <= 0) {
      crossing = rad_to_hz(s.options.speeds[i - 1] + (s.options.speeds[i] - s.options.speeds[i - 1]) * d0 / (d0 - d1));
      break;
    }
  }
  ASSERT_FALSE(std::isnan(crossing));
  EXPECT_NEAR(crossing, critical_hz(s.with, "forward 1"), 0.03 * crossing);
  EXPECT_GT(with.damping_ratio[0], without.damping_ratio[0]);
  EXPECT_LT(with.damping_ratio.back(), 0.0);
  EXPECT_GT(without.damping_ratio.back(), 0.0);
}

// Fig. 4 right: the damping of forward whirl 1 with and without internal damping at
// rest, at the critical speed and at the end of the diagram, as docs/validation.md
// quotes them. The paper's axis runs from −20 to 40 %: every value must lie inside.
// The values themselves are this implementation's (the paper's curves cannot be read
// numerically): ±0.05 percentage points, the rounding of the quoted values.
//
// How strongly the free whirl grows in the run-up of Fig. 5 (0-80 Hz in 5 s, 16 Hz/s)
// once forward whirl 1 is unstable: the exponent G(f) = ∫ −Re p dt from the threshold
// to f. docs/validation.md quotes G(72.8 Hz) = 8.6 (where the run-up leaves the paper's
// 0.7 mm axis; test_paper_runups.cpp checks the run-up grows at this rate) and
// G(80 Hz) = 16.1, and from them: with the negative damping 30 % weaker the same growth
// would be reached only at 76.6 Hz, and the run-up would stay within 0.7 mm to 80 Hz
// with at most 53 % of it. Trapezoidal integration over the 0.5 Hz grid, with the
// interval containing the threshold integrated from the threshold only: ±1 %.
// (One test, so that the two sweeps are computed once: each test runs in its own process.)
TEST(PaperInternalDamping, DampingAndGrowthOfForwardWhirlOneAsQuoted) {
  const Sweep& s = sweep();
  const TrackedMode& with = mode(s.with, "forward 1");
  const TrackedMode& without = mode(s.without, "forward 1");
  const auto at = [&](const TrackedMode& m, Real hz) { return m.damping_ratio.at(static_cast<std::size_t>(2 * hz)); };
  for (const TrackedMode* m : {&with, &without})
    for (Real d : m->damping_ratio) {
      EXPECT_GT(d, -0.20);
      EXPECT_LT(d, 0.40);
    }
  EXPECT_NEAR(at(with, 0), 0.328, 0.0005);
  EXPECT_NEAR(at(without, 0), 0.093, 0.0005);
  EXPECT_NEAR(at(with, 33), 0.071, 0.0005);
  EXPECT_NEAR(at(without, 33), 0.072, 0.0005);
  EXPECT_NEAR(at(with, 80), -0.074, 0.0005);
  EXPECT_NEAR(at(without, 80), 0.057, 0.0005);

  const Real threshold = rad_to_hz(s.with.stability_threshold->speed);
  const auto rate = [&](std::size_t i) {  // −Re p [1/s]
    const Real d = with.damping_ratio[i], w = hz_to_rad(with.frequency_hz[i]);
    return -d * w / std::sqrt(1 - d * d);
  };
  std::vector<Real> hz{threshold}, growth{0.0};
  for (std::size_t i = 0; i < s.options.speeds.size(); ++i) {
    const Real f = rad_to_hz(s.options.speeds[i]);
    if (f <= threshold) continue;
    const Real previous_rate = hz.size() == 1 ? 0.0 : rate(i - 1);
    growth.push_back(growth.back() + 0.5 * (previous_rate + rate(i)) * (f - hz.back()) / 16.0);
    hz.push_back(f);
  }
  const auto g = [&](Real f) {
    for (std::size_t i = 1; i < hz.size(); ++i)
      if (hz[i] >= f) return growth[i - 1] + (growth[i] - growth[i - 1]) * (f - hz[i - 1]) / (hz[i] - hz[i - 1]);
    return growth.back();
  };
  EXPECT_NEAR(rate(s.options.speeds.size() - 1), 19.4, 0.1);  // growth rate at 80 Hz [1/s], as quoted
  // Forward whirl 2 at 80 Hz, quoted for the explicit Runge-Kutta step limit (0.5 Hz).
  EXPECT_NEAR(mode(s.with, "forward 2").frequency_hz.back(), 135.9, 0.5);
  EXPECT_NEAR(g(72.8), 8.6, 0.01 * 8.6);
  EXPECT_NEAR(g(80.0), 16.1, 0.01 * 16.1);
  Real weaker = NAN;  // where 0.7·G reaches G(72.8)
  for (Real f = 72.8; f <= 80.0; f += 0.01)
    if (0.7 * g(f) >= g(72.8)) {
      weaker = f;
      break;
    }
  EXPECT_NEAR(weaker, 76.6, 0.1);
  EXPECT_NEAR(g(72.8) / g(80.0), 0.53, 0.01);
}

}  // namespace
}  // namespace feran::test_paper_internal_damping

// The paper's internal-damping rotor (Fischer & Strackeljan 2006, sec. 3.2, Fig. 4),
// shipped as examples/01_internal_damping, swept from 0 to 80 Hz in 161 speeds.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/modal/campbell.hpp>
#include <feran/io/model_reader.hpp>

namespace feran {
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

const TrackedMode& mode(const CampbellResult& r, const std::string& label) {
  for (const TrackedMode& m : r.modes)
    if (m.label == label) return m;
  throw std::runtime_error("no mode " + label);
}

Real critical_hz(const CampbellResult& r, const std::string& label) {
  for (const CriticalSpeed& c : r.critical_speeds)
    if (r.modes[static_cast<std::size_t>(c.mode)].label == label && c.order == 1) return rad_to_hz(c.speed);
  return NAN;
}

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
  EXPECT_EQ(s.with.modes[static_cast<std::size_t>(t.mode)].label, "forward 1");
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

}  // namespace
}  // namespace feran

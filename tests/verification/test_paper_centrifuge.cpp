// The paper's lab centrifuge (Fischer & Strackeljan 2006, sec. 3.1, Figs. 1-2) and
// its mounting-stiffness shift during run-ups (sec. 3.3, Figs. 7-10), shipped as
// examples/02_centrifuge. Every choice the paper leaves open (bearing exponent, split
// of the shaft, where the stator mass and the foot springs sit, the switching speed
// of the step) is explained in examples/02_centrifuge/README.md; the tolerances below
// say how far the paper's statements can be matched given those unknowns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/io/model_reader.hpp>

#include "campbell_lookup.hpp"

namespace feran::test_paper_centrifuge {
namespace {

const std::string& example_dir() {
  static const std::string dir = std::string(FERAN_SOURCE_DIR) + "/examples/02_centrifuge/";
  return dir;
}

struct Models {
  Model base, soft, step, arctan;
};

const Models& models() {
  static const Models m = [] {
    Models out;
    out.base = read_model_file(example_dir() + "model.toml").model;
    out.soft = read_model_file(example_dir() + "model_soft_mounting.toml").model;
    out.step = read_model_file(example_dir() + "model_step.toml").model;
    out.arctan = read_model_file(example_dir() + "model_arctan.toml").model;
    return out;
  }();
  return m;
}

std::vector<Real> speeds_hz(Real stop_hz, Real step_hz) {
  std::vector<Real> speeds;
  const int n = static_cast<int>(std::lround(stop_hz / step_hz));
  for (int i = 0; i <= n; ++i) speeds.push_back(hz_to_rad(step_hz * i));
  return speeds;
}

CampbellResult campbell(const Model& model, Real stop_hz) {
  CampbellOptions options;
  options.speeds = speeds_hz(stop_hz, 0.5);
  options.n_modes = 6;
  return run_campbell(model, options);
}

// Campbell diagrams of Fig. 1 (0-200 Hz), Fig. 9 right (0-60 Hz) and Fig. 8 (0-60 Hz).
const CampbellResult& base_campbell() {
  static const CampbellResult r = campbell(models().base, 200.0);
  return r;
}
const CampbellResult& arctan_campbell() {
  static const CampbellResult r = campbell(models().arctan, 60.0);
  return r;
}
const CampbellResult& step_campbell() {
  static const CampbellResult r = campbell(models().step, 60.0);
  return r;
}

using test::critical_hz;
using test::mode;

std::size_t speed_index(const CampbellResult& r, Real hz) {
  for (std::size_t i = 0; i < r.speeds.size(); ++i)
    if (std::abs(rad_to_hz(r.speeds[i]) - hz) < 1e-9) return i;
  throw std::runtime_error("speed not on the grid");
}

// Oscillating lateral modes at one speed, by frequency.
std::vector<Mode> lateral_modes(const Model& model, Real hz) {
  std::vector<Mode> out;
  for (const Mode& m : run_modal(model, hz_to_rad(hz)).modes)
    if (m.type == ModeType::lateral && m.oscillatory && !m.rigid_body) out.push_back(m);
  return out;
}

// The paper's "first backward whirl": the lowest backward-whirling lateral mode.
Real first_backward_hz(const Model& model, Real hz) {
  for (const Mode& m : lateral_modes(model, hz))
    if (m.whirl == Whirl::backward) return m.frequency_hz;
  return std::numeric_limits<Real>::quiet_NaN();
}

// Steady-state unbalance response: the semi-major axis of the rotor's orbit [m].
std::vector<Real> rotor_deflection(const Model& model, const std::vector<Real>& speeds) {
  HarmonicOptions options;
  options.speeds = speeds;
  options.probes = {model.find_node("rotor")};
  const HarmonicResult r = run_harmonic_response(model, options);
  EXPECT_TRUE(r.info.converged());
  std::vector<Real> out;
  for (const Orbit& o : r.probes.at(0).orbit) out.push_back(o.major);
  return out;
}

constexpr Real f_as = 3.98;  // the paper's average switching frequency [Hz]

// Sec. 3.3: f_as = 3.98 Hz "is slight below the first critical frequency in the
// unchanged configuration". The unchanged model's forward whirl 1 meets the 1x line
// at 5.35 Hz, 34 % above f_as. No placement of the given stator mass and foot springs
// at the stator's nodes brings it closer than 5.04 Hz (+27 %): the translational
// mode of the 7.1 kg machine on 9150 N/m bounds it at 5.7 Hz, and the tilt coupling
// of the paper's 180 N m/rad lowers it only so far. So the bound is +40 %, not the
// +25 % that "slightly" would suggest, and the exact value is pinned as a regression
// value (0.5 %: only a change of the model or the element moves it).
TEST(PaperCentrifuge, FirstCriticalSpeedOfTheUnchangedModelLiesAboveTheSwitchingFrequency) {
  const Real critical = critical_hz(base_campbell(), "forward 1");
  EXPECT_GT(critical, f_as);
  EXPECT_LE(critical, 1.40 * f_as);
  EXPECT_NEAR(critical, 5.346, 0.005 * 5.346);
  // The second forward critical speed, quoted in docs/validation.md (regression, 0.5 %).
  EXPECT_NEAR(critical_hz(base_campbell(), "forward 2"), 20.92, 0.005 * 20.92);
}

// The paper's sentence points at Fig. 9 right, the configuration softened by the
// arctan law. There the first critical speed falls to f_as itself: the law already
// takes the mounting to 55 % at f_as. Computed 3.958 Hz; ±5 % covers the placements
// of the stator mass and the foot springs tried (3.76-4.14 Hz; see the README).
TEST(PaperCentrifuge, SwitchingFrequencyMeetsTheFirstCriticalSpeedOfTheArctanModel) {
  EXPECT_NEAR(critical_hz(arctan_campbell(), "forward 1"), f_as, 0.05 * f_as);
  EXPECT_NEAR(critical_hz(arctan_campbell(), "forward 1"), 3.958, 0.005 * 3.958);  // regression value, 0.5 %
}

// Fig. 9 left (unchanged, 0-60 Hz): backward and forward whirl 1 and 2 lie below its
// 30 Hz axis at rest (5.33 and 15.26 Hz; the whole machine on its mounting); the
// next pair (rotor and stator tilting against each other on the thin neck) is far
// above (180 Hz).
TEST(PaperCentrifuge, WhirlsOneAndTwoAreTheOnlyModesBelow30HzAtRest) {
  const std::vector<Mode> modes = lateral_modes(models().base, 0.0);
  ASSERT_GE(modes.size(), 6u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(modes[i].frequency_hz, 30.0) << "mode " << i;
  EXPECT_GT(modes[4].frequency_hz, 100.0);
  // Values quoted in docs/validation.md (regression values, 0.5 %): whirls 1 and 2 at
  // rest, unchanged and with the arctan law (Fig. 9 left and right).
  EXPECT_NEAR(modes[0].frequency_hz, 5.33, 0.005 * 5.33);
  EXPECT_NEAR(modes[2].frequency_hz, 15.26, 0.005 * 15.26);
  const std::vector<Mode> arctan = lateral_modes(models().arctan, 0.0);
  EXPECT_NEAR(arctan.at(0).frequency_hz, 4.32, 0.005 * 4.32);
  EXPECT_NEAR(arctan.at(2).frequency_hz, 12.34, 0.005 * 12.34);
}

// Fig. 1 (0-200 Hz speed, eigenfrequency axis to 350 Hz): three whirl pairs lie in
// that window, the highest, forward whirl 3 (gyroscopically stiffened rotor tilt),
// reaching the top of the axis near the end of the speed range. Computed 368.5 Hz at
// 200 Hz; ±10 %, as the figure gives only its axis, and the unknown split of the
// upper 30 mm of the shaft and the bearing exponent move the value between 367 and
// 382 Hz. The next pair starts at 787 Hz, well out of the figure.
TEST(PaperCentrifuge, ThreeWhirlPairsFillFigureOnesWindow) {
  const CampbellResult& r = base_campbell();
  ASSERT_EQ(r.speeds.size(), 401u);
  EXPECT_NEAR(mode(r, "forward 3").frequency_hz.back(), 350.0, 0.10 * 350.0);
  EXPECT_NEAR(mode(r, "forward 3").frequency_hz.back(), 368.5, 0.005 * 368.5);  // regression value, 0.5 %
  const std::vector<Mode> modes = lateral_modes(models().base, 0.0);
  ASSERT_GE(modes.size(), 8u);
  EXPECT_LT(modes[5].frequency_hz, 350.0);
  EXPECT_GT(modes[6].frequency_hz, 2.0 * 350.0);
  EXPECT_FALSE(r.stability_threshold.has_value());
}

// Sec. 3.3, Figs. 7-8: after the step to 10 % the first backward whirl is excited,
// "with decreasing frequency from 0.98 Hz to 0.68 Hz. This coincides with the
// Campbell diagram (figure 8, left)", whose speed axis ends at 60 Hz. With the
// 10 % mounting the first backward whirl is 0.988 Hz at 40 Hz (the switching speed
// chosen for model_step.toml) and 0.697 Hz at 60 Hz. ±10 %: the frequencies are read
// from a time signal; the model's values differ by 1 % and 2.5 %.
TEST(PaperCentrifuge, SoftMountingFirstBackwardWhirlFallsFrom0_98To0_68Hz) {
  EXPECT_NEAR(first_backward_hz(models().soft, 40.0), 0.98, 0.10 * 0.98);
  EXPECT_NEAR(first_backward_hz(models().soft, 60.0), 0.68, 0.10 * 0.68);
  // As quoted in docs/validation.md (regression values, ±0.001 Hz).
  EXPECT_NEAR(first_backward_hz(models().soft, 40.0), 0.988, 0.001);
  EXPECT_NEAR(first_backward_hz(models().soft, 60.0), 0.697, 0.001);
}

// In this speed range the first backward whirl is the gyroscopic precession of the
// whole machine on its tilt spring, ω ≈ k_r/(J_P·Ω) (k_r = 18 N m/rad, 10 % of k11r;
// J_P = 0.0104 kg m² of the rotor), so it keeps falling as 1/Ω: 0.31 Hz at 140 Hz,
// the end of the run-up of Fig. 7, within 3 % of the estimate. Its fall from 0.98 to
// 0.68 Hz spans a speed ratio of about 1.44, so 0.68 Hz at 140 Hz would need the
// 0.98 Hz near 97 Hz, where the 10 % mounting gives 0.44 Hz: the paper's two
// frequencies belong inside Fig. 8's 0-60 Hz, not at the end of the run-up.
TEST(PaperCentrifuge, SoftMountingFirstBackwardWhirlFollowsTheGyroscopicEstimate) {
  const Real omega = hz_to_rad(140.0);
  const Real estimate_hz = rad_to_hz(18.0 / (0.0104 * omega));
  const Real at_140 = first_backward_hz(models().soft, 140.0);
  EXPECT_NEAR(at_140, estimate_hz, 0.03 * estimate_hz);
  EXPECT_LT(at_140, 0.5 * 0.68);
  EXPECT_LT(first_backward_hz(models().soft, 97.0), 0.5 * 0.98);
}

// Fig. 8 right: after the step "the first backward whirl is the natural frequency in
// this speed range with the lowermost damping". Checked at every speed of the step
// model's diagram from the step (40 Hz) to 60 Hz among whirls 1 and 2 (the modes of
// Fig. 8). Fig. 8 right's damping axis ends at 60 %: with the stiffness at 10 % and
// the damping unchanged, the damping ratios rise by about √10, to 49.7 % at most
// (between 40 and 60 %). Reducing only the tilt stiffness would leave them below
// 20 %; reducing only the translation would make backward whirl 1 the best damped.
TEST(PaperCentrifuge, AfterTheStepBackwardWhirlOneIsTheLeastDampedMode) {
  const CampbellResult& r = step_campbell();
  const std::vector<std::string> labels{"backward 1", "forward 1", "backward 2", "forward 2"};
  Real largest = 0.0;
  for (std::size_t i = 0; i < r.speeds.size(); ++i) {
    for (const std::string& label : labels) largest = std::max(largest, mode(r, label).damping_ratio[i]);
    if (rad_to_hz(r.speeds[i]) < 40.0 - 1e-9) continue;
    const Real bw1 = mode(r, "backward 1").damping_ratio[i];
    for (const std::string& label : labels) {
      if (label == "backward 1") continue;
      EXPECT_LT(bw1, mode(r, label).damping_ratio[i]) << label << " at " << rad_to_hz(r.speeds[i]) << " Hz";
    }
  }
  EXPECT_GT(largest, 0.40);
  EXPECT_LT(largest, 0.60);
  EXPECT_NEAR(largest, 0.498, 0.001);  // as quoted in docs/validation.md (regression value)
}

// The step model is the unchanged model below 40 Hz and the soft one from 40 Hz on.
// Same matrices, so the frequencies agree to round-off: 1e-9 relative is observed
// (the state matrix spans 1 Hz to 5e5 Hz); 1e-7 leaves room for other LAPACKs.
TEST(PaperCentrifuge, StepModelSwitchesAt40Hz) {
  const auto frequencies = [](const Model& model, Real hz) {
    std::vector<Real> f;
    for (const Mode& m : lateral_modes(model, hz)) f.push_back(m.frequency_hz);
    f.resize(4);
    return f;
  };
  const std::vector<Real> below = frequencies(models().step, 39.99);
  const std::vector<Real> above = frequencies(models().step, 40.0);
  const std::vector<Real> base = frequencies(models().base, 39.99);
  const std::vector<Real> soft = frequencies(models().soft, 40.0);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(below[i], base[i], 1e-7 * base[i]);
    EXPECT_NEAR(above[i], soft[i], 1e-7 * soft[i]);
  }
  const std::size_t at = speed_index(step_campbell(), 40.0);
  EXPECT_NEAR(mode(step_campbell(), "backward 1").frequency_hz[at], first_backward_hz(models().soft, 40.0), 1e-7);
}

// Sec. 3.3: "The steady state deflection of the rotor ... reduces about 15 % due to
// the change of the stiffness parameters" (the step, Fig. 7). At the switching speed
// the rotor's steady-state deflection drops from 0.090 to 0.077 mm, by 14.4 %;
// ±5 points for "about". (The drop shrinks with speed, to 6 % at 60 Hz and 1 % at
// 140 Hz, and grows below 40 Hz: 29 % at 30 Hz. That the paper's 15 % comes out at
// the speed chosen from the backward-whirl frequencies supports the choice.)
TEST(PaperCentrifuge, StepReducesTheSteadyStateDeflectionByAbout15Percent) {
  const std::vector<Real> at{hz_to_rad(40.0)};
  const Real before = rotor_deflection(models().base, at).at(0);
  const Real after = rotor_deflection(models().soft, at).at(0);
  EXPECT_NEAR(1.0 - after / before, 0.15, 0.05);
  // As quoted in docs/validation.md (regression values, the rounding of the quote).
  EXPECT_NEAR(before, 0.090e-3, 0.0005e-3);
  EXPECT_NEAR(after, 0.077e-3, 0.0005e-3);
  EXPECT_NEAR(1.0 - after / before, 0.144, 0.0005);
}

// Sec. 3.3, Fig. 10: with the arctan law "a reduction of the maximum rotor deflection
// up to about 30 % was achieved" against the unchanged stiffness, in a run-up to
// 100 Hz. The steady-state maxima over 0.5-100 Hz: 0.222 mm (unchanged, at the
// forward whirl 2 resonance near 21.5 Hz) and 0.154 mm (arctan), 30.5 % lower.
// The paper's figure comes from a time integration of a 5 s run-up, whose peaks lag
// and differ from the steady state: ±10 points.
TEST(PaperCentrifuge, ArctanLawReducesTheMaximumDeflectionByAbout30Percent) {
  const std::vector<Real> speeds = [] {
    std::vector<Real> s;
    for (int i = 5; i <= 1000; ++i) s.push_back(hz_to_rad(0.1 * i));
    return s;
  }();
  const std::vector<Real> base = rotor_deflection(models().base, speeds);
  const std::vector<Real> arctan = rotor_deflection(models().arctan, speeds);
  const Real base_max = *std::max_element(base.begin(), base.end());
  const Real arctan_max = *std::max_element(arctan.begin(), arctan.end());
  EXPECT_NEAR(1.0 - arctan_max / base_max, 0.30, 0.10);
  // As quoted in docs/validation.md (regression values, the rounding of the quote).
  // The 10 % mounting's peak is checked with the run-ups (test_paper_runups.cpp).
  EXPECT_NEAR(base_max, 0.222e-3, 0.0005e-3);
  EXPECT_NEAR(arctan_max, 0.154e-3, 0.0005e-3);
  EXPECT_NEAR(1.0 - arctan_max / base_max, 0.305, 0.0005);
  // Fig. 10's deflection axis ends at 0.25 mm.
  EXPECT_LT(base_max, 0.25e-3);
  EXPECT_GT(base_max, 0.15e-3);
}

}  // namespace
}  // namespace feran::test_paper_centrifuge

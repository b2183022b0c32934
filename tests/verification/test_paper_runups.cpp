// The paper's run-ups (Fischer & Strackeljan 2006, Figs. 5, 6, 7 and 10), each run
// as its example's [runup] table states, against the paper's statements and against
// independent values: the steady-state (harmonic) response, the eigenvalues, and the
// closed-form radius of a friction-driven whirl. The numbers are those quoted in
// docs/validation.md; scripts/figures.sh draws the same run-ups.
//
// Whole run-ups take seconds: this executable carries the ctest label long_runup
// (tests/CMakeLists.txt), which the sanitizer pass skips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/io/model_reader.hpp>

namespace feran::test_paper_runups {
namespace {

std::string example(const std::string& name) { return std::string(FERAN_SOURCE_DIR) + "/examples/" + name; }

struct RunUp {
  Model model;
  TransientResult result;
};

// The run-up of the model file's [runup] table (profile, integrator, step, probes),
// sampled every 1 ms; `duration` > 0 cuts it short.
RunUp runup(const std::string& path, Real duration = 0) {
  const ModelFile file = read_model_file(example(path));
  RunupSpec request;
  if (duration > 0) request.duration = duration;
  request.output_interval = 1e-3;
  request.probes = {NodeRef{std::string("rotor")}};
  const TransientOptions t = runup_options(file, request);
  return {file.model, run_transient(file.model, t)};
}

struct Band {
  Real max = 0, min = 1e300;
};

// Largest and smallest |r| of the rotor between two speeds [Hz].
Band band(const TransientResult& r, Real from_hz, Real to_hz) {
  Band b;
  for (const TransientSample& s : r.samples) {
    const Real hz = rad_to_hz(s.speed);
    if (hz < from_hz || hz > to_hz) continue;
    b.max = std::max(b.max, s.magnitude[0]);
    b.min = std::min(b.min, s.magnitude[0]);
  }
  return b;
}

// Speed [Hz] at which |r| first exceeds a limit, NaN if never.
Real first_above(const TransientResult& r, Real limit) {
  for (const TransientSample& s : r.samples)
    if (s.magnitude[0] > limit) return rad_to_hz(s.speed);
  return NAN;
}

// Steady-state orbit radius of the rotor on a 0.1 Hz grid from `from_hz` to `to_hz`.
struct Steady {
  std::vector<Real> hz, radius;
  Real at(Real f) const {
    const auto i = static_cast<std::size_t>(std::lround((f - hz.front()) / 0.1));
    return radius.at(i);
  }
};

Steady steady_state(const Model& model, Real from_hz, Real to_hz) {
  HarmonicOptions h;
  Steady s;
  for (Real f = from_hz; f <= to_hz + 1e-9; f += 0.1) {
    s.hz.push_back(f);
    h.speeds.push_back(hz_to_rad(f));
  }
  h.probes = {model.find_node("rotor")};
  const HarmonicResult r = run_harmonic_response(model, h);
  for (const Orbit& o : r.probes.at(0).orbit) s.radius.push_back(o.major);
  return s;
}

// Forward whirl 1: the lowest forward-whirling lateral mode at a speed.
Mode forward_1(const Model& model, Real hz) {
  for (const Mode& m : run_modal(model, hz_to_rad(hz)).modes)
    if (m.type == ModeType::lateral && m.oscillatory && m.whirl == Whirl::forward) return m;
  throw std::runtime_error("no forward whirl");
}

// Fig. 5 without internal damping. A run-up at 16 Hz/s passes the resonance
// (half-power width 2·D·f = 4.7 Hz at D = 7 %) in about ten whirl periods: nearly
// quasi-static, so the peak is close to the steady-state peak and comes a little later.
TEST(PaperRunups, Fig5WithoutInternalDampingFollowsTheSteadyState) {
  const RunUp run = runup("01_internal_damping/model_without_internal_damping.toml");
  ASSERT_TRUE(run.result.info.converged()) << run.result.info.message;
  const Steady steady = steady_state(run.model, 0.0, 80.0);
  const auto top = std::max_element(steady.radius.begin(), steady.radius.end());
  const Real steady_peak = *top;
  const Real steady_peak_hz = steady.hz[static_cast<std::size_t>(top - steady.radius.begin())];
  // Steady-state peak 0.561 mm at 33.9 Hz (0.1 Hz grid), inside the paper's 0.7 mm
  // axis, at the critical speed of test_paper_internal_damping (33.24 Hz) within the
  // half-power width. Regression values: 0.2 % and one grid step.
  EXPECT_NEAR(steady_peak, 0.561e-3, 0.002 * 0.561e-3);
  EXPECT_NEAR(steady_peak_hz, 33.9, 0.1 + 1e-9);
  const Envelope& e = run.result.envelopes.at(0);
  // Run-up peak 0.568 mm at 35.8 Hz: within 3 % of the steady-state peak and 1-3 Hz
  // later (the quasi-static estimate above), and pinned as regression values (0.5 %,
  // 0.2 Hz: the time step's phase error moves them far less).
  EXPECT_NEAR(e.peak, steady_peak, 0.03 * steady_peak);
  EXPECT_GT(rad_to_hz(e.peak_speed) - steady_peak_hz, 1.0);
  EXPECT_LT(rad_to_hz(e.peak_speed) - steady_peak_hz, 3.0);
  EXPECT_NEAR(e.peak, 0.568e-3, 0.005 * 0.568e-3);
  EXPECT_NEAR(rad_to_hz(e.peak_speed), 35.8, 0.2);
  // From 70 Hz on, the free whirl left from the passage has decayed (forward whirl 1
  // keeps ~6 % damping, e-folding in 0.07 s): the run-up lies on the steady state
  // within 5 %.
  for (const TransientSample& s : run.result.samples) {
    const Real hz = rad_to_hz(s.speed);
    if (hz >= 70.0 && hz <= 80.0) {
      ASSERT_NEAR(s.magnitude[0], steady.at(hz), 0.05 * steady.at(hz)) << hz << " Hz";
    }
  }
}

// Fig. 5 with internal damping. Above the stability threshold (53.58 Hz) the free
// whirl grows at the rate −Re p of forward whirl 1: where it dominates the synchronous
// orbit (above 74 Hz, |r| > 5 mm against 0.12 mm), the envelope's growth between two
// speeds equals ∫ −Re p dt = ∫ −Re p df / (16 Hz/s). Tolerance 3 % of the exponent: the
// envelope is a maximum over 1 Hz bins (a fraction of a whirl period of bias) and the
// synchronous part adds at most 2 %.
TEST(PaperRunups, Fig5WithInternalDampingGrowsAtTheEigenvalueRateUntilItBlowsUp) {
  const RunUp run = runup("01_internal_damping/model.toml");
  const TransientResult& r = run.result;
  // The run is stopped at the blow-up limit (1 m / 1 rad): results kept, not converged.
  ASSERT_FALSE(r.info.converged());
  EXPECT_NE(r.info.message.find("blew up"), std::string::npos) << r.info.message;
  const Real stop_hz = rad_to_hz(r.samples.back().speed);
  // Regression values of this model and step (see docs/validation.md on why the
  // paper's curve can differ by several Hz): stop at 77.0 Hz, |r| above the paper's
  // 0.7 mm axis from 72.8 Hz on; ±0.3 Hz.
  EXPECT_NEAR(stop_hz, 77.0, 0.3);
  EXPECT_NEAR(first_above(r, 0.7e-3), 72.8, 0.3);

  constexpr Real rate_hz_per_s = 16.0, a = 74.0, b = 76.5;
  Real exponent = 0;  // ∫ −Re p dt from a to b, trapezoidal rule over 0.25 Hz steps
  for (Real f = a; f < b - 1e-9; f += 0.25)
    exponent += 0.5 * 0.25 *
                (forward_1(run.model, f).eigenvalue.real() + forward_1(run.model, f + 0.25).eigenvalue.real()) /
                rate_hz_per_s;
  const Envelope& e = r.envelopes.at(0);
  const auto bin = [&](Real hz) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < e.speed.size(); ++i)
      if (std::abs(rad_to_hz(e.speed[i]) - hz) < std::abs(rad_to_hz(e.speed[best]) - hz)) best = i;
    return e.magnitude[best];
  };
  const Real measured = std::log(bin(b) / bin(a));
  EXPECT_GT(exponent, 0.0);
  EXPECT_NEAR(measured, exponent, 0.03 * exponent);

  // Below, the run-up follows the steady state, as it does without internal damping:
  // from 50 to 65 Hz within 10 % (the decaying beat of the critical-speed passage).
  const Steady steady = steady_state(run.model, 50.0, 65.0);
  for (const TransientSample& s : r.samples) {
    const Real hz = rad_to_hz(s.speed);
    if (hz >= 50.0 && hz <= 65.0) {
      ASSERT_NEAR(s.magnitude[0], steady.at(hz), 0.10 * steady.at(hz)) << hz << " Hz";
    }
  }
}

// Fig. 6: "after passing the first critical speed ... the rotor oscillates with the
// frequency of the first forward whirl due to Coulomb damping added by a vibration with
// the frequency of revolution ... the effects of Coulomb damping occur immediately
// after passing the critical speed. The magnitude of rotor displacement does not
// increase with increasing speed of revolution." In a speed band, |r| of a whirl of
// radius R_w plus the synchronous orbit R_s swings between |R_w − R_s| and R_w + R_s;
// R_s is the steady state, so R_w is the half-sum or half-difference of the band's
// extremes, whichever is not R_s. The closed form R_w = F_ct0/(c_at·ω_f) (friction and
// external damping in balance, test_runup.cpp checks it on a Jeffcott rotor to 1 %)
// holds within 5 %: the rotor also tilts, so c_ar and the mode shape take a little.
TEST(PaperRunups, Fig6CoulombFrictionWhirlSetsInAfterTheCriticalSpeedAndDoesNotGrow) {
  struct Case {
    std::string file;
    Real force, peak_mm, peak_hz;
  };
  // Peaks: regression values, 0.5 % and 0.3 Hz.
  const std::vector<Case> cases{{"model_5_2N.toml", 5.2, 0.646, 36.0},
                                {"model_20_8N.toml", 20.8, 0.867, 36.8},
                                {"model_41_6N.toml", 41.6, 1.075, 38.8}};
  constexpr Real c_at = 250.0;
  for (const Case& c : cases) {
    const RunUp run = runup("03_coulomb_friction/" + c.file);
    ASSERT_TRUE(run.result.info.converged()) << c.file << ": " << run.result.info.message;
    const Steady steady = steady_state(run.model, 40.0, 80.0);
    const auto whirl = [&](Real from, Real to) {
      const Band b = band(run.result, from, to);
      const Real rs = steady.at(0.5 * (from + to));
      const Real sum = 0.5 * (b.max + b.min), diff = 0.5 * (b.max - b.min);
      return std::abs(sum - rs) < std::abs(diff - rs) ? diff : sum;
    };
    const Real closed_form = c.force / (c_at * forward_1(run.model, 77.5).eigenvalue.imag());
    EXPECT_NEAR(whirl(75.0, 80.0), closed_form, 0.05 * closed_form) << c.file;
    // Immediately after the critical speed (42-47 Hz) the whirl is already there, at
    // least 90 % of its size at the end; and it does not grow (2 %: band sampling).
    EXPECT_GT(whirl(42.0, 47.0), 0.90 * whirl(75.0, 80.0)) << c.file;
    EXPECT_LT(whirl(75.0, 80.0), 1.02 * whirl(45.0, 50.0)) << c.file;
    EXPECT_LT(band(run.result, 75.0, 80.0).max, band(run.result, 45.0, 50.0).max) << c.file;
    EXPECT_LT(band(run.result, 75.0, 80.0).max, 1.2e-3) << c.file;  // within the paper's axis
    EXPECT_NEAR(run.result.envelopes[0].peak, c.peak_mm * 1e-3, 0.005 * c.peak_mm * 1e-3) << c.file;
    EXPECT_NEAR(rad_to_hz(run.result.envelopes[0].peak_speed), c.peak_hz, 0.3) << c.file;
  }
}

// Frequency of the dominant slow whirl in r = v + iw of probe 0 around each sample:
// three centred 100-sample (100 ms) box filters remove the synchronous motion
// (≥ 40 Hz: attenuated below 1e-3), the unwrapped phase of the rest is fitted by a line
// over ±100 samples. Positive for a backward whirl. NaN near the ends.
std::vector<Real> backward_whirl_hz(const TransientResult& r) {
  using C = std::complex<Real>;
  const std::size_t n = r.samples.size(), box = 100, half = 100;
  std::vector<C> z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = C(r.samples[i].probes[0][1], r.samples[i].probes[0][2]);
  std::size_t first = 0, last = n;  // z is valid in [first, last)
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<C> sum(n + 1, C(0));
    for (std::size_t i = first; i < last; ++i) sum[i + 1] = sum[i] + z[i];
    std::vector<C> out(n, C(0));
    for (std::size_t i = first + box / 2; i + box / 2 <= last; ++i)
      out[i] = (sum[i + box / 2] - sum[i - box / 2]) / Real(box);
    z = out;
    first += box / 2;
    last -= box / 2;
  }
  std::vector<Real> phase(n, NAN);
  phase[first] = std::arg(z[first]);
  for (std::size_t i = first + 1; i < last; ++i) phase[i] = phase[i - 1] + std::arg(z[i] / z[i - 1]);
  std::vector<Real> hz(n, NAN);
  for (std::size_t i = first + half; i + half < last; ++i) {
    Real st = 0, sp = 0, stt = 0, stp = 0;
    for (std::size_t j = i - half; j <= i + half; ++j) {
      const Real t = r.samples[j].t;
      st += t;
      sp += phase[j];
      stt += t * t;
      stp += t * phase[j];
    }
    const Real m = 2 * half + 1;
    hz[i] = -(m * stp - st * sp) / (m * stt - st * st) / (2 * pi);
  }
  return hz;
}

// Fig. 7: after the step to 10 % at 40 Hz, "an excitation of the first backward whirl
// can be clearly observed ... with decreasing frequency from 0.98 Hz to 0.68 Hz. This
// coincides with the Campbell diagram (figure 8, left)." The frequency is read from the
// run-up's own time signal and compared with the eigenvalues of the 10 % mounting. The
// run is cut at 6.6 s (66 Hz) to keep the test short.
TEST(PaperRunups, Fig7StepExcitesTheFirstBackwardWhirlFalling0_98To0_68Hz) {
  const RunUp run = runup("02_centrifuge/model_step.toml", 6.6);
  ASSERT_TRUE(run.result.info.converged()) << run.result.info.message;
  const Model soft = read_model_file(example("02_centrifuge/model_soft_mounting.toml")).model;
  const std::vector<Real> hz = backward_whirl_hz(run.result);
  const auto at = [&](Real speed_hz) {  // samples every 1 ms at 10 Hz/s: 0.01 Hz apart
    for (std::size_t i = 0; i < hz.size(); ++i)
      if (rad_to_hz(run.result.samples[i].speed) >= speed_hz) return hz[i];
    return Real(NAN);
  };
  const auto campbell_bw1 = [&](Real speed_hz) {
    for (const Mode& m : run_modal(soft, hz_to_rad(speed_hz)).modes)
      if (m.type == ModeType::lateral && m.oscillatory && m.whirl == Whirl::backward) return m.frequency_hz;
    return Real(NAN);
  };
  // Half a second after the step the faster whirls (1.6 Hz, 44-50 % damping) have
  // died out: from 48 Hz on the signal's whirl is backward whirl 1 within 1.5 % (filter
  // and fit window bias).
  for (Real f : {48.0, 50.0, 55.0, 60.0, 63.0})
    EXPECT_NEAR(at(f), campbell_bw1(f), 0.015 * campbell_bw1(f)) << f << " Hz";
  // Right after the step: 1.00 Hz at 43.5 Hz (the paper: 0.98 Hz), ±5 % as the
  // paper's value is read from a time signal and the mixture of whirls is still there.
  EXPECT_NEAR(at(43.5), 0.98, 0.05 * 0.98);
  // Falls to the paper's 0.68 Hz at 62.0 Hz (±1 Hz: the curve falls 0.013 Hz per Hz,
  // 1.5 % of frequency is ~1 Hz of speed).
  Real reach = NAN;
  for (std::size_t i = 0; i < hz.size(); ++i)
    if (rad_to_hz(run.result.samples[i].speed) > 45.0 && hz[i] <= 0.68) {
      reach = rad_to_hz(run.result.samples[i].speed);
      break;
    }
  EXPECT_NEAR(reach, 62.0, 1.0);
  // "An overshoot occurs": after the step |v| reaches 0.101 mm, 1.3 times the new
  // steady-state amplitude of v (0.077 mm), and well above it (> 1.15).
  Real largest = 0;
  for (const TransientSample& s : run.result.samples)
    if (rad_to_hz(s.speed) > 40.0 && rad_to_hz(s.speed) < 45.0) largest = std::max(largest, std::abs(s.probes[0][1]));
  HarmonicOptions h;
  h.speeds = {hz_to_rad(42.5)};
  h.probes = {soft.find_node("rotor")};
  const Real steady_v = std::abs(run_harmonic_response(soft, h).probes.at(0).q.at(0)[1]);
  EXPECT_GT(largest, 1.15 * steady_v);
  EXPECT_NEAR(largest, 0.101e-3, 0.01 * 0.101e-3);  // regression value, 1 %
  // The largest |r| of the whole run-up comes before the step, passing forward whirl 2
  // (critical speed 20.9 Hz): 0.227 mm at 23.3 Hz, inside Fig. 7's 0.25 mm axis.
  // Regression values, 0.5 % and 0.3 Hz.
  const Envelope& e = run.result.envelopes.at(0);
  EXPECT_LT(e.peak, 0.25e-3);
  EXPECT_NEAR(e.peak, 0.227e-3, 0.005 * 0.227e-3);
  EXPECT_NEAR(rad_to_hz(e.peak_speed), 23.3, 0.3);
}

// Fig. 10 / sec. 3.3: with the arctan law "a reduction of the maximum rotor deflection
// up to about 30 % was achieved in the calculations compared to a simulation with an
// unchanged bearing stiffness of 100 %" — run-ups of 0-100 Hz in 5 s. Peaks 0.223 mm
// (unchanged, 24.7 Hz) and 0.164 mm (arctan, 15.1 Hz): 26.6 % lower. ±5 points around
// the paper's 30 % for "up to about"; both peaks inside Fig. 10's 0.25 mm axis.
TEST(PaperRunups, Fig10ArctanLawLowersTheRunUpPeakByAbout30Percent) {
  const RunUp constant = runup("02_centrifuge/model.toml");
  const RunUp arctan = runup("02_centrifuge/model_arctan.toml");
  ASSERT_TRUE(constant.result.info.converged()) << constant.result.info.message;
  ASSERT_TRUE(arctan.result.info.converged()) << arctan.result.info.message;
  const Envelope& c = constant.result.envelopes.at(0);
  const Envelope& a = arctan.result.envelopes.at(0);
  EXPECT_NEAR(1.0 - a.peak / c.peak, 0.30, 0.05);
  EXPECT_LT(c.peak, 0.25e-3);
  // Regression values: 0.5 % and 0.3 Hz.
  EXPECT_NEAR(c.peak, 0.223e-3, 0.005 * 0.223e-3);
  EXPECT_NEAR(a.peak, 0.164e-3, 0.005 * 0.164e-3);
  EXPECT_NEAR(rad_to_hz(c.peak_speed), 24.7, 0.3);
  EXPECT_NEAR(rad_to_hz(a.peak_speed), 15.1, 0.3);
  // Fig. 10's dotted reference, the steady state with the mounting at 10 %: peak
  // 0.116 mm (regression value, the rounding of the quote). Here rather than in
  // test_paper_centrifuge.cpp, to keep that one short under the sanitizers.
  const Model soft = read_model_file(example("02_centrifuge/model_soft_mounting.toml")).model;
  const Steady steady = steady_state(soft, 0.5, 100.0);
  EXPECT_NEAR(*std::max_element(steady.radius.begin(), steady.radius.end()), 0.116e-3, 0.0005e-3);
}

// The centrifuge driven by a DC motor instead of the prescribed ramp
// (model_motor.toml): T = T_s(1 − Ω/Ω₀) − c_v Ω accelerates the polar inertia J of
// everything that turns, so the speed follows Ω_eq(1 − e^{−bt/J}) with b = T_s/Ω₀ + c_v
// and Ω_eq = T_s/b, as long as the unbalance's drag is small. J is summed here from
// the model's parts by hand: the rotor's J_P, the motor's own inertia, the unbalance
// m e² and the shaft's ρ(π/32)d⁴L over its three sections. The roller bearings are
// springs (no friction torque); the unbalance whirls 0.1-0.2 mm on damped foot
// springs, and the torque it takes, m e r Ω² sin(phase) ≈ 1e-4 N m at most against
// the motor's 4 N m, bounds the deviation: 1e-4 of Ω_eq (observed 1.4e-5).
TEST(PaperRunups, CentrifugeOnADcMotorFollowsTheMotorsExponentialRise) {
  const RunUp r = runup("02_centrifuge/model_motor.toml", 2.0);
  const Real pi = std::acos(-1.0);
  const Real shaft =
      7850.0 * pi / 32.0 * (std::pow(0.017, 4) * 0.068 + std::pow(0.01105, 4) * 0.025 + std::pow(0.0187, 4) * 0.005);
  const Real J = 0.0104 + 5e-4 + 0.003 * 0.08 * 0.08 + shaft;
  const Real stall = 4.0, no_load = hz_to_rad(105.0), viscous = 2e-4;
  const Real b = stall / no_load + viscous;
  const Real top = stall / b;
  Real worst = 0;
  for (const TransientSample& s : r.result.samples)
    worst = std::max(worst, std::abs(s.speed - top * (1 - std::exp(-b * s.t / J))) / top);
  EXPECT_LT(worst, 1e-4);
  // The run passes the forward-whirl resonance near 21.5 Hz on its way (Fig. 10).
  EXPECT_GT(rad_to_hz(r.result.samples.back().speed), 60.0);
  EXPECT_GT(band(r.result, 15, 30).max, 0.15e-3);
}

}  // namespace
}  // namespace feran::test_paper_runups

// Example 06's steady states (`feran orbits`) against its linearised model and against
// run-ups of the nonlinear films at constant speed. The numbers are quoted in
// examples/06_oil_whip/README.md ("Periodic orbits").
// - With its unbalance the forced orbit loses stability at a Neimark–Sacker point
//   within 1 % of the Campbell diagram's threshold (measured 88.27 Hz against 88.00
//   Hz), the motion growing there at the threshold's whirl frequency (5 %: measured
//   43.8 Hz against 44.6 Hz). Further up, the orbit already unstable, the pair of
//   multipliers meets at −1: period doublings, the growing motion locked onto half
//   the speed between them (88.51 to 90.24 Hz).
// - Without it the equilibrium's Hopf point is the Campbell threshold (1e-4: the
//   threshold's own bisection); the whip branch leaving it is subcritical and turns at
//   a fold 0.3 % below it (measured 87.708 Hz at H = 6) into stable whip orbits.
// - Between the fold and the Hopf point (87.85 Hz) both the equilibrium and the whip
//   orbit are stable: a run-up started at 95 % of the whip orbit returns to it (1 %:
//   measured 0.3 % after 2 s, H = 6 and the trapezoidal rule's 50 µs), one started at
//   the equilibrium disturbed by 1 µm stays there (below 1 µm). Below the fold (87.55
//   Hz) the whip orbit of the fold dies out (measured to 48 % of its size in 3 s).
//   Hence the run-down's hysteresis: a rotor that whips keeps whipping down to the
//   fold, below the speed where the run-up's equilibrium lost its stability.
// The orbit's size is half the journal's peak-to-peak displacement (in y or z, the
// larger), sampled every 0.1 ms (≈ 230 samples per whirl period).
//
// Run-ups of seconds of the 53-DOF rotor: label long_runup.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/periodic/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>

namespace feran::test_example_oil_whip_orbits {
namespace {

const std::string path = std::string(FERAN_SOURCE_DIR) + "/examples/06_oil_whip/model.toml";

std::string model_text() {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The example without its unbalance (the whirl alone: a periodic orbit).
std::shared_ptr<const ModelFile> without_unbalance() {
  const std::string text =
      std::regex_replace(model_text(), std::regex(R"(\[\[unbalances\]\]\n([^\[\n][^\n]*\n)*)"), "");
  return std::make_shared<const ModelFile>(read_model_string(text, "model_without_unbalance.toml"));
}

Real threshold() {
  const ModelFile file = read_model_file(path);
  const CampbellResult c =
      run_campbell(file.model, analysis_options<CampbellAnalysis>(file, {}, file_key_name<CampbellAnalysis>()));
  return c.stability_threshold.value().speed;
}

Real half_range(const std::vector<Real>& y, const std::vector<Real>& z) {
  const auto [ylo, yhi] = std::minmax_element(y.begin(), y.end());
  const auto [zlo, zhi] = std::minmax_element(z.begin(), z.end());
  return 0.5 * std::max(*yhi - *ylo, *zhi - *zlo);
}

TEST(ExampleOilWhipOrbits, TheForcedOrbitLosesStabilityAtTheThresholdIntoTheWhirl) {
  const auto file = std::make_shared<const ModelFile>(read_model_file(path));
  OrbitsSpec request;
  request.from = hz_to_rad(85.0);
  request.to = hz_to_rad(92.0);
  request.branch = "forced";
  request.harmonics = 4;
  const Outcome<OrbitsAnalysis> o = run_analysis<OrbitsAnalysis>(file, request, file_key_name<OrbitsAnalysis>());
  ASSERT_EQ(o.result.branch, "forced");
  const OrbitBranch& b = o.result.branches.at(0).branch;
  ASSERT_GE(b.bifurcations.size(), 1U) << b.ended_by;
  const Bifurcation& ns = b.bifurcations[0];
  EXPECT_EQ(ns.kind, Bifurcation::Kind::neimark_sacker);
  // Past it, on the unstable branch, the pair meets at −1 and splits: the new motion
  // locks onto half the speed between two period doublings (measured 88.51 and
  // 90.24 Hz), then parts again.
  for (std::size_t i = 1; i < b.bifurcations.size(); ++i) {
    EXPECT_EQ(b.bifurcations[i].kind, Bifurcation::Kind::period_doubling) << i;
    EXPECT_FALSE(b.orbits[b.bifurcations[i].after].stable) << i;
  }
  const Real onset = threshold();
  std::printf("Neimark–Sacker at %.4f Hz, new motion at %.3f Hz; threshold %.4f Hz\n", rad_to_hz(ns.at.speed),
              rad_to_hz(critical_frequency(ns)), rad_to_hz(onset));
  EXPECT_NEAR(ns.at.speed, onset, 0.01 * onset);
  EXPECT_NEAR(critical_frequency(ns), 0.507 * onset, 0.05 * 0.507 * onset);  // the threshold's whirl, 44.6 Hz
}

struct Whip {
  std::shared_ptr<const ModelFile> file = without_unbalance();
  Outcome<OrbitsAnalysis> outcome;
  std::unique_ptr<CondensedRotor> rotor;
  OrbitSettings settings;
  Index journal = -1;

  Whip() {
    OrbitsSpec request;
    request.from = hz_to_rad(87.0);
    request.to = hz_to_rad(89.0);
    request.harmonics = 6;
    request.branch = "whirl";
    request.probes = {NodeRef{std::string("journal A")}};
    outcome = run_analysis<OrbitsAnalysis>(file, request, file_key_name<OrbitsAnalysis>());
    const OrbitsOptions& o = outcome.options;
    rotor = std::make_unique<CondensedRotor>(file->model, nullptr,
                                             CondensationOptions{.modes = o.modes,
                                                                 .gravity = o.gravity,
                                                                 .static_loads = o.static_loads,
                                                                 .unbalance = false,
                                                                 .reference_speed = 0.5 * (o.from + o.to)});
    settings.fourier = o.fourier;
    settings.continuation.p_min = o.from;
    settings.continuation.p_max = o.to;
    journal = o.probes.at(0);
  }
  const OrbitBranch& equilibrium() const { return outcome.result.branches.at(0).branch; }
  const OrbitBranch& whirl() const { return outcome.result.branches.at(1).branch; }

  Real size(const SteadyState& s) const {
    std::vector<Real> y, z;
    Vector x, v;
    for (int j = 0; j < 720; ++j) {
      orbit_state(*rotor, s, whirl().fourier, 2 * pi * j / 720.0, x, v);
      y.push_back(x(global_dof(journal, Dof::v)));
      z.push_back(x(global_dof(journal, Dof::w)));
    }
    return half_range(y, z);
  }

  // A run at constant @p speed from (x0, v0): the journal's size over [to − 0.2 s, to].
  Real run(Real speed, const Vector& x0, const Vector& v0, Real to) const {
    TransientOptions t;
    t.profile = SpeedProfile::constant(speed);
    t.duration = to;
    t.integrator = "trapezoidal";
    t.settings.dt = 5e-5;  // the example's run-up step
    t.output_interval = 1e-4;
    t.probes = {journal};
    t.gravity = outcome.options.gravity;
    t.initial_displacement = x0;
    t.initial_velocity = v0;
    const TransientResult r = run_transient(file->model, t);
    EXPECT_TRUE(r.info.converged()) << r.info.message;
    std::vector<Real> y, z;
    for (const TransientSample& s : r.samples)
      if (s.t >= to - 0.2) {
        y.push_back(s.probes[0][1]);
        z.push_back(s.probes[0][2]);
      }
    return half_range(y, z);
  }
};

const Whip& whip() {
  static const Whip w;
  return w;
}

TEST(ExampleOilWhipOrbits, TheHopfPointIsTheThresholdAndTheWhipTurnsBelowIt) {
  const Whip& w = whip();
  ASSERT_EQ(w.equilibrium().bifurcations.size(), 1U);
  const Real hopf = w.equilibrium().bifurcations[0].at.speed, onset = threshold();
  EXPECT_NEAR(hopf, onset, 1e-4 * onset);
  EXPECT_EQ(w.whirl().criticality, "subcritical");
  ASSERT_EQ(w.whirl().bifurcations.size(), 1U);
  const Bifurcation& fold = w.whirl().bifurcations[0];
  EXPECT_EQ(fold.kind, Bifurcation::Kind::fold);
  std::printf("Hopf %.4f Hz (threshold %.4f Hz), fold %.4f Hz\n", rad_to_hz(hopf), rad_to_hz(onset),
              rad_to_hz(fold.at.speed));
  EXPECT_LT(fold.at.speed, hopf);
  EXPECT_GT(fold.at.speed, 0.99 * hopf);
}

TEST(ExampleOilWhipOrbits, BetweenFoldAndHopfTheWhipAndTheEquilibriumAreBothStableAndBelowTheFoldTheWhipDies) {
  const Whip& w = whip();
  const Real between = hz_to_rad(87.85);
  const std::vector<SteadyState> at = states_at(*w.rotor, w.whirl(), between, w.settings);
  ASSERT_EQ(at.size(), 2U);
  const SteadyState& large = w.size(at[0]) > w.size(at[1]) ? at[0] : at[1];
  ASSERT_TRUE(large.stable);
  const Real expected = w.size(large);
  Vector x0, v0;
  orbit_state(*w.rotor, large, w.whirl().fourier, 0.0, x0, v0);
  const Vector centre = w.rotor->expand(large.X.head(w.rotor->size()));
  const Real whipping = w.run(between, centre + 0.95 * (x0 - centre), 0.95 * v0, 2.0);
  // From the equilibrium, the disk pushed 1 µm aside.
  const std::vector<SteadyState> eq = states_at(*w.rotor, w.equilibrium(), between, w.settings);
  ASSERT_EQ(eq.size(), 1U);
  ASSERT_TRUE(eq[0].stable);
  Vector e0, e1;
  orbit_state(*w.rotor, eq[0], FourierBasis{.harmonics = 0, .samples = 1}, 0.0, e0, e1);
  e0(global_dof(node_index(w.file->model, NodeRef{std::string("disk")}), Dof::w)) += 1e-6;
  const Real resting = w.run(between, e0, e1, 2.0);
  // Below the fold, from the fold's orbit.
  const SteadyState& fold = w.whirl().bifurcations.at(0).at;
  orbit_state(*w.rotor, fold, w.whirl().fourier, 0.0, x0, v0);
  const Real dying = w.run(hz_to_rad(87.55), x0, v0, 3.0);
  std::printf(
      "87.85 Hz: whip orbit %.4f um, run-up from 95 %% of it %.4f um, from the equilibrium %.4f um; "
      "87.55 Hz: from the fold's orbit (%.4f um) %.4f um after 3 s\n",
      1e6 * expected, 1e6 * whipping, 1e6 * resting, 1e6 * w.size(fold), 1e6 * dying);
  EXPECT_NEAR(whipping, expected, 0.01 * expected);
  EXPECT_LT(resting, 1e-6);
  EXPECT_LT(dying, 0.6 * w.size(fold));
}

}  // namespace
}  // namespace feran::test_example_oil_whip_orbits

// The rotor a turbomachinery engineer models first, through every analysis: a 1.2 m
// shaft with two disks on two short journal bearings under gravity, operated from
// 8000 to 10000 rpm (tests/models/valid/journal_rotor.toml), which the oil films make
// unstable above about 5300 rpm. Checked against what is independent of each door:
// the journal loads carry the rotor's weight; the response marks its points unstable
// from the Campbell diagram's stability threshold on; API 684 finds the two bearings,
// fails its stability verdict and passes no peak where the rotor is unstable.
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include <feran/analyses/api684/analysis.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/io/model_reader.hpp>

namespace feran::test_journal_rotor {
namespace {

const std::string path = FERAN_TEST_MODELS "/valid/journal_rotor.toml";

TEST(JournalRotor, ResponsePointsAreMarkedUnstableFromTheCampbellThresholdOn) {
  const ModelFile file = read_model_file(path);
  CampbellOptions co = analysis_options<CampbellAnalysis>(file, {}, file_key_name<CampbellAnalysis>());
  const CampbellResult campbell = run_campbell(file.model, co);
  ASSERT_TRUE(campbell.stability_threshold.has_value());
  const Real threshold = campbell.stability_threshold->speed;
  EXPECT_GT(threshold * 30 / pi, 4000.0);
  EXPECT_LT(threshold * 30 / pi, 7000.0);

  const HarmonicOptions ho = response_options(file);
  const HarmonicResult r = run_harmonic_response(file.model, ho);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_EQ(r.stability.size(), r.speeds.size());
  // Two doors, one answer: stable below the threshold, unstable above it (the
  // threshold refined by Brent's method to the Campbell diagram's speed tolerance).
  for (std::size_t k = 0; k < r.speeds.size(); ++k) {
    ASSERT_TRUE(r.stability[k].known) << r.stability[k].message;
    EXPECT_EQ(r.stability[k].unstable, r.speeds[k] > threshold) << "at " << r.speeds[k] * 30 / pi << " rpm";
  }
  EXPECT_GT(unstable_points(r), 0);
}

TEST(JournalRotor, TheJournalOrbitIsGivenAgainstTheClearanceAndWarnedBeyondIt) {
  // "bearing A" is a probe and its housing is the ground: the journal's orbit relative
  // to the housing is the probe's own (v, w) orbit, computed by another path, to
  // round-off; over the clearance c = 0.06 mm it is the ratio. The model's 2 g at
  // 150 mm keeps every orbit inside the clearance (no warning); a thousand times that
  // throws the linearised orbit far beyond it, and the warning names the bearing.
  const ModelFile file = read_model_file(path);
  HarmonicOptions ho = response_options(file);
  ho.stability = false;
  const HarmonicResult r = run_harmonic_response(file.model, ho);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_EQ(r.supports.size(), 2u);
  const ProbeResponse& journal = r.probes[1];
  ASSERT_EQ(file.model.node_label(journal.node), "1 (bearing A)");
  const SupportForceResponse& a = r.supports[0];
  ASSERT_EQ(a.orbit.size(), r.speeds.size());
  for (std::size_t k = 0; k < r.speeds.size(); ++k) {
    EXPECT_NEAR(a.orbit[k], journal.orbit[k].major, 1e-12 * journal.orbit[k].major + 1e-20);
    EXPECT_NEAR(a.orbit_clearance_ratio[k], a.orbit[k] / 0.06e-3, 1e-12 * a.orbit_clearance_ratio[k]);
    EXPECT_LT(a.orbit_clearance_ratio[k], 1.0);
  }
  EXPECT_TRUE(clearance_warnings(r, file.model).empty());

  const ModelFile heavy = read_model_file(path, {"unbalances[disk 1 unbalance].mass=2 kg"});
  const HarmonicResult big = run_harmonic_response(heavy.model, ho);
  const std::vector<std::string> warnings = clearance_warnings(big, heavy.model);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.front().find("'bearing A'"), std::string::npos) << warnings.front();
}

// The bearings' operating state at one point of an analysis, by name.
std::map<std::string, Real> state_at(const OperatingSeries& s, std::size_t k) {
  std::map<std::string, Real> out;
  for (std::size_t q = 0; q < s.quantities.size(); ++q) out[s.quantities[q]] = s.values[k][q];
  return out;
}

// The same from a static analysis at @p speed under the model's gravity: its own
// equilibrium, solved apart from the linear analyses' (another door).
std::vector<std::map<std::string, Real>> static_state(const Model& model, Real speed) {
  const StaticResult st =
      run_static(model, {.gravity = model.gravity, .speed = speed, .loads = true, .stability = false});
  std::vector<std::map<std::string, Real>> out;
  for (const auto& data : st.support_data) {
    out.emplace_back();
    for (const OperatingValue& o : data) out.back()[o.name] = o.value;
  }
  return out;
}

TEST(JournalRotor, BearingOperatingDataIsTheEquilibriumsInEveryAnalysis) {
  // The Campbell diagram, the response and the modal analysis give each bearing's state
  // at the equilibrium about which they linearise it: the static analysis at the same
  // speed finds the same (both solve to a residual of 1e-10 of the load: 1e-8 on ε and
  // the attitude angle). At every point, independent of any door: the film loads carry
  // the rotor's weight (1e-9), h_min = c(1 − ε) with c = 0.06 mm, the power loss is the
  // friction torque times the speed, and the Sommerfeld number is μNLD/W·(R/c)² of the
  // bearing's data (μ = 0.02 Pa s, L = 30 mm, D = 60 mm: the model's).
  const ModelFile file = read_model_file(path);
  const Model& model = file.model;
  const Real weight = rotating_mass(model) * model.gravity.norm();
  CampbellOptions co = analysis_options<CampbellAnalysis>(file, {}, file_key_name<CampbellAnalysis>());
  const CampbellResult campbell = run_campbell(model, co);
  ASSERT_EQ(campbell.operating.size(), 2u);
  const Real c = 0.06e-3, mu = 0.02, L = 0.03, D = 0.06, R = D / 2;
  for (std::size_t k = 0; k < campbell.speeds.size(); ++k) {
    const Real speed = campbell.speeds[k];
    Real carried = 0;
    for (const OperatingSeries& s : campbell.operating) {
      std::map<std::string, Real> d = state_at(s, k);
      carried += d["load_n"];
      EXPECT_NEAR(d["min_film_thickness_m"], c * (1 - d["eccentricity_ratio"]), 1e-18);
      EXPECT_NEAR(d["power_loss_w"], d["friction_torque_nm"] * speed, 1e-12 * d["power_loss_w"]);
      const Real S = mu * speed / (2 * pi) * L * D / d["load_n"] * (R / c) * (R / c);
      EXPECT_NEAR(d["sommerfeld_number"], S, 1e-12 * S);
    }
    EXPECT_NEAR(carried, weight, 1e-9 * weight) << "at " << speed * 30 / pi << " rpm";
  }
  for (const std::size_t k : {std::size_t{0}, campbell.speeds.size() / 2, campbell.speeds.size() - 1}) {
    const auto expect = static_state(model, campbell.speeds[k]);
    for (std::size_t b = 0; b < 2; ++b) {
      std::map<std::string, Real> d = state_at(campbell.operating[b], k);
      EXPECT_NEAR(d["eccentricity_ratio"], expect[b].at("eccentricity_ratio"), 1e-8);
      EXPECT_NEAR(d["attitude_angle_deg"], expect[b].at("attitude_angle_deg"), 1e-6);
    }
  }
  const ModalResult modal = run_modal(model, 9000 * pi / 30);
  const HarmonicOptions ho = response_options(file);
  const HarmonicResult response = run_harmonic_response(model, ho);
  const auto at_9000 = static_state(model, 9000 * pi / 30);
  ASSERT_EQ(modal.operating.size(), 2u);
  ASSERT_EQ(response.operating.size(), 2u);
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_NEAR(state_at(modal.operating[b], 0)["eccentricity_ratio"], at_9000[b].at("eccentricity_ratio"), 1e-8);
    ASSERT_EQ(response.operating[b].values.size(), response.speeds.size());
    for (std::size_t k = 0; k < response.speeds.size(); k += response.speeds.size() / 3) {
      const auto expect = static_state(model, response.speeds[k]);
      EXPECT_NEAR(state_at(response.operating[b], k)["eccentricity_ratio"], expect[b].at("eccentricity_ratio"), 1e-8);
    }
  }
}

TEST(JournalRotor, RunupBearingDataStartsAtTheEquilibriumAndWatchesTheClearance) {
  // Started at the equilibrium at 4000 rpm (below the threshold) at constant speed:
  // the first sample's state is the static analysis' (the start is that equilibrium,
  // 1e-8 on ε); the largest excursion, watched at every step, is at least every
  // sample's eccentricity ratio, and the unbalance's small orbit keeps it near ε.
  const ModelFile file = read_model_file(path);
  const Model& model = file.model;
  const Real speed = 4000 * pi / 30;
  TransientOptions o;
  o.profile = SpeedProfile::constant(speed);
  o.duration = 0.01;
  o.settings.dt = 1e-4;
  o.output_interval = 1e-3;
  o.gravity = model.gravity;
  o.start = RunupStart::equilibrium;
  const TransientResult r = run_transient(model, o);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_EQ(r.operating.size(), 2u);
  ASSERT_EQ(r.clearance_use.size(), 2u);
  const auto expect = static_state(model, speed);
  for (std::size_t b = 0; b < 2; ++b) {
    ASSERT_EQ(r.operating[b].values.size(), r.samples.size());
    ASSERT_EQ(r.samples.front().operating[b], r.operating[b].values.front());
    const Real eps = state_at(r.operating[b], 0)["eccentricity_ratio"];
    EXPECT_NEAR(eps, expect[b].at("eccentricity_ratio"), 1e-8);
    // Samples are interpolated between steps (fourth order): 1e-9 of slack.
    for (const Real e : r.operating[b].series("eccentricity_ratio")) EXPECT_LE(e, r.clearance_use[b].largest + 1e-9);
    EXPECT_LT(r.clearance_use[b].largest, eps + 0.1);
    EXPECT_NEAR(r.clearance_use[b].clearance, 0.06e-3, 1e-18);
  }
}

TEST(JournalRotor, Api684TakesTheJournalBearingsAndFailsTheStabilityVerdict) {
  const ModelFile file = read_model_file(path);
  Api684Spec request;
  request.points = 41;
  request.map_points = 9;
  request.stability = false;
  const Api684Options options = analysis_options<Api684Analysis>(file, request, file_key_name<Api684Analysis>());
  const Api684Result r = run_api684(file.model, options);
  ASSERT_EQ(r.bearings.size(), 2u);
  // The journal loads carry the weight: their sum is the rotor's mass times g.
  ASSERT_EQ(r.journals.size(), 2u);
  const Real g = options.gravity.gravity.norm();
  EXPECT_NEAR(r.journals[0].force + r.journals[1].force, rotating_mass(file.model) * g,
              1e-9 * rotating_mass(file.model) * g);
  // The operating range lies above the threshold: the verdict fails with its reason.
  EXPECT_FALSE(r.stability_verdict.passes);
  EXPECT_NE(r.stability_verdict.reason.find("unstable at 8000 rpm"), std::string::npos) << r.stability_verdict.reason;
  // The undamped critical speeds with the films' direct stiffness, positive, ascending.
  ASSERT_GE(r.undamped.size(), 2u);
  EXPECT_GT(r.undamped[0].speed, 0);
  EXPECT_LT(r.undamped[0].speed, r.undamped[1].speed);
  // No peak passes where the rotor is unstable.
  for (const Api684Case& c : r.cases)
    for (const auto& probe : c.checks)
      for (const SeparationCheck& check : probe)
        if (check.unstable) {
          EXPECT_TRUE(check.passes.has_value() && !*check.passes);
          EXPECT_FALSE(c.passes);
        }
  // The map's bearing curves are the films' direct stiffness, positive where the
  // equilibrium exists.
  ASSERT_TRUE(r.map.has_value());
  EXPECT_EQ(r.map->curves.size(), 4u);
}

}  // namespace
}  // namespace feran::test_journal_rotor

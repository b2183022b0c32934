// The rotor a turbomachinery engineer models first, through every analysis: a 1.2 m
// shaft with two disks on two short journal bearings under gravity, operated from
// 8000 to 10000 rpm (tests/models/valid/journal_rotor.toml), which the oil films make
// unstable above about 5300 rpm. Checked against what is independent of each door:
// the journal loads carry the rotor's weight; the response marks its points unstable
// from the Campbell diagram's stability threshold on; API 684 finds the two bearings,
// fails its stability verdict and passes no peak where the rotor is unstable.
#include <cmath>

#include <gtest/gtest.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/modal/campbell.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/io/model_reader.hpp>

namespace feran::test_journal_rotor {
namespace {

const std::string path = FERAN_TEST_MODELS "/valid/journal_rotor.toml";

TEST(JournalRotor, ResponsePointsAreMarkedUnstableFromTheCampbellThresholdOn) {
  const ModelFile file = read_model_file(path);
  CampbellOptions co = campbell_settings(file.spec.campbell, {});
  const CampbellResult campbell = run_campbell(file.model, co);
  ASSERT_TRUE(campbell.stability_threshold.has_value());
  const Real threshold = campbell.stability_threshold->speed;
  EXPECT_GT(threshold * 30 / pi, 4000.0);
  EXPECT_LT(threshold * 30 / pi, 7000.0);

  const HarmonicOptions ho = response_settings(file.model, file.spec.response, {});
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
  HarmonicOptions ho = response_settings(file.model, file.spec.response, {});
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

TEST(JournalRotor, Api684TakesTheJournalBearingsAndFailsTheStabilityVerdict) {
  const ModelFile file = read_model_file(path);
  Api684Request request;
  request.points = 41;
  request.map_points = 9;
  request.stability = false;
  const Api684Options options = api684_settings(file.model, file.spec, request);
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

// The orbits analysis's face (analyses/periodic/analysis.hpp), on the rigid rotor of
// Friswell et al. (2010), Example 5.5.1, in two short bearings carrying 525 N each,
// written as a model file — the door a user takes — against the library's branches on
// the same rotor built in code (test_orbits.cpp):
// - branch "auto" on a rotor without unbalance is the whirl: the equilibrium's Hopf
//   point is the linear threshold 863.345 rad/s (1e-6 relative, the location's
//   tolerance) and the whirl leaving it is subcritical with its fold within 0.5 % of
//   807.55 rad/s (H = 8: 807.19; test_orbits.cpp);
// - the probes' orbits: at the equilibrium a point (amplitude 0), on the whirl the
//   journal's centre and largest distance from it as the library's motion of the
//   whole rotor gives them (orbit_state, expanded from the condensed coordinates;
//   centre 1e-9, size 1e-4: sampled at 256 and 720 phases);
// - the study quantities: jump_down_speed is the fold's speed (exactly: the same
//   number), largest_stable_orbit the largest amplitude among the stable orbits;
// - the JSON and the CSV carry the same states as the result (to their printed digits);
// - a branch in one bearing's oil viscosity at the Hopf speed meets its Hopf point at
//   the file's 0.1 Pa s (both bearings at 0.1 Pa s at that speed are the Hopf point;
//   1e-5 relative: the threshold speed is known to 1e-6, and the viscosity of one
//   bearing moves the threshold about half as much as the speed);
// - bad options are refused, each naming what to change.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include <feran/analyses/periodic/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/study/quantity.hpp>

namespace feran::test_orbits_analysis {
namespace {

// The rigid rotor of test_models.hpp (rigid_rotor_in_journal_bearings) as a file.
std::string rotor_file(const std::string& orbits) {
  return R"(title = "rigid rotor in short journal bearings"
[[nodes]]
name = "centre"
x = 0
rotating = true
[[nodes]]
name = "left"
x = -0.2
rotating = true
[[nodes]]
name = "right"
x = 0.2
rotating = true
[[rigid_bodies]]
name = "rotor"
node = "centre"
mass = 107.03363914373089
Ja = 0.21406727828746178
Jp = 0.08562691131498471
[[rigid_links]]
nodes = ["centre", "left", "right"]
[[fixed]]
node = "centre"
dofs = ["u", "rx"]
[[journal_bearings]]
name = "left"
node = "left"
diameter = 0.1
length = 0.03
clearance = 1e-4
viscosity = 0.1
[[journal_bearings]]
name = "right"
node = "right"
diameter = 0.1
length = 0.03
clearance = 1e-4
viscosity = 0.1
[static]
gravity = "-y"
g = 9.81
[orbits]
)" + orbits;
}

std::shared_ptr<const ModelFile> rotor(const std::string& orbits) {
  return std::make_shared<const ModelFile>(read_model_string(rotor_file(orbits), "rotor.toml"));
}

Outcome<OrbitsAnalysis> run(const std::shared_ptr<const ModelFile>& file, const OrbitsSpec& request = {}) {
  return run_analysis<OrbitsAnalysis>(file, request, file_key_name<OrbitsAnalysis>());
}

constexpr Real threshold = 863.345;  // rad/s, the modal analysis's bisection

TEST(OrbitsAnalysis, TheWhirlOfTheFileIsTheLibrarysWithItsProbesAndQuantities) {
  const auto file = rotor("from = 600\nto = 1100\nharmonics = 8\npoints = 60\nprobes = [\"left\"]\n");
  const Outcome<OrbitsAnalysis> o = run(file);
  ASSERT_TRUE(o.result.info.converged()) << o.result.info.message;
  EXPECT_EQ(o.result.branch, "whirl");
  ASSERT_EQ(o.result.branches.size(), 2U);
  const OrbitsBranch& eq = o.result.branches[0];
  ASSERT_EQ(eq.branch.bifurcations.size(), 1U);
  const Bifurcation& hopf = eq.branch.bifurcations[0];
  EXPECT_EQ(hopf.kind, Bifurcation::Kind::hopf);
  EXPECT_NEAR(hopf.at.speed, threshold, 1e-6 * threshold);
  EXPECT_NEAR(critical_frequency(hopf) / hopf.at.speed, 0.5, 0.05);
  for (const auto& p : eq.probes) EXPECT_EQ(p[0].amplitude, 0.0);
  const OrbitsBranch& whirl = o.result.branches[1];
  EXPECT_EQ(whirl.branch.criticality, "subcritical");
  ASSERT_EQ(whirl.branch.bifurcations.size(), 1U);
  const Real fold = whirl.branch.bifurcations[0].at.speed;
  EXPECT_NEAR(fold, 807.55, 0.005 * 807.55);
  // The probe's orbit is the library's motion of the whole rotor (orbit_state) at the
  // probe's DOFs: its centre and its largest distance from it (1e-6 relative: the
  // analysis samples the orbit at 256 phases, here at 720).
  const CondensedRotor condensed(o.model(), nullptr,
                                 {.modes = 12,
                                  .gravity = Eigen::Vector3d(0, -9.81, 0),
                                  .static_loads = true,
                                  .unbalance = false,
                                  .reference_speed = 850.0});
  const Index v = global_dof(o.options.probes[0], Dof::v), w = global_dof(o.options.probes[0], Dof::w);
  for (std::size_t k = 1; k < whirl.probes.size(); k += 7) {
    const ProbeOrbit& p = whirl.probes[k][0];
    Vector x, xdot;
    Real mean_v = 0, mean_w = 0, largest = 0;
    std::vector<std::pair<Real, Real>> path;
    for (int j = 0; j < 720; ++j) {
      orbit_state(condensed, whirl.branch.orbits[k], whirl.branch.fourier, 2 * pi * j / 720.0, x, xdot);
      path.emplace_back(x(v), x(w));
      mean_v += x(v) / 720.0;
      mean_w += x(w) / 720.0;
    }
    for (const auto& [y, z] : path) largest = std::max(largest, std::hypot(y - mean_v, z - mean_w));
    EXPECT_NEAR(p.mean_v, mean_v, 1e-9 * std::abs(mean_v)) << k;
    EXPECT_NEAR(p.mean_w, mean_w, 1e-9 * std::abs(mean_w)) << k;
    EXPECT_NEAR(p.amplitude, largest, 1e-4 * largest) << k;
    EXPECT_LT(p.largest, 1e-4) << k;  // inside the clearance
  }
  // The study quantities read the same result.
  std::vector<QuantitySpec> q(2);
  q[0].kind = "jump_down_speed";
  q[1].kind = "largest_stable_orbit";
  std::vector<std::string> clipped;
  const std::vector<Real> values = evaluate_quantities(file->spec, file->model, q, {}, &clipped);
  EXPECT_EQ(values[0], whirl.branch.bifurcations[0].at.parameter);
  EXPECT_EQ(clipped[0], "");
  Real largest = 0;
  for (std::size_t k = 0; k < whirl.probes.size(); ++k)
    if (whirl.branch.orbits[k].stable) largest = std::max(largest, whirl.probes[k][0].amplitude);
  EXPECT_EQ(values[1], largest);
  // The JSON and the CSV: every state, in order.
  const nlohmann::json j = nlohmann::json::parse(OrbitsAnalysis::json(o));
  ASSERT_EQ(j["branches"].size(), 2U);
  EXPECT_EQ(j["branches"][1]["criticality"], "subcritical");
  EXPECT_EQ(j["branches"][1]["points"].size(), whirl.branch.orbits.size());
  EXPECT_NEAR(j["branches"][0]["bifurcations"][0]["speed_hz"].get<Real>() * 2 * pi, threshold, 1e-6 * threshold);
  std::istringstream csv(OrbitsAnalysis::csv(o));
  std::size_t rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 1 + eq.branch.orbits.size() + whirl.branch.orbits.size() + 2);
}

TEST(OrbitsAnalysis, ABranchInTheViscosityMeetsTheHopfPointAtTheFilesViscosity) {
  const auto file = rotor("");
  OrbitsSpec request;
  request.parameter = "journal_bearings[left].viscosity";
  request.parameter_from = "50 mPa*s";
  request.parameter_to = "200 mPa*s";
  request.branch = "equilibrium";
  // The Hopf speed of the equilibrium over speed, then the branch in viscosity there.
  OrbitsSpec over_speed;
  over_speed.from = 800.0;
  over_speed.to = 950.0;
  over_speed.branch = "equilibrium";
  const Outcome<OrbitsAnalysis> s = run(file, over_speed);
  ASSERT_EQ(s.result.branches.at(0).branch.bifurcations.size(), 1U);
  request.speed = s.result.branches[0].branch.bifurcations[0].at.speed;
  const Outcome<OrbitsAnalysis> o = run(file, request);
  ASSERT_TRUE(o.result.info.converged()) << o.result.info.message;
  ASSERT_EQ(o.result.branches.size(), 1U);
  const OrbitsBranch& eq = o.result.branches[0];
  EXPECT_TRUE(eq.branch.clipped) << eq.branch.ended_by;
  ASSERT_EQ(eq.branch.bifurcations.size(), 1U);
  EXPECT_EQ(eq.branch.bifurcations[0].kind, Bifurcation::Kind::hopf);
  // Both bearings at 0.1 Pa s and the threshold speed is the Hopf point, so the left
  // bearing's viscosity alone crosses there too.
  EXPECT_NEAR(eq.branch.bifurcations[0].at.parameter, 0.1, 1e-5 * 0.1);
  EXPECT_TRUE(eq.branch.orbits.front().stable != eq.branch.orbits.back().stable);
  EXPECT_EQ(o.options.parameter, "journal_bearings[left].viscosity");
  EXPECT_NEAR(o.options.from, 0.05, 1e-15);
  EXPECT_NEAR(o.options.to, 0.2, 1e-15);
}

// Stability that changes back and forth within a hundredth of the range is said to be
// within the method's accuracy; changes farther apart are not.
TEST(OrbitsAnalysis, StabilityFlickeringAtTheUnitCircleIsSaid) {
  const auto file = rotor("from = 600\nto = 1100\n");
  const OrbitsOptions options = orbits_options(*file);
  OrbitsResult result;
  result.branch = "whirl";
  OrbitsBranch& b = result.branches.emplace_back();
  b.name = "whirl 1";
  b.branch.kind = OrbitBranch::Kind::self_excited;
  b.branch.clipped = true;
  const auto states = [&](std::vector<std::pair<Real, bool>> points) {
    b.branch.orbits.clear();
    for (const auto& [p, stable] : points) {
      SteadyState& state = b.branch.orbits.emplace_back();
      state.parameter = state.speed = p;
      state.stable = stable;
    }
    std::string said;
    for (const std::string& w : OrbitsAnalysis::warnings(file->model, options, result))
      if (w.find("stability changes") != std::string::npos) said = w;
    return said;
  };
  EXPECT_NE(states({{700, true}, {701, false}, {702, true}, {703, false}, {704, true}}).find("changes 4 times"),
            std::string::npos);
  EXPECT_EQ(states({{700, true}, {750, false}, {800, true}, {850, false}}), "");
}

TEST(OrbitsAnalysis, RefusesBadOptionsNamingWhatToChange) {
  const auto file = rotor("");
  const auto refused = [&](const OrbitsSpec& request, const std::string& expected) {
    try {
      static_cast<void>(run(file, request));
      ADD_FAILURE() << "not refused: " << expected;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused({}, "give the speed range with orbits.from and orbits.to");
  OrbitsSpec r;
  r.from = 900.0;
  r.to = 800.0;
  refused(r, "orbits.to (");
  r.to = 1000.0;
  r.harmonics = 8;
  r.samples = 16;
  refused(r, "orbits.samples (16) must be at least 2·orbits.harmonics + 1 = 17");
  r.samples.reset();
  r.branch = "forced";
  refused(r, "branch \"forced\" needs a load at the rotor speed");
  r.branch.reset();
  r.parameter = "journal_bearings[left].viscosity";
  refused(r, "orbits.parameter continues in a parameter at the fixed orbits.speed");
  r.from.reset();
  r.to.reset();
  r.parameter_from = "50 mPa*s";
  r.parameter_to = "200 mPa*s";
  refused(r, "orbits.parameter needs");
  r.speed = 800.0;
  r.parameter_to = "20 mPa*s";
  refused(r, "orbits.parameter_to (20 mPa*s) must be above");
  r.parameter_to = "2 m";
  refused(r, "orbits.parameter_to '2 m'");
  r.parameter = "journal_bearings[middle].viscosity";
  refused(r, "orbits.parameter");
}

}  // namespace
}  // namespace feran::test_orbits_analysis

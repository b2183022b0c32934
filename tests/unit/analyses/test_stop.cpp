// A stop asked for (a signal in the command line) ends sweeps and run-ups at a clean
// point: status interrupted, the results so far kept and whole.
#include <gtest/gtest.h>

#include <atomic>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>

#include "test_models.hpp"

namespace feran::test_stop {
namespace {

std::vector<Real> speeds(int n) {
  std::vector<Real> s;
  for (int i = 0; i < n; ++i) s.push_back(i * 100.0 * 2 * pi / 60);
  return s;
}

TEST(Stop, AnUnsetTokenChangesNothing) {
  const Model model = test::friswell_5_9_1();
  std::atomic<bool> flag{false};
  CampbellOptions opt;
  opt.speeds = speeds(11);
  opt.n_modes = 4;
  const CampbellResult plain = run_campbell(model, opt);
  opt.stop = StopToken(flag);
  const CampbellResult with_token = run_campbell(model, opt);
  ASSERT_TRUE(with_token.info.converged());
  ASSERT_EQ(plain.speeds, with_token.speeds);
  ASSERT_EQ(plain.critical_speeds.size(), with_token.critical_speeds.size());
  for (std::size_t j = 0; j < plain.modes.size(); ++j)
    EXPECT_EQ(plain.modes[j].frequency_hz, with_token.modes[j].frequency_hz);
}

TEST(Stop, SweepsStopBeforeTheirFirstPoint) {
  Model model = test::friswell_5_9_1();
  Unbalance u;
  u.node = 4;
  u.mass = 1e-3;
  u.radius = 0.1;
  model.forces.emplace_back(u);
  std::atomic<bool> flag{true};
  for (int threads : {1, 2}) {
    CampbellOptions c;
    c.speeds = speeds(11);
    c.n_threads = threads;
    c.stop = StopToken(flag);
    const CampbellResult cr = run_campbell(model, c);
    EXPECT_EQ(cr.info.status, SolverStatus::interrupted);
    EXPECT_EQ(cr.info.message, "stopped on request before 0 Hz");
    EXPECT_TRUE(cr.speeds.empty());
    EXPECT_TRUE(cr.critical_speeds.empty());

    HarmonicOptions h;
    h.speeds = speeds(11);
    h.probes = {4};
    h.n_threads = threads;
    h.stop = StopToken(flag);
    const HarmonicResult hr = run_harmonic_response(model, h);
    EXPECT_EQ(hr.info.status, SolverStatus::interrupted);
    EXPECT_EQ(hr.info.message, "stopped on request before 0 Hz");
    EXPECT_TRUE(hr.speeds.empty());
    EXPECT_TRUE(hr.probes[0].q.empty());
  }
}

// Asked for after the 50th sample, the run-up ends at the step after it: every sample
// whole, the end time that of the last step taken.
TEST(Stop, RunupStopsAtTheNextStep) {
  Model model = test::friswell_5_9_1();
  TransientOptions t;
  t.profile = SpeedProfile::constant(100.0);
  t.duration = 1.0;
  t.settings.dt = 1e-4;
  t.output_interval = 1e-3;
  t.probes = {4};
  std::atomic<bool> flag{false};
  t.stop = StopToken(flag);
  std::size_t seen = 0;
  const TransientResult r = run_transient(model, t, [&](const TransientSample&) {
    if (++seen == 50) flag = true;
  });
  EXPECT_EQ(r.info.status, SolverStatus::interrupted);
  EXPECT_NE(r.info.message.find("stopped on request at t = 0.049"), std::string::npos) << r.info.message;
  // Sample 50 is t = 0.049 s (the first is t = 0); the step that reached it is the last.
  ASSERT_EQ(r.samples.size(), 50u);
  EXPECT_NEAR(r.t_end, 0.049, 1e-12);
  for (const TransientSample& s : r.samples) {
    ASSERT_EQ(s.probes.size(), 1u);
    EXPECT_EQ(s.magnitude.size(), 1u);
  }
}

}  // namespace
}  // namespace feran::test_stop

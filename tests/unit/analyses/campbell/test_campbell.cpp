#include <gtest/gtest.h>

#include <feran/analyses/campbell/campbell.hpp>

#include <cmath>

#include "test_models.hpp"

namespace feran {
namespace {

// The speeds and the refinements are independent solves: any number of threads
// gives the same diagram, bit for bit.
TEST(Campbell, ResultDoesNotDependOnThreads) {
  const Model model = test::friswell_5_9_1();
  CampbellOptions opt;
  for (int i = 0; i <= 40; ++i) opt.speeds.push_back(i * 100.0 * 2 * pi / 60);
  opt.n_modes = 6;
  opt.n_threads = 1;
  const CampbellResult a = run_campbell(model, opt);
  opt.n_threads = 3;
  const CampbellResult b = run_campbell(model, opt);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  EXPECT_EQ(a.n_solves, b.n_solves);
  for (std::size_t j = 0; j < a.modes.size(); ++j) {
    EXPECT_EQ(a.modes[j].label, b.modes[j].label);
    EXPECT_EQ(a.modes[j].frequency_hz, b.modes[j].frequency_hz);
  }
  ASSERT_EQ(a.critical_speeds.size(), b.critical_speeds.size());
  ASSERT_FALSE(a.critical_speeds.empty());
  for (std::size_t k = 0; k < a.critical_speeds.size(); ++k)
    EXPECT_EQ(a.critical_speeds[k].speed, b.critical_speeds[k].speed);
}

// On soft anisotropic bearings the lowest modes are nearly straight-line orbits
// (directivity −0.002 to −0.02 over 0–4000 rpm for the first), below the 5 % that
// classifies an orbit at one speed as forward or backward; they still whirl one way.
// The labels follow the sense over the sweep — the pairs split by the gyroscopic
// moments, backward below forward — and every critical speed carries the sense of
// its mode at that speed, so "the first forward critical speed" is found by whirl.
// Before, the first mode was "planar 1" and the first forward critical speed
// reported a planar whirl.
TEST(Campbell, LabelsFollowTheWhirlOverTheSweep) {
  Model model = test::friswell_5_9_1();
  // Bearings of 1 MN/m made soft and anisotropic: ky = 0.2, kz = 0.5 MN/m.
  for (Element& e : model.elements)
    if (const SpringDamper* s = e.target<SpringDamper>()) {
      SpringDamperCoefficients c = s->coefficients();
      c.k[static_cast<std::size_t>(Dof::v)] = 2e5;
      c.k[static_cast<std::size_t>(Dof::w)] = 5e5;
      e = SpringDamper(s->node_a(), s->node_b(), c);
    }
  CampbellOptions opt;
  for (int i = 0; i <= 40; ++i) opt.speeds.push_back(i * 100.0 * 2 * pi / 60);
  opt.n_modes = 4;
  const CampbellResult r = run_campbell(model, opt);
  ASSERT_EQ(r.modes.size(), 4u);
  // On bearings this soft the rotor moves as a rigid body: translating, then tilting.
  const char* expected[] = {"backward 1", "forward 1", "backward 2", "forward 2"};
  const char* labels[] = {"backward cylindrical 1", "forward cylindrical 1", "backward conical 1", "forward conical 1"};
  for (std::size_t j = 0; j < 4; ++j) {
    const TrackedMode& m = r.modes[j];
    EXPECT_EQ(whirl_name(r, static_cast<Index>(j)), expected[j]);
    EXPECT_EQ(m.label, labels[j]);
    // The sense agrees with the sign of the directivity at every spinning speed.
    for (std::size_t i = 1; i < m.directivity.size(); ++i)
      EXPECT_EQ(m.directivity[i] > 0, m.whirl == Whirl::forward) << m.label << " at " << r.speeds[i];
  }
  ASSERT_EQ(r.critical_speeds.size(), 4u);
  for (const CriticalSpeed& c : r.critical_speeds) EXPECT_EQ(c.whirl, r.modes[static_cast<std::size_t>(c.mode)].whirl);
  const auto first_forward = std::find_if(r.critical_speeds.begin(), r.critical_speeds.end(),
                                          [](const CriticalSpeed& c) { return c.whirl == Whirl::forward; });
  ASSERT_NE(first_forward, r.critical_speeds.end());
  EXPECT_EQ(whirl_name(r, first_forward->mode), "forward 1");
}

// Without gyroscopic coupling of the two planes (a point mass on anisotropic
// supports, tilts held) each mode moves in one plane at every speed, at √(k/m): a
// straight-line orbit, labelled planar.
TEST(Campbell, PlanarOnlyWhenNoSpeedWhirls) {
  Model model;
  const Index n = test::add_node(model, 0.0, true, "disk");
  test::add_body(model, n, 10.0, 1e-3, 1e-3);
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::v)] = 1e6;
  c.k[static_cast<std::size_t>(Dof::w)] = 4e6;
  model.elements.emplace_back(SpringDamper(n, std::nullopt, c));
  test::fix(model, n, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  CampbellOptions opt;
  opt.speeds = {0.0, 200.0, 400.0, 600.0};
  opt.n_modes = 2;
  const CampbellResult r = run_campbell(model, opt);
  ASSERT_EQ(r.modes.size(), 2u);
  EXPECT_EQ(r.modes[0].label, "planar cylindrical 1");  // one node: a rigid translation
  EXPECT_EQ(r.modes[1].label, "planar cylindrical 2");
  EXPECT_NEAR(r.modes[0].frequency_hz[2], std::sqrt(1e6 / 10.0) / (2 * pi), 1e-9 * r.modes[0].frequency_hz[2]);
  EXPECT_NEAR(r.modes[1].frequency_hz[2], std::sqrt(4e6 / 10.0) / (2 * pi), 1e-9 * r.modes[1].frequency_hz[2]);
}

}  // namespace
}  // namespace feran

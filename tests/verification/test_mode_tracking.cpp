// Mode tracking on the Friswell 5.9.1 rotor swept to 60 000 rpm, where the rising
// forward 1 and the falling backward 2 meet near 55 000 rpm.
//  - Isotropic bearings: forward and backward whirl do not interact, so the curves
//    cross. Tracking must follow each whirl through the crossing (sorting by
//    frequency would swap them).
//  - Anisotropic bearings couple forward and backward whirl: the curves veer apart
//    without crossing, and tracking must follow each continuous branch.
// The reference at each speed is an independent modal solve classified by whirl or
// sorted by frequency.
#include <gtest/gtest.h>

#include <algorithm>

#include <feran/analyses/campbell/campbell.hpp>

#include "test_models.hpp"

namespace feran::test_mode_tracking {
namespace {

CampbellOptions sweep() {
  CampbellOptions opt;
  for (int i = 0; i <= 60; ++i) opt.speeds.push_back(i * 1000.0 * 2 * pi / 60);
  opt.n_modes = 7;
  return opt;
}

// The mode named @p name by its whirl ("forward 1", whirl_name()).
const TrackedMode& find(const CampbellResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.modes.size(); ++i)
    if (whirl_name(r, static_cast<Index>(i)) == name) return r.modes[i];
  throw std::runtime_error("no mode " + name);
}

std::vector<Real> lateral_frequencies(const Model& model, Real speed, Whirl whirl, bool any_whirl) {
  std::vector<Real> f;
  for (const Mode& m : run_modal(model, speed).modes)
    if (m.type == ModeType::lateral && (any_whirl || m.whirl == whirl)) f.push_back(m.frequency_hz);
  return f;
}

TEST(ModeTracking, FollowsWhirlThroughACrossing) {
  const Model model = test::friswell_5_9_1();
  const CampbellOptions opt = sweep();
  const CampbellResult r = run_campbell(model, opt);
  const TrackedMode& f1 = find(r, "forward 1");
  const TrackedMode& b2 = find(r, "backward 2");
  // They do cross: forward 1 starts below backward 2 and ends above it.
  EXPECT_LT(f1.frequency_hz[1], b2.frequency_hz[1]);
  EXPECT_GT(f1.frequency_hz.back(), b2.frequency_hz.back());
  for (std::size_t i = 1; i < r.speeds.size(); ++i) {
    EXPECT_EQ(f1.whirl_at[i], Whirl::forward) << "speed index " << i;
    EXPECT_EQ(b2.whirl_at[i], Whirl::backward) << "speed index " << i;
    // The tracked curves are the lowest forward and the second backward whirl of an
    // independent solve at the same speed (same eigen solver: 1e-9 relative).
    const auto fw = lateral_frequencies(model, r.speeds[i], Whirl::forward, false);
    const auto bw = lateral_frequencies(model, r.speeds[i], Whirl::backward, false);
    EXPECT_NEAR(f1.frequency_hz[i], fw[0], 1e-9 * fw[0]);
    EXPECT_NEAR(b2.frequency_hz[i], bw[1], 1e-9 * bw[1]);
  }
}

TEST(ModeTracking, FollowsBranchesThroughAVeering) {
  Model model = test::friswell_5_9_1();
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::w)] = 5e4;  // bearings 5 % stiffer along z
  model.elements.emplace_back(SpringDamper(0, std::nullopt, c));
  model.elements.emplace_back(SpringDamper(6, std::nullopt, c));
  const CampbellOptions opt = sweep();
  const CampbellResult r = run_campbell(model, opt);
  // At rest the anisotropic rotor's modes are planar; tracked modes are labelled by
  // the whirl they show at most speeds.
  const TrackedMode& lower = find(r, "forward 1");
  const TrackedMode& upper = find(r, "backward 2");
  Real min_gap = 1e9;
  for (std::size_t i = 0; i < r.speeds.size(); ++i) {
    // No crossing: each branch is the 2nd and 3rd lowest lateral frequency at every
    // speed of an independent solve.
    const auto all = lateral_frequencies(model, r.speeds[i], Whirl::none, true);
    EXPECT_NEAR(lower.frequency_hz[i], all[1], 1e-9 * all[1]) << "speed index " << i;
    EXPECT_NEAR(upper.frequency_hz[i], all[2], 1e-9 * all[2]) << "speed index " << i;
    min_gap = std::min(min_gap, upper.frequency_hz[i] - lower.frequency_hz[i]);
  }
  EXPECT_GT(min_gap, 0.0);
  // The branches exchange character through the veering: the lower one starts as a
  // forward whirl and has turned mixed or backward by the end of the sweep.
  EXPECT_EQ(lower.whirl_at[1], Whirl::forward);
  EXPECT_NE(lower.whirl_at.back(), Whirl::forward);
  EXPECT_LT(lower.directivity.back(), lower.directivity[1] - 0.5);
}

}  // namespace
}  // namespace feran::test_mode_tracking

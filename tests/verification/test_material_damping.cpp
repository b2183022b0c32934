// Stiffness-proportional material damping of a rotating shaft (C_i = βK, K_i the
// matching circulatory part) with no external damping: for a forward whirl of
// frequency ω it adds damping in proportion to (1 − Ω/ω), so the shaft is stable
// below its first forward critical speed and unstable above it, and the stability
// threshold coincides with the critical speed (Ω = ω). Simply supported uniform
// shaft, 8 elements, including its own gyroscopic effect.
#include <gtest/gtest.h>

#include <feran/analyses/campbell/campbell.hpp>

#include "test_models.hpp"

namespace feran::test_material_damping {
namespace {

TEST(MaterialDamping, ThresholdIsTheFirstForwardCriticalSpeed) {
  Model model;
  BeamOptions damped;
  damped.damping_beta = 2e-5;  // β [s]
  test::add_shaft(model, 0.0, 1.0, 8, 0.04, test::steel(), 0.0, damped);
  test::fix(model, 0, {Dof::u, Dof::v, Dof::w, Dof::rx});
  test::fix(model, 8, {Dof::v, Dof::w});
  CampbellOptions opt;
  for (int i = 0; i <= 40; ++i) opt.speeds.push_back(hz_to_rad(4.0 * i));  // first critical near 82 Hz
  opt.n_modes = 4;
  const CampbellResult r = run_campbell(model, opt);
  ASSERT_TRUE(r.stability_threshold.has_value());
  const TrackedMode& unstable = r.modes[static_cast<std::size_t>(r.stability_threshold->mode)];
  EXPECT_EQ(unstable.label, "forward bending 1");  // a pinned shaft: its first forward mode bends
  Real critical = 0;
  for (const CriticalSpeed& c : r.critical_speeds)
    if (r.modes[static_cast<std::size_t>(c.mode)].label == "forward bending 1") critical = c.speed;
  ASSERT_GT(critical, 0.0);
  // Both roots are refined to 1e-8 rad/s; the identity is exact up to the damping
  // tolerance (1e-9) in the threshold's definition: 1e-6 relative.
  EXPECT_NEAR(r.stability_threshold->speed, critical, 1e-6 * critical);
  // Below it, material damping damps the forward whirl.
  EXPECT_GT(unstable.damping_ratio[1], 0.0);
}

}  // namespace
}  // namespace feran::test_material_damping

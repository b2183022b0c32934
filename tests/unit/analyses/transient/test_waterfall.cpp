// The run-up's waterfall (analyses/runup/waterfall.hpp) on samples of known spectra.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/runup/waterfall.hpp>
#include <feran/core/error.hpp>

namespace feran {
namespace {

// Samples every dt of v(t) = offset + a·sin(2πft) at one probe, the speed rising
// linearly with time (1 rad/s per second).
TransientResult sine(Real a, Real f, Real offset, Real dt, std::size_t count) {
  TransientResult r;
  for (std::size_t k = 0; k < count; ++k) {
    TransientSample s;
    s.t = static_cast<Real>(k) * dt;
    s.speed = s.t;
    s.probes.push_back({0, offset + a * std::sin(2 * pi * f * s.t), 0, 0, 0, 0});
    r.samples.push_back(s);
  }
  return r;
}

TEST(Waterfall, ASineOnTheGridShowsItsAmplitudeAndTheMeanIsRemoved) {
  // 50 Hz on the grid of 1 s windows (1000 samples): the symmetric Hann taper
  // (n − 1 in its denominator) is not exactly periodic over the window, which moves
  // the peak by O(1/n): 2e-3 relative.
  const Real a = 2e-5;
  const TransientResult r = sine(a, 50.0, 1e-3, 1e-3, 10000);
  const Waterfall w = waterfall(r, 0, Dof::v, 1.0, 0.5);
  EXPECT_EQ(w.window_samples, 1000);
  EXPECT_DOUBLE_EQ(w.sample_interval, 1e-3);
  ASSERT_EQ(w.frequencies.size(), 501u);
  EXPECT_NEAR(w.frequencies[50], 50.0, 1e-12);
  ASSERT_EQ(w.amplitude.rows(), 19);  // windows starting every 500 samples
  for (Index i = 0; i < w.amplitude.rows(); ++i) {
    Index peak = 0;
    w.amplitude.row(i).maxCoeff(&peak);
    EXPECT_EQ(peak, 50);
    EXPECT_NEAR(w.amplitude(i, 50), a, 2e-3 * a);
    // The offset, 50 times the sine, is gone (it would show as 2·offset = 100·a at
    // 0 Hz): what is left there is the taper's leakage from 50 Hz, O(a/k³), below 1e-6·a.
    EXPECT_LT(w.amplitude(i, 0), 1e-6 * a);
    // The speed is that of each window's middle sample.
    EXPECT_DOUBLE_EQ(w.speeds[static_cast<std::size_t>(i)], r.samples[static_cast<std::size_t>(i * 500 + 500)].speed);
  }
}

TEST(Waterfall, DefaultWindowIsATwentiethOfTheRunAndBadArgumentsAreRefused) {
  const TransientResult r = sine(1.0, 10.0, 0.0, 1e-3, 2001);
  EXPECT_EQ(waterfall(r, 0, Dof::v).window_samples, 100);
  EXPECT_THROW(waterfall(sine(1.0, 10.0, 0.0, 1e-3, 7), 0, Dof::v), Error);
  EXPECT_THROW(waterfall(r, 1, Dof::v), Error);
  EXPECT_THROW(waterfall(r, 0, Dof::v, {}, 1.0), Error);
  EXPECT_THROW(waterfall(r, 0, Dof::v, -1.0), Error);
  TransientResult still = r;  // samples all at one time
  for (TransientSample& s : still.samples) s.t = 0.0;
  EXPECT_THROW(waterfall(still, 0, Dof::v), Error);
}

}  // namespace
}  // namespace feran

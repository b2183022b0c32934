#include <gtest/gtest.h>

#include <feran/analyses/modal/campbell.hpp>

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

}  // namespace
}  // namespace feran

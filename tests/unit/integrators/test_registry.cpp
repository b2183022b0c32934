// make_integrator: integrators by name.
#include <gtest/gtest.h>

#include <feran/integrators/integrator.hpp>
#include <feran/core/error.hpp>

namespace feran {
namespace {

TEST(Registry, KnowsTheFourIntegrators) {
  const std::vector<std::string> expected{"trapezoidal", "rk3", "wolfbrandt", "ros34pw2"};
  EXPECT_EQ(integrator_names(), expected);
  const IntegratorSettings settings;
  for (const std::string& name : expected) {
    const auto integ = make_integrator(name, settings);
    ASSERT_NE(integ, nullptr) << name;
    EXPECT_EQ(integ->name(), name);
    EXPECT_EQ(integ->adaptive(), name == "ros34pw2") << name;
  }
}

TEST(Registry, UnknownNameThrowsAndListsTheKnownOnes) {
  try {
    make_integrator("rk4", IntegratorSettings{});
    FAIL() << "no exception";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'rk4'"), std::string::npos) << what;
    EXPECT_NE(what.find("trapezoidal, rk3, wolfbrandt, ros34pw2"), std::string::npos) << what;
  }
}

TEST(Registry, BadSettingsThrow) {
  IntegratorSettings settings;
  settings.jacobian_interval = 0;
  EXPECT_THROW(make_integrator("wolfbrandt", settings), Error);
  settings = IntegratorSettings{};
  settings.dt_min = 1.0;
  settings.dt_max = 0.5;
  EXPECT_THROW(make_integrator("ros34pw2", settings), Error);
  settings = IntegratorSettings{};
  settings.newton_max_iterations = 0;
  EXPECT_THROW(make_integrator("trapezoidal", settings), Error);
}

}  // namespace
}  // namespace feran

// Design variables: their mapping from the unit cube, and setting tied paths.
#include <gtest/gtest.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/study/design.hpp>
#include <feran/study/quantity.hpp>

namespace feran::test_design {
namespace {

DesignVariable range(Real lower, Real upper, VariableScale scale = VariableScale::linear,
                     std::vector<std::string> paths = {"p"}, std::string name = "x") {
  DesignVariable v;
  v.name = std::move(name);
  v.paths = std::move(paths);
  v.lower = lower;
  v.upper = upper;
  v.scale = scale;
  return v;
}

TEST(DesignVariable, LinearLogAndDiscreteMappings) {
  const auto lin = range(2, 6);
  EXPECT_EQ(value_at(lin, 0), 2);
  EXPECT_EQ(value_at(lin, 0.25), 3);
  EXPECT_EQ(value_at(lin, 1), 6);
  EXPECT_EQ(value_at(lin, 1.5), 6);  // clamped
  const auto log = range(1e6, 1e9, VariableScale::log);
  EXPECT_EQ(value_at(log, 1), 1e9);  // the bound exactly, not 1e6·1000^1 rounded
  EXPECT_NEAR(value_at(log, 1.0 / 3), 1e7, 1e7 * 1e-14);
  auto choice = range(0, 0);
  choice.values = {10, 20, 30};
  // Equal shares of [0, 1]: [0, 1/3) → 10, [1/3, 2/3) → 20, [2/3, 1] → 30.
  EXPECT_EQ(value_at(choice, 0), 10);
  EXPECT_EQ(value_at(choice, 0.34), 20);
  EXPECT_EQ(value_at(choice, 0.99), 30);
  EXPECT_EQ(value_at(choice, 1), 30);
}

TEST(DesignVariable, ChecksRefuseInconsistentOnes) {
  const auto refused = [](DesignVariable v) {
    const std::vector<DesignVariable> one{std::move(v)};
    EXPECT_THROW(check_variables(one), SpecError);
  };
  refused(range(0, 1, VariableScale::linear, {}));
  refused(range(1, 1));
  refused(range(0, 1, VariableScale::log));
  const std::vector<DesignVariable> twice{range(0, 1), range(0, 1, VariableScale::linear, {"q"})};
  EXPECT_THROW(check_variables(twice), SpecError);
}

TEST(ApplyDesign, SetsEveryTiedPath) {
  const auto file = read_model_file(FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml");
  const std::vector<DesignVariable> vars{
      range(1e6, 1e8, VariableScale::linear, {"springs[bearing k12].ky", "springs[bearing k22].ky"}, "k")};
  const std::vector<Real> values{3e7};
  const auto spec = apply_design(file.spec, vars, values);
  EXPECT_EQ(get_parameter(spec, "springs[bearing k12].ky").value, 3e7);
  EXPECT_EQ(get_parameter(spec, "springs[bearing k22].ky").value, 3e7);
  EXPECT_EQ(get_parameter(spec, "springs[bearing k12].kz").value, 6e7);  // untouched
}

TEST(SeparationMargin, RelativeToTheNearerEdgeOfTheOperatingRange) {
  // API 684's margin: below the range relative to its lower edge, above it relative to
  // the upper edge; inside, negative.
  EXPECT_DOUBLE_EQ(separation_margin(2000, 2900, 3300), 900.0 / 2900);
  EXPECT_DOUBLE_EQ(separation_margin(3630, 2900, 3300), 330.0 / 3300);
  EXPECT_DOUBLE_EQ(separation_margin(2900, 2900, 3300), 0.0);
  EXPECT_DOUBLE_EQ(separation_margin(3000, 2900, 3300), -100.0 / 2900);
  EXPECT_DOUBLE_EQ(separation_margin(3250, 2900, 3300), -50.0 / 3300);
}

TEST(RotatingMass, SumsTheRotatingPartsOnly) {
  // The centrifuge: drive shaft (steel, 68 mm of 17 mm, 25 mm of 11.05 mm, 5 mm of
  // 18.7 mm) and the 1.93 kg rotor; the 5 kg stator does not rotate.
  const auto file = read_model_file(FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml");
  const Real pi = 3.14159265358979323846;
  const Real shaft = 7850 * pi / 4 * (0.068 * 0.017 * 0.017 + 0.025 * 0.01105 * 0.01105 + 0.005 * 0.0187 * 0.0187);
  EXPECT_NEAR(rotating_mass(file.model), 1.93 + shaft, 1e-12);
}

}  // namespace
}  // namespace feran::test_design

// A study on the shipped centrifuge: designs the builder refuses are recorded with
// their message and do not stop the study; the sensitivity table finds what the
// quantity depends on.
#include <cmath>

#include <gtest/gtest.h>

#include <feran/io/study_reader.hpp>
#include <feran/study/sensitivity.hpp>
#include <feran/study/study.hpp>

namespace feran::test_study {
namespace {

const std::string model = "model = \"" FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml\"\n";

TEST(Study, AnInvalidDesignIsRecordedAndTheStudyGoesOn) {
  // The neck's bore from 0 to 15 mm in an 11.05 mm shaft: the designs with a bore
  // of 11.05 mm or more cannot be built.
  const auto file = read_study_string(model +
                                          "[[variables]]\nname = \"bore\"\npath = \"shafts[0].sections[1].inner_diameter\"\n"
                                          "lower = \"0 mm\"\nupper = \"15 mm\"\n"
                                          "[[quantities]]\nname = \"m\"\nkind = \"rotor_mass\"\n"
                                          "[explore]\nmethod = \"grid\"\nlevels = 7\n",
                                      "s.toml");
  ThreadEvaluator evaluator(2);
  const auto all = run_exploration(file.study, evaluator, {}, {}, 3);
  ASSERT_EQ(all.size(), 7u);
  for (const auto& e : all) {
    const bool buildable = e.values[0] < 0.01105;
    EXPECT_EQ(e.evaluated, buildable) << e.values[0];
    EXPECT_EQ(e.feasible, buildable);
    if (!buildable) {
      EXPECT_TRUE(e.quantities.empty());
      EXPECT_NE(e.message.find("inner_diameter"), std::string::npos) << e.message;
    }
  }
  // The hollower the neck, the lighter the rotor: ρ π/4 d_i² L less.
  const Real pi = 3.14159265358979323846;
  EXPECT_NEAR(all[0].quantities[0] - all[1].quantities[0], 7850 * pi / 4 * 0.0025 * 0.0025 * 0.025, 1e-12);
}

TEST(Study, SensitivityFindsWhatTheQuantityDependsOn) {
  // The rotating mass is the rotor's mass plus the shaft's: linear in the rotor's
  // mass, independent of the stator's (which does not rotate). On a full grid the
  // coordinates are uncorrelated, so SRC = 1 and 0 and R² = 1, to rounding.
  const auto file = read_study_string(model +
                                          "[[variables]]\nname = \"rotor\"\npath = \"rigid_bodies[rotor].mass\"\n"
                                          "lower = \"1 kg\"\nupper = \"3 kg\"\n"
                                          "[[variables]]\nname = \"stator\"\npath = \"rigid_bodies[stator].mass\"\n"
                                          "lower = \"2 kg\"\nupper = \"6 kg\"\n"
                                          "[[quantities]]\nname = \"m\"\nkind = \"rotor_mass\"\n"
                                          "[explore]\nmethod = \"grid\"\nlevels = 4\n",
                                      "s.toml");
  ThreadEvaluator evaluator(2);
  const auto all = run_exploration(file.study, evaluator, {}, {}, 8);
  const auto table = sensitivities(file.study, all);
  ASSERT_EQ(table.size(), 1u);
  EXPECT_NEAR(table[0].src[0], 1.0, 1e-12);
  EXPECT_NEAR(table[0].src[1], 0.0, 1e-12);
  EXPECT_NEAR(table[0].r2, 1.0, 1e-12);
  EXPECT_NEAR(table[0].srrc[0], 1.0, 1e-12);
  EXPECT_EQ(table[0].samples, 16);
}

}  // namespace
}  // namespace feran::test_study

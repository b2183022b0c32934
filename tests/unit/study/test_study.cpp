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
  const auto file =
      read_study_string(model +
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

TEST(Study, AQuantityBoundedByTheAnalysedRangeSaysItIsClipped) {
  // Friswell's Example 5.9.1 rotor, bearing stiffness 10-100 MN/m, operating range
  // 2900-3300 rpm. With the Campbell diagram stopping at 3400 rpm, a design whose
  // critical speeds all lie above 3400 rpm has only the range's end to go by: its
  // margin is the end's, 100/3300 exactly, a lower bound, and it says so; a design with
  // a critical speed below 3400 rpm has that speed's margin, exact. Up to 9000 rpm
  // (no mode of these rotors goes unstable: no internal damping, isotropic supports)
  // the stability threshold is the range's end, clipped in every design.
  const std::string base = "model = \"" FERAN_TEST_MODELS "/studies/friswell_5_9_1.toml\"\n";
  const std::string rest =
      "[[variables]]\nname = \"k\"\npaths = [\"springs[bearing 1].ky\", \"springs[bearing 1].kz\", "
      "\"springs[bearing 2].ky\", \"springs[bearing 2].kz\"]\nlower = \"0.1 MN/m\"\nupper = \"100 MN/m\"\n"
      "scale = \"log\"\n"
      "[[quantities]]\nname = \"margin\"\nkind = \"separation_margin\"\noperating = [\"2900 rpm\", \"3300 rpm\"]\n"
      "[[quantities]]\nname = \"threshold\"\nkind = \"stability_threshold\"\n"
      "[explore]\nmethod = \"grid\"\nlevels = 9\n";
  const auto file = read_study_string(base + "[settings]\n\"campbell.stop\" = \"3400 rpm\"\n" + rest, "s.toml");
  ThreadEvaluator evaluator(2);
  const auto all = run_exploration(file.study, evaluator, {}, {}, 3);
  ASSERT_EQ(all.size(), 9u);
  const Real end_margin = 100.0 / 3300.0;
  int clipped = 0, exact = 0;
  for (const auto& e : all) {
    ASSERT_TRUE(e.evaluated) << e.message;
    ASSERT_EQ(e.clipped.size(), 2u);
    if (!e.clipped[0].empty()) {
      ++clipped;
      EXPECT_NEAR(e.quantities[0], end_margin, 1e-12) << e.values[0];
      EXPECT_NE(e.clipped[0].find("a lower bound"), std::string::npos) << e.clipped[0];
    } else {
      ++exact;
      EXPECT_LT(e.quantities[0], end_margin) << e.values[0];  // a critical speed nearer than the end
    }
    EXPECT_NEAR(e.quantities[1], 3400.0 * 2 * 3.14159265358979323846 / 60, 1e-9);
    EXPECT_NE(e.clipped[1].find("stable up to the Campbell range's end"), std::string::npos) << e.clipped[1];
  }
  // The stiffest supports put the first critical speed above 3400 rpm, the softest
  // below 2900 rpm: both cases occur.
  EXPECT_GT(clipped, 0);
  EXPECT_GT(exact, 0);
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

// The study reader: a good study read completely, and each mistake reported where it
// was written, before any design is evaluated.
#include <gtest/gtest.h>

#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/study_reader.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/study/study.hpp>

namespace feran::test_study_reader {
namespace {

const std::string model = FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml";

std::string study(const std::string& body) { return "title = \"t\"\nmodel = \"" + model + "\"\n" + body; }

const std::string variable =
    "[[variables]]\nname = \"k\"\npaths = [\"springs[bearing k12].ky\", \"springs[bearing k12].kz\"]\n"
    "lower = \"1e6 N/m\"\nupper = \"1e8 N/m\"\nscale = \"log\"\n";
const std::string quantity = "[[quantities]]\nname = \"n1\"\nkind = \"critical_speed\"\nunit = \"rpm\"\n";

// The message of the ModelError reading @p text raises, which must be at @p line.
std::string error_at(const std::string& text, int line) {
  try {
    read_study_string(text, "s.toml");
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, "s.toml");
    EXPECT_EQ(e.where().line, line) << e.what();
    return e.message();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

TEST(StudyReader, ReadsAWholeStudy) {
  const auto f = read_study_string(
      study(variable + quantity +
            "[[quantities]]\nname = \"sm\"\nkind = \"separation_margin\"\noperating = [\"2000 rpm\", \"3000 rpm\"]\n"
            "[[objectives]]\nquantity = \"n1\"\nsense = \"maximise\"\n"
            "[[constraints]]\nquantity = \"sm\"\nat_least = 0.15\n"
            "[settings]\n\"campbell.stop\" = \"100 Hz\"\n"
            "[explore]\nmethod = \"sobol\"\nsamples = 16\n"),
      "s.toml");
  const auto& s = f.study;
  ASSERT_EQ(s.variables.size(), 1u);
  EXPECT_EQ(s.variables[0].paths.size(), 2u);
  EXPECT_EQ(s.variables[0].lower, 1e6);
  EXPECT_EQ(s.variables[0].scale, VariableScale::log);
  EXPECT_EQ(s.variables[0].quantity, Quantity::stiffness);
  ASSERT_EQ(s.quantities.size(), 2u);
  EXPECT_EQ(s.quantities[1].kind, "separation_margin");
  EXPECT_NEAR(s.quantities[1].operating_low, 2000 * 3.14159265358979 / 30, 1e-9);
  ASSERT_EQ(s.objectives.size(), 1u);
  EXPECT_EQ(s.objectives[0].sense, Sense::maximise);
  ASSERT_EQ(s.constraints.size(), 1u);
  EXPECT_EQ(s.constraints[0].quantity, 1);
  EXPECT_EQ(*s.constraints[0].at_least, 0.15);
  EXPECT_NEAR(*s.base.campbell.stop, 2 * 3.14159265358979 * 100, 1e-9);  // the setting applied
  EXPECT_EQ(s.explore.method, ExploreMethod::sobol);
  EXPECT_EQ(s.explore.samples, 16);
}

TEST(StudyReader, LocatesEachMistake) {
  EXPECT_NE(error_at(study("colour = 1\n" + variable + quantity), 3).find("unknown key 'colour'"), std::string::npos);
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npath = \"springs[bearing k99].ky\"\nlower = 1\nupper = 2\n" +
                           quantity),
                     5)
                .find("k99"),
            std::string::npos);
  // Tied paths of different kinds.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npaths = [\"springs[bearing k12].ky\",\n"
                           "  \"springs[foot k11].cy\"]\nlower = 1\nupper = 2\n" +
                           quantity),
                     6)
                .find("not of the same kind"),
            std::string::npos);
  // A bound of the wrong kind.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npath = \"springs[bearing k12].ky\"\nlower = \"1 kg\"\n"
                           "upper = 2\n" +
                           quantity),
                     6)
                .find("stiffness"),
            std::string::npos);
  // An unknown quantity kind, with a suggestion.
  EXPECT_NE(error_at(study(variable + "[[quantities]]\nname = \"n\"\nkind = \"critical_sped\"\n"), 11)
                .find("did you mean 'critical_speed'"),
            std::string::npos);
  // An objective naming no quantity.
  EXPECT_NE(error_at(study(variable + quantity + "[[objectives]]\nquantity = \"n2\"\nsense = \"minimise\"\n"), 14)
                .find("no quantity named 'n2'; did you mean 'n1'?"),
            std::string::npos);
  // A separation margin without its operating range.
  EXPECT_NE(
      error_at(study(variable + "[[quantities]]\nname = \"sm\"\nkind = \"separation_margin\"\n"), 9).find("operating"),
      std::string::npos);
  // A setting the model cannot take.
  EXPECT_NE(error_at(study(variable + quantity + "[settings]\n\"campbell.stopp\" = \"1 Hz\"\n"), 14).find("stopp"),
            std::string::npos);
  // A log scale that starts at zero.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npath = \"springs[bearing k12].ky\"\nlower = 0\nupper = 2\n"
                           "scale = \"log\"\n" +
                           quantity),
                     3)
                .find("log scale"),
            std::string::npos);
}

TEST(StudyReader, ReportsAMissingModelAtTheModelKey) {
  const auto message = error_at("model = \"no/such/model.toml\"\n" + variable + quantity, 1);
  EXPECT_NE(message.find("no/such/model.toml"), std::string::npos);
}

TEST(StudyReader, AFunctionQuantityBelongsToStudiesBuiltInCode) {
  // In a study file it is refused where it is named.
  EXPECT_NE(error_at(study(variable + "[[quantities]]\nname = \"f\"\nkind = \"function\"\n"), 11)
                .find("studies built in code"),
            std::string::npos);
  // Built in code: the base model is given (a 'model' key is refused), and the
  // function the caller attaches sees each design's own model.
  StudyCode code;
  code.base = read_model_file(model);
  code.model_name = "centrifuge";
  const std::string body = variable +
                           "[[quantities]]\nname = \"f\"\nkind = \"function\"\n"
                           "[explore]\nmethod = \"grid\"\nlevels = 3\n";
  try {
    read_study_string("model = \"m.toml\"\n" + body, "<study>", code);
    ADD_FAILURE() << "a study built in code took a 'model' key";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 1);
    EXPECT_NE(e.message().find("given its base model"), std::string::npos) << e.message();
  }
  auto file = read_study_string(body, "<study>", code);
  EXPECT_EQ(file.study.model_path, "centrifuge");
  ThreadEvaluator evaluator(2);
  // Without its function a design fails with the reason.
  const auto none = run_exploration(file.study, evaluator, {}, {}, 3);
  ASSERT_EQ(none.size(), 3u);
  EXPECT_NE(none[0].message.find("no function is given"), std::string::npos) << none[0].message;
  file.study.quantities[0].function =
      std::make_shared<const QuantityFunction>([](const ModelSpec& spec, const Model& built) {
        EXPECT_EQ(built.name, spec.title);
        return get_parameter(spec, "springs[bearing k12].kz").value;
      });
  const auto all = run_exploration(file.study, evaluator, {}, {}, 3);
  ASSERT_EQ(all.size(), 3u);
  for (const auto& e : all) {
    ASSERT_TRUE(e.evaluated) << e.message;
    EXPECT_EQ(e.quantities[0], e.values[0]);
  }
  EXPECT_EQ(all[0].values[0], 1e6);
  EXPECT_EQ(all[2].values[0], 1e8);
}

TEST(StudyReader, PathsTiedByALinearRelation) {
  // The bearing's ky the variable's value, its kz 0.8 of it plus 1 MN/m.
  const auto file =
      read_study_string(study("[[variables]]\nname = \"k\"\npaths = [\"springs[bearing k12].ky\",\n"
                              "  { path = \"springs[bearing k12].kz\", factor = 0.8, offset = \"1 MN/m\" }]\n"
                              "lower = \"1e6 N/m\"\nupper = \"1e8 N/m\"\n" +
                              quantity),
                        "s.toml");
  const auto& v = file.study.variables.at(0);
  ASSERT_EQ(v.factors.size(), 2u);
  const ModelSpec spec = apply_design(file.study.base, file.study.variables, std::vector<Real>{2e7});
  EXPECT_EQ(get_parameter(spec, "springs[bearing k12].ky").value, 2e7);
  EXPECT_EQ(get_parameter(spec, "springs[bearing k12].kz").value, 1e6 + 0.8 * 2e7);
  // Mistakes, where they were written.
  const std::string head = "[[variables]]\nname = \"k\"\npaths = [\"springs[bearing k12].ky\",\n";
  EXPECT_NE(
      error_at(study(head + "  { path = \"springs[bearing k12].kz\", factor = 0 }]\nlower = 1\nupper = 2\n" + quantity),
               6)
          .find("'factor' must be a finite number other than 0"),
      std::string::npos);
  EXPECT_NE(
      error_at(study(head + "  { path = \"springs[bearing k12].kz\", scale = 2 }]\nlower = 1\nupper = 2\n" + quantity),
               6)
          .find("unknown key 'scale'"),
      std::string::npos);
  EXPECT_NE(
      error_at(study(head + "  { path = \"springs[bearing k12].kz\", offset = \"1 kg\" }]\nlower = 1\nupper = 2\n" +
                     quantity),
               6)
          .find("stiffness"),
      std::string::npos);
  EXPECT_NE(error_at(study(head + "  3]\nlower = 1\nupper = 2\n" + quantity), 6).find("'paths' must hold"),
            std::string::npos);
}

}  // namespace
}  // namespace feran::test_study_reader

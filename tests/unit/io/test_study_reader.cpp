// The study reader: a good study read completely, and each mistake reported where it
// was written, before any design is evaluated.
#include <gtest/gtest.h>

#include <feran/core/error.hpp>
#include <feran/io/study_reader.hpp>

namespace feran {
namespace {

const std::string model = FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml";

std::string study(const std::string& body) {
  return "title = \"t\"\nmodel = \"" + model + "\"\n" + body;
}

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
  EXPECT_EQ(s.quantities[1].kind, QuantityKind::separation_margin);
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
                           quantity), 5)
                .find("k99"),
            std::string::npos);
  // Tied paths of different kinds.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npaths = [\"springs[bearing k12].ky\",\n"
                           "  \"springs[foot k11].cy\"]\nlower = 1\nupper = 2\n" + quantity), 6)
                .find("not of the same kind"),
            std::string::npos);
  // A bound of the wrong kind.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npath = \"springs[bearing k12].ky\"\nlower = \"1 kg\"\n"
                           "upper = 2\n" + quantity), 6)
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
  EXPECT_NE(error_at(study(variable + "[[quantities]]\nname = \"sm\"\nkind = \"separation_margin\"\n"), 9)
                .find("operating"),
            std::string::npos);
  // A setting the model cannot take.
  EXPECT_NE(error_at(study(variable + quantity + "[settings]\n\"campbell.stopp\" = \"1 Hz\"\n"), 14).find("stopp"),
            std::string::npos);
  // A log scale that starts at zero.
  EXPECT_NE(error_at(study("[[variables]]\nname = \"k\"\npath = \"springs[bearing k12].ky\"\nlower = 0\nupper = 2\n"
                           "scale = \"log\"\n" + quantity), 3)
                .find("log scale"),
            std::string::npos);
}

TEST(StudyReader, ReportsAMissingModelAtTheModelKey) {
  const auto message = error_at("model = \"no/such/model.toml\"\n" + variable + quantity, 1);
  EXPECT_NE(message.find("no/such/model.toml"), std::string::npos);
}

}  // namespace
}  // namespace feran

// Tests of io/model_writer: read → write → read gives an equal spec for every shipped
// example, every benchmark model and every valid test model, and for specs built in
// code with values that no unit writes exactly. Equality is exact (operator== of the
// spec, doubles compared bit for bit): the writer promises digits that read back
// exactly, so no tolerance is needed or allowed.

#include <feran/io/model_reader.hpp>
#include <feran/io/model_writer.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace feran::test_model_writer {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> valid_model_files() {
  std::vector<std::string> files;
  for (const std::string& dir :
       {std::string(FERAN_SOURCE_DIR) + "/examples", std::string(FERAN_SOURCE_DIR) + "/bench/models",
        std::string(FERAN_TEST_MODELS) + "/valid"})
    for (const auto& entry : fs::recursive_directory_iterator(dir))
      if (entry.path().extension() == ".toml" && !entry.path().string().ends_with(".study.toml"))
        files.push_back(entry.path().string());  // every model, not the studies
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ModelWriter, RoundTripOfEveryShippedAndValidModel) {
  const std::vector<std::string> files = valid_model_files();
  ASSERT_GE(files.size(), 21u);  // 9 examples, 6 benchmark models, 6 valid fixtures
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const ModelFile file = read_model_file(path);
    const std::string text = write_toml(file.spec);
    const ModelSpec again = read_model_spec(text, path + " (written)");
    EXPECT_TRUE(again == file.spec) << text;
    // Written once more, the text is the same: the writer is a function of the spec.
    EXPECT_EQ(write_toml(again), text);
    // The written file builds (the spec is valid, so its copy must be too).
    EXPECT_NO_THROW((void)read_model_string(text, path + " (written)"));
  }
}

TEST(ModelWriter, QuantitiesCarryTheirUnit) {
  const ModelFile file = read_model_file(std::string(FERAN_SOURCE_DIR) + "/examples/01_internal_damping/model.toml");
  const std::string text = write_toml(file.spec);
  // The field tables' units where they read back exactly.
  EXPECT_NE(text.find("length = \"60 mm\""), std::string::npos) << text;
  EXPECT_NE(text.find("E = \"210 GPa\""), std::string::npos) << text;
  EXPECT_NE(text.find("mass = \"9.1 kg\""), std::string::npos) << text;
  // Every quantity is a string with a unit: no line "key = <bare float>" for a quantity.
  const std::regex bare_length(R"((length|outer_diameter|radius|E|rho|mass|Ja|Jp) = [-0-9])");
  EXPECT_FALSE(std::regex_search(text, bare_length)) << text;
}

TEST(ModelWriter, ValuesThatNoUnitWritesExactlyRoundTrip) {
  ModelSpec spec;
  spec.title = "awkward \"values\"\twith escapes";
  spec.materials.push_back(
      {.name = "steel", .E = 2.1e11 / 3.0, .G = {}, .nu = 0.1 + 0.2, .rho = 7850.0 / 7.0, .loss_factor = 1e-300});
  ShaftSpec shaft;
  shaft.material = "steel";
  shaft.start_node = "a";
  shaft.sections.push_back({.length = 0.1 + 0.2,
                            .outer_diameter = 1.0 / 3.0,
                            .inner_diameter = 0.0,
                            .outer_diameter_end = 0.2 / 3.0,
                            .inner_diameter_end = 0.01 / 3.0,
                            .axial_force = -1e3 / 3.0,
                            .material = {},
                            .elements = 3,
                            .end_node = "b"});
  spec.shafts.push_back(shaft);
  SpringSpec bearing;
  bearing.name = "bearing";
  bearing.node = std::string("a");
  bearing.coefficients[spring::ky] =
      SpeedCoefficient(SpeedCoefficient::Table{{0.0, 1.0 / 3.0, 100.0}, {1e7, 2e7 / 3.0, 3e7}});
  bearing.coefficients[spring::kz] = SpeedCoefficient(SpeedCoefficient::Arctan{5e6, 3.98, 0.55, 0.9, 0.1});
  bearing.coefficients[spring::cy] =
      SpeedCoefficient(SpeedCoefficient::Step{10.0, 20.0, 2.0 * 3.141592653589793 * 7.1});
  bearing.coefficients[spring::kx] = SpeedCoefficient(1e8);
  spec.springs.push_back(bearing);
  spec.nodes.push_back({.x = -0.0, .name = "housing", .number = 40, .rotating = false});
  spec.campbell.stop = 1000.0 / 7.0;
  spec.campbell.orders = {1, 2, 3};
  spec.runup.table = {{0.0, 0.0}, {1.0 / 3.0, 500.0 / 3.0}};
  spec.runup.springs = {"bearing"};
  spec.static_.gravity = "-z";

  const std::string text = write_toml(spec);
  const ModelSpec again = read_model_spec(text, "written");
  EXPECT_TRUE(again == spec) << text;
}

}  // namespace
}  // namespace feran::test_model_writer

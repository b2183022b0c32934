// Tests of spec/build_model for specs built in code: the same model as the file that
// says the same, and errors located by spec paths with values shown in the key's unit.

#include <feran/analyses/modal/modal.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/spec/build_model.hpp>

#include <gtest/gtest.h>

#include <string>

namespace feran::test_build_model {
namespace {

/// The Jeffcott rotor of tests/models/valid/jeffcott.toml, written in code.
ModelSpec jeffcott() {
  ModelSpec s;
  s.title = "Jeffcott rotor";
  s.options.shear_deformation = false;
  s.materials.push_back({.name = "massless steel", .E = 210e9, .G = {}, .nu = 0.3, .rho = 0.0, .loss_factor = 0.0});
  ShaftSpec shaft;
  shaft.material = "massless steel";
  shaft.start_node = "left";
  shaft.sections.push_back({.length = 0.25,
                            .outer_diameter = 0.012,
                            .inner_diameter = 0.0,
                            .outer_diameter_end = {},
                            .inner_diameter_end = {},
                            .axial_force = 0.0,
                            .material = {},
                            .elements = 1,
                            .end_node = "disk"});
  shaft.sections.push_back({.length = 0.25,
                            .outer_diameter = 0.012,
                            .inner_diameter = 0.0,
                            .outer_diameter_end = {},
                            .inner_diameter_end = {},
                            .axial_force = 0.0,
                            .material = {},
                            .elements = 1,
                            .end_node = "right"});
  s.shafts.push_back(shaft);
  RigidBodySpec disk;
  disk.name = "disk";
  disk.node = std::string("disk");
  disk.mass = 5.0;
  disk.Ja = 0.02;
  disk.Jp = 0.04;
  s.rigid_bodies.push_back(disk);
  // Named, not braced temporaries: GCC 12 at -O3 reports a false
  // -Wmaybe-uninitialized inside std::variant's move for the braced form.
  FixedSpec left, right;
  left.node = std::string("left");
  right.node = std::string("right");
  right.dofs = {"all"};
  s.fixed.push_back(left);
  s.fixed.push_back(right);
  s.unbalances.push_back(
      {.name = {}, .node = std::string("disk"), .mass = 0.001, .radius = 0.05, .phase = 0.0, .lever = 0.0});
  s.modal.speed = 0.0;
  s.modal.modes = 4;
  return s;
}

/// The SpecError build_model(spec) throws (path and message), or empty strings.
std::pair<std::string, std::string> error_of(const ModelSpec& spec) {
  try {
    (void)build_model(spec);
  } catch (const SpecError& e) {
    return {e.path(), e.message()};
  }
  return {};
}

TEST(BuildModel, CodeAndFileGiveTheSameModel) {
  const ModelFile file = read_model_file(std::string(FERAN_TEST_MODELS) + "/valid/jeffcott.toml");
  const ModelSpec code = jeffcott();
  // "250 mm" is 250/1000 and "1 g" 1/1000 in the file: the same doubles as 0.25, 0.001.
  EXPECT_TRUE(code == file.spec);
  const Model model = build_model(code);
  ASSERT_EQ(model.n_nodes(), file.model.n_nodes());
  ASSERT_EQ(model.elements.size(), file.model.elements.size());
  const ModalResult a = run_modal(model, 0.0), b = run_modal(file.model, 0.0);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (std::size_t i = 0; i < a.modes.size(); ++i)
    EXPECT_EQ(a.modes[i].frequency_hz, b.modes[i].frequency_hz);  // same matrices, same solver
}

TEST(BuildModel, ErrorsCarryASpecPathAndShowValuesInTheKeysUnit) {
  ModelSpec s = jeffcott();
  s.shafts[0].sections[1].length = -0.068;
  EXPECT_EQ(error_of(s), std::make_pair(std::string("shafts[0].sections[1].length"),
                                        std::string("'length' must be positive, got -68 mm")));

  s = jeffcott();
  s.shafts[0].sections[0].inner_diameter = 0.02;
  EXPECT_EQ(error_of(s).first, "shafts[0].sections[0].inner_diameter");
  EXPECT_EQ(error_of(s).second, "inner_diameter (20 mm) must be smaller than outer_diameter (12 mm)");

  s = jeffcott();
  s.rigid_bodies[0].node = std::string("dsik");
  EXPECT_EQ(error_of(s), std::make_pair(std::string("rigid_bodies[0].node"),
                                        std::string("node 'dsik' does not exist; did you mean 'disk'?")));

  s = jeffcott();
  s.options.gyroscopic = "lumpd";
  EXPECT_EQ(error_of(s).second,
            "'gyroscopic' must be \"consistent\" or \"lumped\", got \"lumpd\"; did you mean \"lumped\"?");

  s = jeffcott();
  s.campbell.start = 2.0 * pi * 50.0;
  s.campbell.stop = 2.0 * pi * 10.0;
  EXPECT_EQ(error_of(s), std::make_pair(std::string("campbell.stop"),
                                        std::string("'stop' (10 Hz) must be greater than 'start' (50 Hz)")));

  // A problem of the assembled model is located at the table that defines its node.
  s = jeffcott();
  s.fixed.pop_back();
  s.fixed.pop_back();
  const auto structure = error_of(s);
  EXPECT_EQ(structure.first.rfind("shafts[0]", 0), 0u) << structure.first;
  // The shaft is massless: unfixed, its end node has no mass.
  EXPECT_NE(structure.second.find("has no mass"), std::string::npos) << structure.second;

  ModelSpec empty;
  EXPECT_EQ(error_of(empty).first, "");
  EXPECT_NE(error_of(empty).second.find("the model has no nodes"), std::string::npos);

  // what() puts the path first, as a location.
  s = jeffcott();
  s.unbalances[0].mass = 0.0;
  try {
    (void)build_model(s);
    FAIL();
  } catch (const SpecError& e) {
    EXPECT_STREQ(e.what(), "unbalances[0].mass: 'mass' must be positive, got 0 kg");
  }
}

TEST(BuildModel, NonFiniteValuesAreRejected) {
  ModelSpec s = jeffcott();
  s.materials[0].E = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(error_of(s).first, "materials[0].E");
  EXPECT_NE(error_of(s).second.find("finite"), std::string::npos);
}

// A spec built in code has no file order: two profile forms of [runup] are reported
// in declaration order (constant speed, then ramp).
TEST(BuildModel, MixedRunupFormsWithoutASource) {
  ModelSpec s = jeffcott();
  s.runup.to = 100.0;
  s.runup.ramp_time = 1.0;
  s.runup.speed = 50.0;
  const auto [path, message] = error_of(s);
  EXPECT_EQ(path, "runup.to");
  EXPECT_NE(message.find("this [runup] mixes 'speed' and 'to'"), std::string::npos) << message;
}

}  // namespace
}  // namespace feran::test_build_model

// Tests of spec/parameters: paths by name, index and node name; values with units;
// the parts of coefficient laws; every listed parameter reads back and sets; errors
// with suggestions; and a value set by path changes the physics as a closed form
// says it must.

#include <feran/analyses/modal/modal.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/parameters.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace feran::test_parameters {
namespace {

const std::string examples = std::string(FERAN_SOURCE_DIR) + "/examples";
const std::string models = FERAN_TEST_MODELS;

ModelSpec spec_of(const std::string& path) { return read_model_file(path).spec; }

/// The message of the ParameterError that @p f throws ("" when it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, GetByNameAndIndex) {
  const ModelSpec spec = spec_of(examples + "/01_internal_damping/model.toml");
  // Converted once by the reader ("210 GPa" → 210e9 exactly): exact comparisons.
  EXPECT_EQ(get_parameter(spec, "materials[steel].E").value, 210e9);
  EXPECT_EQ(get_parameter(spec, "materials[0].E").value, 210e9);
  EXPECT_EQ(get_parameter(spec, "shafts[0].sections[0].outer_diameter").value, 6.0 / 1000.0);
  EXPECT_EQ(get_parameter(spec, "rigid_bodies[rotor].mass").value, 9.1);
  const Parameter e = get_parameter(spec, "materials[steel].E");
  EXPECT_EQ(e.text(), "210 GPa");
  EXPECT_EQ(e.quantity, Quantity::pressure);
}

TEST(Parameters, SetWithUnitsAndBareSI) {
  ModelSpec spec = spec_of(examples + "/02_centrifuge/model.toml");
  set_parameter(spec, "springs[bearing k12].ky", "2e7 N/m");
  EXPECT_EQ(*spec.springs[0].coefficients[spring::ky], SpeedCoefficient(2e7));
  set_parameter(spec, "springs[bearing k12].ky", "30 kN/mm");
  EXPECT_EQ(*spec.springs[0].coefficients[spring::ky], SpeedCoefficient(3e7));
  set_parameter(spec, "shafts[0].sections[1].outer_diameter", "12 mm");
  EXPECT_EQ(spec.shafts[0].sections[1].outer_diameter, 12.0 / 1000.0);
  set_parameter(spec, "shafts[0].sections[1].elements", "8");
  EXPECT_EQ(spec.shafts[0].sections[1].elements, 8);
  set_parameter(spec, "materials[steel].rho", 7800.0);
  EXPECT_EQ(spec.materials[0].rho, 7800.0);
  // An absent optional key is created.
  EXPECT_FALSE(spec.campbell.start.has_value() && *spec.campbell.start == 2.0 * pi * 5.0);
  set_parameter(spec, "campbell.start", "5 Hz");
  EXPECT_DOUBLE_EQ(*spec.campbell.start, 2.0 * pi * 5.0);
  set_parameter(spec, "springs[bearing k12].kyz", "1e5 N/m");
  EXPECT_EQ(*spec.springs[0].coefficients[spring::kyz], SpeedCoefficient(1e5));
}

TEST(Parameters, PartsOfCoefficientLaws) {
  ModelSpec spec = spec_of(examples + "/02_centrifuge/model_arctan.toml");
  EXPECT_EQ(get_parameter(spec, "springs[foot k11].ky.f_as").value, 3.98);
  EXPECT_EQ(get_parameter(spec, "springs[foot k11].ky").value, 9000.0);  // the arctan's value
  set_parameter(spec, "springs[foot k11].ky.f_as", "5 Hz");
  set_parameter(spec, "springs[foot k11].ky.c1", "0.8");
  const auto& law = std::get<SpeedCoefficient::Arctan>(spec.springs[2].coefficients[spring::ky]->law());
  EXPECT_EQ(law.f_as, 5.0);
  EXPECT_EQ(law.c1, 0.8);
  EXPECT_EQ(law.value, 9000.0);  // the other parts are kept

  ModelSpec step = spec_of(examples + "/02_centrifuge/model_step.toml");
  const std::vector<Parameter> all = list_parameters(step);
  const auto has = [&](const std::string& suffix) {
    return std::any_of(all.begin(), all.end(),
                       [&](const Parameter& p) { return p.path.size() >= suffix.size() && p.path.ends_with(suffix); });
  };
  EXPECT_TRUE(has(".ky.below"));
  EXPECT_TRUE(has(".ky.at"));

  // A frequency table: values[speed][frequency] with speeds, values[frequency] without.
  ModelSpec grid = spec_of(models + "/valid/everything.toml");
  EXPECT_EQ(get_parameter(grid, "springs[bearing b].kyz.values[1][0]").value, -1e4);
  EXPECT_EQ(get_parameter(grid, "springs[bearing b].cy.values[2]").value, 50.0);
  set_parameter(grid, "springs[bearing b].kyz.values[1][1]", "5 kN/m");
  set_parameter(grid, "springs[bearing b].cy.frequencies[1]", "60 Hz");
  const auto& t = std::get<SpeedCoefficient::FrequencyTable>(grid.springs[1].coefficients[spring::kyz]->law());
  EXPECT_EQ(t.values, (std::vector<Real>{1e4, 2e4, -1e4, 5e3}));  // row-major, the rest kept
  const auto& row = std::get<SpeedCoefficient::FrequencyTable>(grid.springs[1].coefficients[spring::cy]->law());
  EXPECT_DOUBLE_EQ(row.frequencies[1], 2.0 * 3.141592653589793 * 60.0);
  const std::string whole = error_of([&] { (void)get_parameter(grid, "springs[bearing b].kyz"); });
  EXPECT_NE(whole.find("follows a frequency table law: name an entry"), std::string::npos) << whole;
  const std::string one = error_of([&] { (void)get_parameter(grid, "springs[bearing b].kyz.values[1]"); });
  EXPECT_NE(one.find("values[0][0]"), std::string::npos) << one;
}

TEST(Parameters, EveryListedParameterReadsBackAndSetsItself) {
  for (const std::string& path :
       {examples + "/01_internal_damping/model.toml", examples + "/02_centrifuge/model_arctan.toml",
        examples + "/03_coulomb_friction/model_5_2N.toml", models + "/valid/everything.toml"}) {
    SCOPED_TRACE(path);
    const ModelSpec spec = spec_of(path);
    const std::vector<Parameter> params = list_parameters(spec);
    EXPECT_GE(params.size(), 20u);
    ModelSpec copy = spec;
    for (const Parameter& p : params) {
      SCOPED_TRACE(p.path);
      EXPECT_EQ(get_parameter(spec, p.path).value, p.value);
      // Setting a value to itself, in SI and as its text, changes nothing: the text is
      // exact (the writer's rule), and the path names the same number it lists.
      set_parameter(copy, p.path, p.value);
      set_parameter(copy, p.path, p.text());
    }
    EXPECT_TRUE(copy == spec);
  }
}

TEST(Parameters, ErrorsNameThePartAndSuggest) {
  ModelSpec spec = spec_of(examples + "/02_centrifuge/model.toml");
  EXPECT_NE(error_of([&] {
              set_parameter(spec, "materails[steel].E", "1 GPa");
            }).find("there is no table 'materails'; did you mean 'materials'?"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              set_parameter(spec, "materials[stel].E", "1 GPa");
            }).find("'materials' has no entry named 'stel'; did you mean 'steel'?"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              set_parameter(spec, "springs[bearing k12].kyy", "1 N/m");
            }).find("has no key 'kyy'; did you mean 'ky'?"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_parameter(spec, "springs[bearing k12].ky", "1 kg"); }).find("unit 'kg'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_parameter(spec, "shafts[0].sections[0].elements", "2.5"); }).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              set_parameter(spec, "shafts[7].x", "1 mm");
            }).find("'shafts' has 1 entries, indices 0 to 0; got 7"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_parameter(spec, "materials[steel].name", "1"); }).find("is not a number"),
            std::string::npos);
  EXPECT_NE(error_of([&] { apply_assignment(spec, "campbell.stop"); }).find("expected PATH=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { (void)get_parameter(spec, "response.loss_factor"); }).find("not given"), std::string::npos);
}

TEST(Parameters, NodeNameNamesAnUnnamedEntry) {
  ModelSpec spec = spec_of(models + "/valid/jeffcott.toml");
  // [[unbalances]] at node "disk" has no name: it is found by its node's name.
  set_parameter(spec, "unbalances[disk].mass", "2 g");
  EXPECT_EQ(spec.unbalances[0].mass, 2.0 / 1000.0);
}

// The Jeffcott rotor of jeffcott.toml: a disk of mass m at mid-span of a massless
// clamped–clamped Euler–Bernoulli shaft of length L, k = 192·E·I/L³. Its translation
// and tilt decouple at mid-span, so the lowest lateral frequency is exactly √(k/m)/2π
// (cubic elements are exact for a point load; the eigensolver's round-off: 1e-9).
TEST(Parameters, ChangedByPathTheCriticalSpeedFollowsTheClosedForm) {
  ModelSpec spec = spec_of(models + "/valid/jeffcott.toml");
  apply_assignment(spec, "shafts[0].sections[0].outer_diameter=16 mm");
  apply_assignment(spec, "shafts[0].sections[1].outer_diameter=16mm");
  apply_assignment(spec, "rigid_bodies[disk].mass=8 kg");
  apply_assignment(spec, "materials[massless steel].E=200 GPa");
  const Model model = build_model(spec);
  const Real d = 0.016, L = 0.5, E = 200e9, m = 8.0;
  const Real I = pi * std::pow(d, 4) / 64.0;
  const Real expected = std::sqrt(192.0 * E * I / (L * L * L) / m) / (2.0 * pi);
  const ModalResult r = run_modal(model, 0.0);
  const auto lateral =
      std::find_if(r.modes.begin(), r.modes.end(), [](const Mode& mode) { return mode.type == ModeType::lateral; });
  ASSERT_NE(lateral, r.modes.end());
  EXPECT_NEAR(lateral->frequency_hz / expected, 1.0, 1e-9);
}

TEST(Parameters, SetValuesSurviveTheWriter) {
  ModelSpec spec = spec_of(examples + "/02_centrifuge/model_arctan.toml");
  set_parameter(spec, "springs[foot k11].ky.f_as", "4.5 Hz");
  set_parameter(spec, "rigid_bodies[rotor].Jp", "0.011 kg*m^2");
  EXPECT_TRUE(read_model_spec(write_toml(spec), "written") == spec);
}

}  // namespace
}  // namespace feran::test_parameters

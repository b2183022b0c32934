// The static analysis's study quantities read the same numbers as its other doors:
// each equals, bit for bit, what run_static() gives for the design's own [static]
// settings; and a design whose equilibrium is unstable has none.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <feran/analyses/static/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/study/quantity.hpp>

namespace feran::test_static_quantities {
namespace {

QuantitySpec quantity(const std::string& kind) {
  QuantitySpec q;
  q.name = kind;
  q.kind = kind;
  return q;
}

Real lateral(const StaticResult& r, Index node) { return std::hypot(r.q(6 * node + 1), r.q(6 * node + 2)); }

TEST(StaticQuantities, EqualTheStaticResult) {
  // The centrifuge on its foot springs, under gravity along its [static] table's.
  const ModelFile file = read_model_file(FERAN_SOURCE_DIR "/examples/02_centrifuge/model.toml");
  const StaticResult r = run_static(file.model, static_options(file));
  ASSERT_TRUE(r.info.converged());
  std::vector<QuantitySpec> qs{quantity("static_deflection"), quantity("static_deflection"), quantity("static_stress"),
                               quantity("static_spring_force"), quantity("static_spring_force")};
  qs[1].probe = NodeRef(std::string("rotor"));
  qs[4].spring = "bearing k12";
  const std::vector<Real> v = evaluate_quantities(file.spec, file.model, qs);

  Real deflection = 0, stress = 0, force = 0, k12 = -1;
  for (Index n = 0; n < file.model.n_nodes(); ++n) deflection = std::max(deflection, lateral(r, n));
  for (const SectionStress& s : r.stresses) stress = std::max(stress, s.von_mises);
  for (const auto& [e, f] : r.springs) {
    force = std::max(force, std::hypot(f[1], f[2]));
    if (file.model.elements[static_cast<std::size_t>(e)].label() == "bearing k12") k12 = std::hypot(f[1], f[2]);
  }
  EXPECT_GT(deflection, 0.0);
  EXPECT_EQ(v[0], deflection);
  EXPECT_EQ(v[1], lateral(r, file.model.find_node(std::string("rotor"))));
  EXPECT_EQ(v[2], stress);
  EXPECT_EQ(v[3], force);
  EXPECT_EQ(v[4], k12);
  // The rows say what they are.
  EXPECT_EQ(quantity_unit(qs[0]), Quantity::length);
  EXPECT_EQ(quantity_unit(qs[2]), Quantity::pressure);
  EXPECT_EQ(quantity_unit(qs[3]), Quantity::force);
}

TEST(StaticQuantities, BearingValuesAtTheEquilibriumAndNoneWhereItIsUnstable) {
  // The oil-whip rotor: stable at its [static] speed, 3000 rpm; unstable (flutter) at
  // 100 Hz, where the study refuses every static quantity with the reason.
  const ModelFile file = read_model_file(FERAN_SOURCE_DIR "/examples/06_oil_whip/model.toml");
  const StaticResult r = run_static(file.model, static_options(file));
  ASSERT_FALSE(r.stability.unstable);
  QuantitySpec smallest = quantity("min_static_bearing_value"), largest = quantity("max_static_bearing_value");
  smallest.value = largest.value = "eccentricity_ratio";
  const std::vector<Real> v = evaluate_quantities(file.spec, file.model, std::vector<QuantitySpec>{smallest, largest});
  std::vector<Real> expected;
  for (const auto& data : r.support_data)
    for (const OperatingValue& o : data)
      if (o.name == "eccentricity_ratio") expected.push_back(o.value);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(v[0], *std::min_element(expected.begin(), expected.end()));
  EXPECT_EQ(v[1], *std::max_element(expected.begin(), expected.end()));

  ModelSpec fast = file.spec;
  (void)set_parameter(fast, "static.speed", "100 Hz");
  const ModelFile whirling = build_model_file(fast, {}, "fast");
  try {
    (void)evaluate_quantities(whirling.spec, whirling.model, std::vector<QuantitySpec>{quantity("static_deflection")});
    FAIL() << "a static quantity of an unstable equilibrium";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not stay at its static equilibrium"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feran::test_static_quantities

namespace feran::test_static_quantities {
namespace {

TEST(QuantityRows, EveryRowIsDocumentedOnceAndNamedOnce) {
  // docs/study-format.md's table names every kind of the table of quantities (a row
  // added without its documentation fails here), and no two rows share a name.
  std::ifstream in(FERAN_SOURCE_DIR "/docs/study-format.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  std::set<std::string_view> names;
  for (const QuantityRow& row : quantity_rows()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    EXPECT_NE(doc.find("`" + std::string(row.name) + "`"), std::string::npos) << row.name;
    EXPECT_NE(row.evaluate, nullptr) << row.name;
  }
  EXPECT_NE(quantity_row("static_deflection"), nullptr);
  EXPECT_EQ(quantity_row("static_deflection")->analysis, "static");
}

}  // namespace
}  // namespace feran::test_static_quantities

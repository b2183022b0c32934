// Tests of io/model_reader on the valid fixtures in tests/models/valid/ and on
// small models written inline.
//
// Tolerances. Values written in a unit are converted by one multiplication and one
// division (e.g. "68 mm" is 68/1000, "30 Hz" is 30·2π), the same arithmetic the
// expectations below spell out, so they agree to rounding: EXPECT_DOUBLE_EQ (4 ulp).
// Node positions are sums of a few such lengths, hence EXPECT_NEAR with 1e-15 m,
// about ten ulp of the 0.1 m positions. Element matrices are compared with exact
// equality because reader and test build the same elements from the same doubles.

#include <feran/analyses/runup/analysis.hpp>
#include <feran/elements/rigid_body.hpp>
#include <feran/elements/rotating_damper.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/elements/timoshenko_beam.hpp>
#include <feran/forces/coulomb_friction.hpp>
#include <feran/forces/fluid_film_bearing.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/forces/static_load.hpp>
#include <feran/forces/unbalance.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/modal/analysis.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/io/model_reader.hpp>

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace feran::test_model_reader {
namespace {

const std::string models = FERAN_TEST_MODELS;

/// 1-based number of the first line of @p path that contains @p needle, or 0.
int line_of(const std::string& path, const std::string& needle) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

const Element& element(const Model& m, const std::string& label) {
  for (const Element& e : m.elements)
    if (e.label() == label) return e;
  throw std::runtime_error("no element labelled " + label);
}

template <class E>
const E& element_as(const Model& m, const std::string& label) {
  const E* e = element(m, label).target<E>();
  if (e == nullptr) throw std::runtime_error(label + " has another type");
  return *e;
}

Index element_index(const Model& m, const std::string& label) {
  for (std::size_t i = 0; i < m.elements.size(); ++i)
    if (m.elements[i].label() == label) return static_cast<Index>(i);
  throw std::runtime_error("no element labelled " + label);
}

/// The forces of type F of @p m, in model order, with their labels.
template <class F>
std::vector<std::pair<F, std::string>> forces_of(const Model& m) {
  std::vector<std::pair<F, std::string>> out;
  for (const Force& f : m.forces)
    if (const F* x = f.target<F>()) out.emplace_back(*x, f.label());
  return out;
}

Index index_of(const Model& m, const std::string& name) {
  const Index i = m.find_node(name);
  if (i < 0) throw std::runtime_error("no node named " + name);
  return i;
}

// The analysis defaults a file states reach an analysis through the settings
// functions (analyses/settings.hpp), as for every other caller.
HarmonicOptions response_of(const ModelFile& f, const ResponseSpec& request = {}) {
  return response_options(f, request);
}
TransientOptions runup_of(const ModelFile& f) { return runup_options(f); }
StaticOptions static_of(const ModelFile& f) { return static_options(f); }

constexpr Real hz = 2.0 * pi;          // rad/s per Hz
constexpr Real rpm = 2.0 * pi / 60.0;  // rad/s per rpm

// ---------------------------------------------------------------------------------
// everything.toml: every table, every key form and every coefficient law

class EverythingModel : public ::testing::Test {
 protected:
  // Read once for all tests of the suite; a reading error fails each test with its message.
  static void SetUpTestSuite() {
    try {
      file_ = new ModelFile(read_model_file(path_));
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }
  static void TearDownTestSuite() {
    delete file_;
    file_ = nullptr;
  }
  void SetUp() override { ASSERT_NE(file_, nullptr) << error_; }
  static inline const std::string path_ = models + "/valid/everything.toml";
  static inline ModelFile* file_ = nullptr;
  static inline std::string error_;
  const Model& m() const { return file_->model; }
};

TEST_F(EverythingModel, TitleAndPath) {
  EXPECT_EQ(file_->title, "Every table");
  EXPECT_EQ(m().name, "Every table");
  EXPECT_EQ(file_->path, path_);
}

/// The materials of the model's shaft elements, by name (each once, in element order).
std::vector<Material> shaft_materials(const Model& m) {
  std::vector<Material> out;
  for (const Element& e : m.elements)
    if (const auto* beam = e.target<TimoshenkoBeam>())
      if (std::none_of(out.begin(), out.end(), [&](const Material& x) { return x.name == beam->material().name; }))
        out.push_back(beam->material());
  return out;
}

// [options] reach every shaft element (the model keeps only free_motions itself).
TEST_F(EverythingModel, Options) {
  int beams = 0;
  for (const Element& e : m().elements)
    if (const auto* beam = e.target<TimoshenkoBeam>()) {
      ++beams;
      EXPECT_FALSE(beam->options().shear_deformation);
      EXPECT_EQ(beam->options().gyroscopic, GyroscopicForm::lumped);
      // "0.1 ms" on rotating shafts, none on the others.
      EXPECT_DOUBLE_EQ(beam->options().damping_beta, beam->options().rotating ? 0.1 / 1000.0 : 0.0);
    }
  EXPECT_GT(beams, 0);
  EXPECT_EQ(m().free_motions, std::vector<FreeMotion>{FreeMotion::torsion});
}

TEST_F(EverythingModel, Materials) {
  const std::vector<Material> materials = shaft_materials(m());
  ASSERT_EQ(materials.size(), 2u);
  const Material& steel = materials[0];
  EXPECT_EQ(steel.name, "steel");
  EXPECT_DOUBLE_EQ(steel.E, 210e9);
  EXPECT_DOUBLE_EQ(steel.G, 210e9 / (2.0 * 1.3));  // from nu = 0.3
  EXPECT_DOUBLE_EQ(steel.rho, 7850.0);             // "7.85 g/cm^3"
  EXPECT_EQ(steel.loss_factor, 0.002);
  const Material& aluminium = materials[1];
  EXPECT_EQ(aluminium.name, "aluminium");
  EXPECT_DOUBLE_EQ(aluminium.E, 7e10);
  EXPECT_DOUBLE_EQ(aluminium.G, 26e9);
  EXPECT_DOUBLE_EQ(aluminium.rho, 2700.0);
  EXPECT_EQ(aluminium.loss_factor, 0.0);  // default
}

TEST_F(EverythingModel, NodeNumbersNamesPositions) {
  struct Expected {
    int number;
    const char* name;
    Real x;
    bool rotating;
  };
  // Shaft "rotor" from x = 10 mm: 68 mm in 2 elements, 30 mm in 3; the sleeve from
  // 0, one 100 mm element; then [[nodes]]: next free number 9, explicit 20, and 21.
  const std::vector<Expected> expected = {
      {1, "drive", 0.010, true},      {2, "", 0.010 + 0.034, true}, {3, "bearing a", 0.078, true},
      {4, "", 0.088, true},           {5, "", 0.098, true},         {6, "tip", 0.108, true},
      {7, "sleeve a", 0.0, false},    {8, "", 0.1, false},          {9, "stator a", 0.078, false},
      {20, "stator b", 0.108, false}, {21, "foot", 0.090, false},
  };
  ASSERT_EQ(m().nodes.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(m().nodes[i].number, expected[i].number);
    EXPECT_EQ(m().nodes[i].name, expected[i].name);
    EXPECT_NEAR(m().nodes[i].x, expected[i].x, 1e-15);
    EXPECT_EQ(m().nodes[i].rotating, expected[i].rotating);
  }
}

TEST_F(EverythingModel, NodeLocationsPointAtTheDefinitions) {
  ASSERT_EQ(file_->node_locations.size(), m().nodes.size());
  for (const SourceLocation& at : file_->node_locations) EXPECT_EQ(at.file, path_);
  // The first node of a shaft is defined by its [[shafts]] table, the nodes of a
  // section by the section, extra nodes by their [[nodes]] table.
  EXPECT_EQ(file_->node_locations[0].line, line_of(path_, "name = \"rotor\"") - 1);
  const int first_section = line_of(path_, "length = \"68 mm\"") - 1;
  EXPECT_EQ(file_->node_locations[1].line, first_section);
  EXPECT_EQ(file_->node_locations[2].line, first_section);
  EXPECT_EQ(file_->node_locations[7].line, line_of(path_, "sections = [{"));
  EXPECT_EQ(file_->node_locations[8].line, line_of(path_, "name = \"stator a\"") - 1);
}

TEST_F(EverythingModel, ShaftElements) {
  // 2 + 3 elements of the rotor, 1 of the sleeve, 3 rigid bodies, 3 springs,
  // 2 rotating dampers.
  EXPECT_EQ(m().elements.size(), 14u);
  int n_shaft = 0;
  for (const Element& e : m().elements) n_shaft += e.kind() == "shaft" ? 1 : 0;
  EXPECT_EQ(n_shaft, 6);

  const auto& first = element_as<TimoshenkoBeam>(m(), "shaft rotor section 1 element 1");
  EXPECT_EQ(first.node_a(), 0);
  EXPECT_EQ(first.node_b(), 1);
  EXPECT_DOUBLE_EQ(first.length(), 0.068 / 2.0);
  EXPECT_DOUBLE_EQ(first.section().outer_diameter, 0.020);
  EXPECT_EQ(first.section().inner_diameter, 0.0);
  EXPECT_EQ(first.material().name, "steel");
  EXPECT_FALSE(first.options().shear_deformation);
  EXPECT_EQ(first.options().gyroscopic, GyroscopicForm::lumped);
  EXPECT_TRUE(first.options().rotating);
  EXPECT_DOUBLE_EQ(first.options().damping_beta, 1e-4);
  EXPECT_EQ(first.options().loss_factor, 0.002);  // the section's material (steel)
  EXPECT_EQ(first.local_matrices(OperatingPoint{}).loss_factor, 0.002);

  const auto& hollow = element_as<TimoshenkoBeam>(m(), "shaft rotor section 2 element 3");
  EXPECT_EQ(hollow.node_a(), 4);
  EXPECT_EQ(hollow.node_b(), 5);
  EXPECT_DOUBLE_EQ(hollow.length(), 0.03 / 3.0);
  EXPECT_DOUBLE_EQ(hollow.section().outer_diameter, 0.013);
  EXPECT_DOUBLE_EQ(hollow.section().inner_diameter, 0.005);
  EXPECT_EQ(hollow.material().name, "aluminium");
  EXPECT_EQ(hollow.options().loss_factor, 0.0);  // aluminium has none

  // An unnamed shaft is labelled by its index; a non-rotating one has no rotating damping.
  const auto& sleeve = element_as<TimoshenkoBeam>(m(), "shaft 2 section 1 element 1");
  EXPECT_EQ(sleeve.node_a(), 6);
  EXPECT_EQ(sleeve.node_b(), 7);
  EXPECT_DOUBLE_EQ(sleeve.section().inner_diameter, 0.040);
  EXPECT_FALSE(sleeve.options().rotating);
  EXPECT_EQ(sleeve.options().damping_beta, 0.0);
  EXPECT_EQ(sleeve.options().loss_factor, 0.002);  // hysteretic damping is not only for rotors
}

TEST_F(EverythingModel, RigidBodies) {
  const auto& rotor = element_as<RigidBody>(m(), "rotor mass");
  EXPECT_EQ(rotor.node(), index_of(m(), "tip"));
  EXPECT_DOUBLE_EQ(rotor.properties().mass, 1.93);
  EXPECT_DOUBLE_EQ(rotor.properties().transverse_inertia, 0.0063);
  EXPECT_DOUBLE_EQ(rotor.properties().polar_inertia, 0.0104);  // "10400 kg*mm^2"
  EXPECT_DOUBLE_EQ(rotor.properties().offset, 0.005);
  EXPECT_TRUE(rotor.rotating());  // default: the node's flag

  // Disk form, by hand: annulus 60/20 mm, 10 mm wide, steel 7850 kg/m³.
  const auto& disk = element_as<RigidBody>(m(), "disk");
  const Real ro = 0.030, ri = 0.010, width = 0.010, rho = 7850.0;
  const Real mass = rho * pi * (ro * ro - ri * ri) * width;  // 0.19729 kg
  EXPECT_EQ(disk.node(), 1);                                 // node = 2
  EXPECT_NEAR(disk.properties().mass, mass, 1e-12 * mass);
  EXPECT_NEAR(disk.properties().polar_inertia, 0.5 * mass * (ro * ro + ri * ri), 1e-15);
  EXPECT_NEAR(disk.properties().transverse_inertia, 0.25 * mass * (ro * ro + ri * ri) + mass * width * width / 12.0,
              1e-15);
  EXPECT_EQ(disk.properties().offset, 0.0);

  const auto& stator = element_as<RigidBody>(m(), "rigid body 3");  // default label
  EXPECT_EQ(stator.node(), index_of(m(), "stator a"));
  EXPECT_FALSE(stator.rotating());
  EXPECT_EQ(stator.properties().mass, 5.0);
}

TEST_F(EverythingModel, SpringsWithEveryLaw) {
  using Law = SpeedCoefficient;
  const auto& a = element_as<SpringDamper>(m(), "bearing a");
  EXPECT_EQ(a.node_a(), index_of(m(), "bearing a"));
  EXPECT_EQ(a.node_b(), index_of(m(), "stator a"));
  const SpringDamperCoefficients& ca = a.coefficients();
  EXPECT_EQ(ca.k[0], SpeedCoefficient(1e6));  // kx = "1 MN/m"
  EXPECT_EQ(ca.k[1], SpeedCoefficient(6e7));  // ky = "6e7 N/m"
  EXPECT_EQ(ca.k[2], SpeedCoefficient(6e7));  // kz = 6e7
  EXPECT_EQ(ca.kyz, SpeedCoefficient(-1e5));  // cross terms may be negative
  EXPECT_TRUE(ca.kzy.is_zero());
  EXPECT_EQ(ca.loss_factor, 0.1);
  EXPECT_EQ(a.local_matrices(OperatingPoint{}).loss_factor, 0.1);
  const auto* table = std::get_if<Law::Table>(&ca.c[1].law());
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->speeds.size(), 3u);
  EXPECT_EQ(table->speeds[0], 0.0);
  EXPECT_DOUBLE_EQ(table->speeds[1], 50.0 * hz);
  EXPECT_DOUBLE_EQ(table->speeds[2], 6000.0 * rpm);
  ASSERT_EQ(table->values.size(), 3u);
  EXPECT_EQ(table->values[0], 100.0);
  EXPECT_EQ(table->values[1], 80.0);
  EXPECT_DOUBLE_EQ(table->values[2], 60.0);  // "0.06 kN*s/m"

  const auto& b = element_as<SpringDamper>(m(), "bearing b");
  EXPECT_EQ(b.node_b(), index_of(m(), "stator b"));
  const SpringDamperCoefficients& cb = b.coefficients();
  EXPECT_EQ(cb.loss_factor, 0.0);  // default
  const auto* step = std::get_if<Law::Step>(&cb.k[1].law());
  ASSERT_NE(step, nullptr);
  EXPECT_EQ(step->below, 6e7);
  EXPECT_EQ(step->above, 6e6);
  EXPECT_DOUBLE_EQ(step->at, 2000.0 * rpm);
  const auto* arctan = std::get_if<Law::Arctan>(&cb.k[2].law());
  ASSERT_NE(arctan, nullptr);
  EXPECT_EQ(*arctan, (Law::Arctan{6e7, 3.98, 0.55, 0.9, 0.1}));  // default c0, c1, c2
  const auto* hz_table = std::get_if<Law::Table>(&cb.c[2].law());
  ASSERT_NE(hz_table, nullptr);  // bare speeds in speed_unit = "Hz"
  EXPECT_EQ(hz_table->speeds[0], 0.0);
  EXPECT_DOUBLE_EQ(hz_table->speeds[1], 100.0 * hz);
  const auto* cross = std::get_if<Law::Arctan>(&cb.czy.law());
  ASSERT_NE(cross, nullptr);
  EXPECT_EQ(*cross, (Law::Arctan{-5.0, 10.0, 0.5, 1.0, 0.2}));
  const auto* hz_step = std::get_if<Law::Step>(&cb.k[4].law());  // kry
  ASSERT_NE(hz_step, nullptr);
  EXPECT_DOUBLE_EQ(hz_step->at, 50.0 * hz);
  const auto* over_frequency = std::get_if<Law::FrequencyTable>(&cb.c[1].law());  // cy
  ASSERT_NE(over_frequency, nullptr);
  EXPECT_TRUE(over_frequency->speeds.empty());  // the same at every speed
  EXPECT_DOUBLE_EQ(over_frequency->frequencies[2], 100.0 * hz);
  EXPECT_EQ(over_frequency->values, (std::vector<Real>{40.0, 45.0, 50.0}));
  const auto* grid = std::get_if<Law::FrequencyTable>(&cb.kyz.law());  // rows by speed
  ASSERT_NE(grid, nullptr);
  EXPECT_DOUBLE_EQ(grid->speeds[1], 3000.0 * rpm);
  EXPECT_DOUBLE_EQ(grid->frequencies[1], 100.0 * hz);
  EXPECT_EQ(grid->values, (std::vector<Real>{1e4, 2e4, -1e4, 0.0}));
  EXPECT_TRUE(b.frequency_dependent());
  EXPECT_FALSE(a.frequency_dependent());

  const auto& foot = element_as<SpringDamper>(m(), "spring 3");  // default label
  EXPECT_EQ(foot.node_b(), index_of(m(), "foot"));
  const SpringDamperCoefficients& cf = foot.coefficients();
  for (int d = 0; d < 3; ++d) EXPECT_EQ(cf.k[static_cast<std::size_t>(d)], SpeedCoefficient(9000.0));
  for (int d = 3; d < 6; ++d) EXPECT_EQ(cf.k[static_cast<std::size_t>(d)], SpeedCoefficient(180.0));
  EXPECT_EQ(cf.c[0], SpeedCoefficient(75.0));
  EXPECT_EQ(cf.c[3], SpeedCoefficient(0.06));
  EXPECT_EQ(cf.c[4], SpeedCoefficient(0.06));
  EXPECT_TRUE(cf.c[5].is_zero());
}

TEST_F(EverythingModel, RotatingDampersAndFriction) {
  const auto& internal = element_as<RotatingDamper>(m(), "internal");
  EXPECT_EQ(internal.node_a(), 0);
  EXPECT_FALSE(internal.node_b());  // to = "axis" by default
  EXPECT_EQ(internal.coefficients().translational, 638.0);
  EXPECT_EQ(internal.coefficients().rotational, 0.57);
  EXPECT_EQ(internal.coefficients().axial, 0.0);
  const auto& second = element_as<RotatingDamper>(m(), "rotating damper 2");
  EXPECT_EQ(second.node_a(), 5);
  EXPECT_EQ(second.node_b(), 3);
  EXPECT_EQ(second.coefficients().axial, 10.0);
  EXPECT_EQ(second.coefficients().torsional, 0.1);

  const auto friction = forces_of<CoulombFriction>(m());
  ASSERT_EQ(friction.size(), 2u);
  const CoulombFriction& rub = friction[0].first;
  EXPECT_EQ(friction[0].second, "rub");
  EXPECT_EQ(rub.node_a, 5);
  EXPECT_FALSE(rub.node_b);
  EXPECT_EQ(rub.force_amplitude, 5.2);
  EXPECT_EQ(rub.moment_amplitude, 0.1);
  EXPECT_DOUBLE_EQ(rub.epsilon_t, 2e-4);  // "0.2 mm/s"
  EXPECT_EQ(rub.epsilon_r, 0.002);
  const CoulombFriction& second_friction = friction[1].first;
  EXPECT_EQ(friction[1].second, "friction 2");
  EXPECT_EQ(second_friction.node_b, 4);
  EXPECT_DOUBLE_EQ(second_friction.force_amplitude, 1.0);  // "0.001 kN"
  EXPECT_EQ(second_friction.epsilon_t, 1e-4);              // defaults
  EXPECT_EQ(second_friction.epsilon_r, 1e-3);
}

TEST_F(EverythingModel, JournalBearings) {
  const auto bearings = forces_of<FluidFilmBearing>(m());
  ASSERT_EQ(bearings.size(), 2u);
  const FluidFilmBearing& a = bearings[0].first;
  EXPECT_EQ(bearings[0].second, "oil film");
  EXPECT_EQ(a.node_a, m().find_node(std::string("tip")));
  EXPECT_FALSE(a.node_b);  // the ground
  EXPECT_DOUBLE_EQ(a.geometry.diameter, 0.05);
  EXPECT_DOUBLE_EQ(a.geometry.length, 0.02);
  EXPECT_DOUBLE_EQ(a.geometry.clearance, 5e-5);   // "50 um"
  EXPECT_DOUBLE_EQ(a.geometry.viscosity, 0.028);  // "28 cP"
  EXPECT_EQ(a.theory, FilmTheory::short_bearing);
  const FluidFilmBearing& b = bearings[1].first;
  EXPECT_EQ(bearings[1].second, "journal bearing 2");
  EXPECT_EQ(b.node_b, m().find_node(std::string("stator a")));
  EXPECT_EQ(b.theory, FilmTheory::long_bearing);
  EXPECT_EQ(b.dofs().size(), 4u);
}

TEST_F(EverythingModel, ConstraintsAndUnbalances) {
  ASSERT_EQ(m().links.size(), 1u);
  EXPECT_EQ(m().links[0].leader, index_of(m(), "stator a"));
  EXPECT_EQ(m().links[0].followers, std::vector<Index>{index_of(m(), "stator b")});

  // Two entries for node 7 ("sleeve a" and 7) are merged into one.
  ASSERT_EQ(m().fixed.size(), 2u);
  EXPECT_EQ(m().fixed[0].node, index_of(m(), "foot"));
  EXPECT_EQ(m().fixed[1].node, index_of(m(), "sleeve a"));
  for (const FixedDofs& f : m().fixed)
    for (const bool held : f.dofs) EXPECT_TRUE(held);

  const auto unbalances = forces_of<Unbalance>(m());
  ASSERT_EQ(unbalances.size(), 2u);
  const Unbalance& u = unbalances[0].first;
  EXPECT_EQ(unbalances[0].second, "rotor unbalance");
  EXPECT_EQ(u.node, index_of(m(), "tip"));
  EXPECT_DOUBLE_EQ(u.mass, 0.003);
  EXPECT_DOUBLE_EQ(u.radius, 0.080);
  EXPECT_DOUBLE_EQ(u.phase, pi / 2.0);
  EXPECT_DOUBLE_EQ(u.lever, 0.005);
  const Unbalance& v = unbalances[1].first;
  EXPECT_EQ(unbalances[1].second, "unbalance 2");
  EXPECT_EQ(v.node, 1);
  EXPECT_EQ(v.phase, 0.0);
  EXPECT_EQ(v.lever, 0.0);
}

TEST_F(EverythingModel, AnalysisDefaults) {
  const ModalSettings modal = analysis_options<ModalAnalysis>(*file_, {}, file_key_name<ModalAnalysis>());
  EXPECT_DOUBLE_EQ(modal.speed, 30.0 * hz);
  EXPECT_EQ(modal.options.n_modes, 8);
  const CampbellOptions c = analysis_options<CampbellAnalysis>(*file_, {}, file_key_name<CampbellAnalysis>());
  ASSERT_EQ(c.speeds.size(), 51u);
  EXPECT_EQ(c.speeds.front(), 0.0);
  EXPECT_DOUBLE_EQ(c.speeds.back(), 200.0 * hz);
  EXPECT_EQ(c.n_modes, 6);
  EXPECT_EQ(c.orders, (std::vector<int>{1, 2}));
}

TEST_F(EverythingModel, HarmonicForces) {
  using Kind = HarmonicForce::Kind;
  const auto forces = forces_of<HarmonicForce>(m());
  ASSERT_EQ(forces.size(), 5u);
  const HarmonicForce& shaker = forces[0].first;
  EXPECT_EQ(forces[0].second, "shaker");
  EXPECT_EQ(shaker.node, index_of(m(), "stator a"));
  EXPECT_EQ(shaker.type, Kind::fixed);  // default
  EXPECT_EQ(shaker.direction, Dof::v);  // "y"
  EXPECT_EQ(shaker.amplitude, 10.0);
  EXPECT_DOUBLE_EQ(shaker.phase, pi / 6.0);  // "30 deg"

  const HarmonicForce& rotating = forces[1].first;
  EXPECT_EQ(forces[1].second, "force 2");  // default label
  EXPECT_EQ(rotating.node, index_of(m(), "tip"));
  EXPECT_EQ(rotating.type, Kind::rotating_force);
  EXPECT_EQ(rotating.amplitude, 2.5);
  EXPECT_EQ(rotating.phase, 0.0);  // default

  const HarmonicForce& moment = forces[2].first;
  EXPECT_EQ(moment.node, 3);  // node = 4
  EXPECT_EQ(moment.type, Kind::rotating_moment);
  EXPECT_EQ(moment.amplitude, 0.5);  // "0.5 N*m"
  EXPECT_EQ(moment.phase, 1.0);

  const HarmonicForce& tilt = forces[3].first;
  EXPECT_EQ(tilt.node, index_of(m(), "stator b"));
  EXPECT_EQ(tilt.direction, Dof::rz);
  EXPECT_EQ(tilt.amplitude, 3.0);  // "3 Nm": a moment for a rotational direction

  const HarmonicForce& axial = forces[4].first;
  EXPECT_EQ(axial.type, Kind::fixed);
  EXPECT_EQ(axial.direction, Dof::u);       // "x"
  EXPECT_DOUBLE_EQ(axial.amplitude, 10.0);  // "0.01 kN"
}

TEST_F(EverythingModel, StaticLoads) {
  const auto loads = forces_of<StaticLoad>(m());
  ASSERT_EQ(loads.size(), 2u);
  const StaticLoad& coupling = loads[0].first;
  EXPECT_EQ(loads[0].second, "coupling");
  EXPECT_EQ(coupling.node, index_of(m(), "drive"));
  // Indexed by Dof: fx, fy, fz, mx, my, mz.
  EXPECT_EQ(coupling.load, (std::array<Real, dofs_per_node>{0.0, 0.0, -20.0, 0.0, 0.5, 0.0}));
  const StaticLoad& second = loads[1].first;
  EXPECT_EQ(loads[1].second, "static load 2");
  EXPECT_EQ(second.node, 4);  // node = 5
  EXPECT_EQ(second.load[0], 1.0);
  EXPECT_DOUBLE_EQ(second.load[1], -2.0);  // "-0.002 kN"
  EXPECT_EQ(second.load[2], 0.0);
  EXPECT_EQ(second.load[3], 2.0);
  EXPECT_EQ(second.load[4], 0.0);
  EXPECT_EQ(second.load[5], -0.25);
}

TEST_F(EverythingModel, ResponseAndStaticDefaults) {
  const HarmonicOptions r = response_of(*file_);
  ASSERT_EQ(r.speeds.size(), 91u);
  EXPECT_DOUBLE_EQ(r.speeds.front(), 10.0 * hz);
  EXPECT_DOUBLE_EQ(r.speeds.back(), 6000.0 * rpm);
  EXPECT_EQ(r.probes, (std::vector<Index>{index_of(m(), "tip"), 1, index_of(m(), "stator a")}));
  EXPECT_EQ(r.loss_factor, 0.01);

  const StaticOptions s = static_of(*file_);
  EXPECT_EQ(s.gravity.x(), 0.0);
  EXPECT_EQ(s.gravity.y(), 0.0);
  EXPECT_DOUBLE_EQ(s.gravity.z(), -9.81);  // gravity = "-z", g = "9810 mm/s^2"
  EXPECT_DOUBLE_EQ(s.speed, 1000.0 * rpm);
}

TEST_F(EverythingModel, RunupDefaultsWithARamp) {
  const TransientOptions r = runup_of(*file_);
  // from = "10 Hz", to = "4800 rpm", ramp_time = "5 s"
  const auto& profile = r.profile.points();
  ASSERT_EQ(profile.size(), 2u);
  EXPECT_EQ(profile[0].first, 0.0);
  EXPECT_DOUBLE_EQ(profile[0].second, 10.0 * hz);
  EXPECT_EQ(profile[1].first, 5.0);
  EXPECT_DOUBLE_EQ(profile[1].second, 4800.0 * rpm);
  EXPECT_EQ(r.duration, 5.0);  // the ramp time, by default
  EXPECT_EQ(r.integrator, "ros34pw2");
  EXPECT_DOUBLE_EQ(r.settings.dt, 0.1 / 1000.0);
  EXPECT_EQ(r.settings.rel_tol, 1e-5);
  EXPECT_EQ(r.settings.abs_tol, 1e-8);
  EXPECT_DOUBLE_EQ(r.output_interval, 2.0 / 1000.0);
  EXPECT_EQ(r.probes, (std::vector<Index>{index_of(m(), "tip"), 1}));
  EXPECT_EQ(r.springs, (std::vector<Index>{element_index(m(), "bearing b"), element_index(m(), "bearing a")}));
  EXPECT_NE(element(m(), "bearing b").target<SpringDamper>(), nullptr);
}

// ---------------------------------------------------------------------------------
// Round trip: a file reads to exactly the Model built by hand.

void expect_same_matrices(const Element& expected, const Element& actual, Real speed) {
  const OperatingPoint op{speed};
  const LocalMatrices a = expected.local_matrices(op), b = actual.local_matrices(op);
  EXPECT_EQ(a.dofs, b.dofs);
  EXPECT_EQ(a.M, b.M);
  EXPECT_EQ(a.C, b.C);
  EXPECT_EQ(a.K, b.K);
  EXPECT_EQ(a.G, b.G);
  EXPECT_EQ(a.Ci, b.Ci);
  EXPECT_EQ(a.Ki, b.Ki);
}

void expect_same_model(const Model& expected, const Model& actual) {
  EXPECT_EQ(actual.name, expected.name);
  ASSERT_EQ(actual.nodes.size(), expected.nodes.size());
  for (std::size_t i = 0; i < expected.nodes.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_EQ(actual.nodes[i].number, expected.nodes[i].number);
    EXPECT_EQ(actual.nodes[i].name, expected.nodes[i].name);
    EXPECT_NEAR(actual.nodes[i].x, expected.nodes[i].x, 1e-15);
    EXPECT_EQ(actual.nodes[i].rotating, expected.nodes[i].rotating);
  }
  ASSERT_EQ(actual.elements.size(), expected.elements.size());
  for (std::size_t i = 0; i < expected.elements.size(); ++i) {
    SCOPED_TRACE("element " + expected.elements[i].label());
    EXPECT_EQ(actual.elements[i].label(), expected.elements[i].label());
    EXPECT_EQ(actual.elements[i].kind(), expected.elements[i].kind());
    for (const Real speed : {0.0, 100.0, 1000.0}) expect_same_matrices(expected.elements[i], actual.elements[i], speed);
  }
  ASSERT_EQ(actual.fixed.size(), expected.fixed.size());
  for (std::size_t i = 0; i < expected.fixed.size(); ++i) {
    EXPECT_EQ(actual.fixed[i].node, expected.fixed[i].node);
    EXPECT_EQ(actual.fixed[i].dofs, expected.fixed[i].dofs);
  }
  ASSERT_EQ(actual.links.size(), expected.links.size());
  for (std::size_t i = 0; i < expected.links.size(); ++i) {
    EXPECT_EQ(actual.links[i].leader, expected.links[i].leader);
    EXPECT_EQ(actual.links[i].followers, expected.links[i].followers);
  }
  const auto a_unbalances = forces_of<Unbalance>(actual), e_unbalances = forces_of<Unbalance>(expected);
  ASSERT_EQ(a_unbalances.size(), e_unbalances.size());
  for (std::size_t i = 0; i < e_unbalances.size(); ++i) {
    const Unbalance &a = a_unbalances[i].first, &e = e_unbalances[i].first;
    EXPECT_EQ(a.node, e.node);
    EXPECT_DOUBLE_EQ(a.mass, e.mass);
    EXPECT_DOUBLE_EQ(a.radius, e.radius);
    EXPECT_DOUBLE_EQ(a.phase, e.phase);
    EXPECT_DOUBLE_EQ(a.lever, e.lever);
    EXPECT_EQ(a_unbalances[i].second, e_unbalances[i].second);
  }
  EXPECT_EQ(actual.forces.size(), expected.forces.size());
  // The options and materials are in the element matrices compared above.
  EXPECT_EQ(actual.free_motions, expected.free_motions);
}

TEST(ModelReaderRoundTrip, JeffcottRotor) {
  Model expected;
  expected.name = "Jeffcott rotor";
  const Material shaft_material{"massless steel", 210e9, 210e9 / 2.6, 0.0};
  expected.nodes = {{1, "left", 0.0, true}, {2, "disk", 0.25, true}, {3, "right", 0.5, true}};
  const BeamOptions beam{false, GyroscopicForm::consistent, true, 0.0};
  const CircularSection section{0.012, 0.0};
  expected.elements.emplace_back(TimoshenkoBeam(0, 1, 0.25, section, shaft_material, beam),
                                 "shaft 1 section 1 element 1");
  expected.elements.emplace_back(TimoshenkoBeam(1, 2, 0.25, section, shaft_material, beam),
                                 "shaft 1 section 2 element 1");
  expected.elements.emplace_back(RigidBody(1, RigidBodyProperties{5.0, 0.02, 0.04, 0.0}, true), "disk");
  FixedDofs all{0, {}};
  all.dofs.fill(true);
  expected.fixed = {all, all};
  expected.fixed[1].node = 2;
  expected.forces = {Force(Unbalance{1, 0.001, 0.05, 0.0, 0.0}, "unbalance 1")};

  const ModelFile file = read_model_file(models + "/valid/jeffcott.toml");
  expect_same_model(expected, file.model);
  EXPECT_EQ(file.spec.modal.speed, 0.0);
  EXPECT_EQ(file.spec.modal.modes, 4);
  EXPECT_FALSE(file.spec.campbell.start);
  EXPECT_TRUE(file.spec.campbell.orders.empty());
}

TEST(ModelReaderRoundTrip, StatorJoinedByARigidLink) {
  Model expected;
  expected.name = "Rotor in a linked stator";
  const Material steel{"steel", 2.1e11, 2.1e11 / 2.6, 7850.0};
  expected.nodes = {{1, "journal a", 0.0, true},  {2, "", 0.02, true},         {3, "", 0.04, true},
                    {4, "journal b", 0.06, true}, {5, "", 0.08, true},         {6, "tip", 0.1, true},
                    {7, "stator a", 0.0, false},  {8, "stator b", 0.06, false}};
  const BeamOptions beam{};
  const CircularSection section{0.020, 0.0};
  for (int s = 0; s < 2; ++s)
    for (int j = 0; j < (s == 0 ? 3 : 2); ++j) {
      const Index a = s == 0 ? j : 3 + j;
      // The reader divides each section's length by its element count.
      const Real length = s == 0 ? 0.06 / 3.0 : 0.04 / 2.0;
      expected.elements.emplace_back(
          TimoshenkoBeam(a, a + 1, length, section, steel, beam),
          "shaft rotor section " + std::to_string(s + 1) + " element " + std::to_string(j + 1));
    }
  expected.elements.emplace_back(RigidBody(6, RigidBodyProperties{5.0, 0.01, 0.01, 0.03}, false), "stator");
  expected.elements.emplace_back(RigidBody(5, RigidBodyProperties{1.93, 0.0063, 0.0104, 0.0}, true), "rotor");
  SpringDamperCoefficients bearing_a;
  bearing_a.k = {6e7, 6e7, 6e7, 1.0, 0.0, 0.0};
  expected.elements.emplace_back(SpringDamper(0, 6, bearing_a), "bearing a");
  SpringDamperCoefficients bearing_b;
  bearing_b.k = {0.0, 6e7, 6e7, 0.0, 0.0, 0.0};
  expected.elements.emplace_back(SpringDamper(3, 7, bearing_b), "bearing b");
  SpringDamperCoefficients foot;
  foot.k = {9000.0, 9000.0, 9000.0, 180.0, 180.0, 180.0};
  foot.c = {0.0, 75.0, 75.0, 0.0, 0.06, 0.06};
  expected.elements.emplace_back(SpringDamper(6, std::nullopt, foot), "foot");
  expected.links = {RigidLink{6, {7}}};
  expected.forces = {Force(Unbalance{5, 0.003, 0.08, 0.0, 0.0}, "unbalance 1")};

  const ModelFile file = read_model_file(models + "/valid/stator_link.toml");
  expect_same_model(expected, file.model);
}

TEST(ModelReaderValid, TwoDisksOnBearings) {
  const ModelFile file = read_model_file(models + "/valid/two_disks.toml");
  const Model& m = file.model;
  EXPECT_EQ(m.nodes.size(), 9u);  // 1 + 2 + 4 + 2
  EXPECT_EQ(m.find_node("disk 1"), 2);
  EXPECT_EQ(m.find_node("disk 2"), 6);
  EXPECT_NEAR(m.nodes[6].x, 0.6, 1e-15);
  EXPECT_NEAR(m.nodes[8].x, 0.8, 1e-15);
  // Disk 2 sits at an axial offset: its inertia about the node gains m·e².
  const auto& disk = element_as<RigidBody>(m, "disk 2");
  const RigidBodyProperties centre = RigidBody::disk(7810.0, 0.35, 0.05, 0.07);
  EXPECT_DOUBLE_EQ(disk.properties().mass, centre.mass);
  EXPECT_DOUBLE_EQ(disk.properties().transverse_inertia, centre.transverse_inertia + centre.mass * 0.01 * 0.01);
  EXPECT_DOUBLE_EQ(disk.properties().offset, 0.01);
  const auto& bearing = element_as<SpringDamper>(m, "bearing 2");
  EXPECT_FALSE(bearing.node_b());                                 // to = "ground"
  EXPECT_EQ(bearing.coefficients().k[1], SpeedCoefficient(1e7));  // "10 kN/mm"
  EXPECT_DOUBLE_EQ(*file.spec.campbell.stop, 6000.0 * rpm);
}

// ---------------------------------------------------------------------------------
// Inline models: defaults, numbering, references

const char* const steel_and_shaft = R"(
[[materials]]
name = "steel"
E = 2.1e11
nu = 0.3
rho = 7850

[[shafts]]
material = "steel"
sections = [{ length = 0.1, outer_diameter = 0.02, elements = 2 }]
)";

TEST(ModelReaderDefaults, ValuesLeftOutTakeTheirDefaults) {
  const std::string text = std::string(steel_and_shaft) + R"(
[[nodes]]
x = 0.05

[[rigid_bodies]]
node = 4
mass = 1
Ja = 0.01
Jp = 0.01

[[springs]]
node = 1
kx = 1e6
ky = 1e6
kz = 1e6
krx = 1e3
krz = 1e3
kry = 1e3

[[springs]]
node = 4
to = 2
kx = 1e6
ky = 1e6
kz = 1e6
krx = 1e3
krz = 1e3
kry = 1e3

[[unbalances]]
node = 3
mass = 0.001
radius = 0.01
)";
  const ModelFile file = read_model_string(text, "defaults.toml");
  const Model& m = file.model;
  EXPECT_EQ(file.title, "");
  EXPECT_TRUE(m.free_motions.empty());
  ASSERT_EQ(m.nodes.size(), 4u);
  EXPECT_EQ(m.nodes[0].x, 0.0);       // shaft x defaults to 0
  EXPECT_TRUE(m.nodes[0].rotating);   // shafts rotate by default
  EXPECT_EQ(m.nodes[3].number, 4);    // next after the shaft's 1-3
  EXPECT_FALSE(m.nodes[3].rotating);  // [[nodes]] do not rotate by default
  const auto& beam = element_as<TimoshenkoBeam>(m, "shaft 1 section 1 element 2");
  EXPECT_TRUE(beam.options().shear_deformation);  // [options] defaults
  EXPECT_EQ(beam.options().gyroscopic, GyroscopicForm::consistent);
  EXPECT_EQ(beam.options().damping_beta, 0.0);
  EXPECT_EQ(beam.section().inner_diameter, 0.0);
  EXPECT_DOUBLE_EQ(beam.length(), 0.05);
  EXPECT_FALSE(element_as<RigidBody>(m, "rigid body 1").rotating());  // from its node
  EXPECT_EQ(element_as<RigidBody>(m, "rigid body 1").properties().offset, 0.0);
  EXPECT_FALSE(element_as<SpringDamper>(m, "spring 1").node_b());  // to ground
  EXPECT_TRUE(element_as<SpringDamper>(m, "spring 1").coefficients().c[1].is_zero());
  ASSERT_EQ(forces_of<Unbalance>(m).size(), 1u);
  EXPECT_EQ(forces_of<Unbalance>(m)[0].first.phase, 0.0);
  EXPECT_EQ(forces_of<Unbalance>(m)[0].first.lever, 0.0);
  EXPECT_TRUE(file.spec.modal == ModalSpec{});
  EXPECT_TRUE(file.spec.campbell == CampbellSpec{});
  // No loss factors, loads or response and static defaults unless given.
  EXPECT_EQ(beam.material().loss_factor, 0.0);
  EXPECT_EQ(beam.options().loss_factor, 0.0);
  EXPECT_EQ(element_as<SpringDamper>(m, "spring 1").coefficients().loss_factor, 0.0);
  EXPECT_EQ(m.forces.size(), 1u);  // the unbalance: no harmonic forces, no static loads
  EXPECT_TRUE(file.spec.response == ResponseSpec{});
  EXPECT_TRUE(file.spec.static_ == StaticSpec{});
  // So the analyses take the built-in defaults: probes at the unbalances, gravity −y.
  ResponseSpec one_point;
  one_point.points = 1;
  EXPECT_EQ(response_of(file, one_point).probes, (std::vector<Index>{2}));
  EXPECT_EQ(static_of(file).gravity, Eigen::Vector3d(0.0, -9.81, 0.0));
  EXPECT_EQ(static_of(file).speed, 0.0);
  // No run-up defaults without [runup].
  EXPECT_TRUE(file.spec.runup == RunupSpec{});
  EXPECT_THROW((void)runup_of(file), Error);  // a run-up then needs a profile from its caller
}

// A clamped-clamped shaft (valid structure) followed by @p extra.
ModelFile read_with(const std::string& extra) {
  return read_model_string(std::string(steel_and_shaft) + R"(
[[fixed]]
node = 1

[[fixed]]
node = 3
)" + extra,
                           "extra.toml");
}

TEST(ModelReaderStatic, GravityDirectionsAndDefaultMagnitude) {
  struct Case {
    const char* gravity;
    Eigen::Vector3d expected;
  };
  const std::vector<Case> cases = {
      {"+x", {9.81, 0.0, 0.0}}, {"-x", {-9.81, 0.0, 0.0}}, {"+y", {0.0, 9.81, 0.0}},         {"-y", {0.0, -9.81, 0.0}},
      {"+z", {0.0, 0.0, 9.81}}, {"-z", {0.0, 0.0, -9.81}}, {"none", Eigen::Vector3d::Zero()}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.gravity);
    const ModelFile file = read_with(std::string("[static]\ngravity = \"") + c.gravity + "\"\n");
    EXPECT_EQ(static_of(file).gravity, c.expected);  // 9.81 exactly: no conversion
    EXPECT_FALSE(file.spec.static_.speed);
  }
  const ModelFile moon = read_with("[static]\ngravity = \"-y\"\ng = \"1620 mm/s^2\"\n");
  EXPECT_DOUBLE_EQ(static_of(moon).gravity.y(), -1.62);
}

TEST(ModelReaderResponse, ProbesByNumberAndNameInTheOrderGiven) {
  const ModelFile file = read_with(R"(
[response]
probes = [3, 1]
points = 2
)");
  ResponseSpec request;
  request.stop = 10.0;
  request.forces = {"2:y:1N"};  // node index 1
  const HarmonicOptions r = response_of(file, request);
  EXPECT_EQ(r.probes, (std::vector<Index>{2, 0}));
  EXPECT_EQ(r.speeds, (std::vector<Real>{0.0, 10.0}));  // 2 points from 0
  EXPECT_EQ(r.loss_factor, 0.0);
}

// ---------------------------------------------------------------------------------
// [runup]: the three forms of the speed profile, defaults and references

TEST(ModelReaderRunup, ConstantSpeedIsOnePointAndHasNoDefaultDuration) {
  const ModelFile file = read_with("[runup]\nspeed = \"30 Hz\"\n");
  ASSERT_TRUE(file.spec.runup.speed);
  EXPECT_DOUBLE_EQ(*file.spec.runup.speed, 30.0 * hz);
  EXPECT_THROW((void)runup_of(file), Error);  // no duration
  RunupSpec expected;
  expected.speed = file.spec.runup.speed;
  EXPECT_TRUE(file.spec.runup == expected);  // nothing else given

  const ModelFile timed = read_with("[runup]\nspeed = 100\nduration = \"250 ms\"\n");
  const TransientOptions t = runup_of(timed);
  EXPECT_EQ(t.profile.points(), (std::vector<std::pair<Real, Real>>{{0.0, 100.0}}));
  EXPECT_DOUBLE_EQ(t.duration, 0.25);
  EXPECT_EQ(t.integrator, "trapezoidal");  // built-in defaults
  EXPECT_EQ(t.settings.dt, 1e-4);
  EXPECT_TRUE(t.probes.empty());  // the model has no unbalance
  EXPECT_TRUE(t.springs.empty());
}

TEST(ModelReaderRunup, RampStartsAtRestByDefaultAndMayRunDown) {
  // The paper's Fig. 5 run-up.
  const TransientOptions up = runup_of(read_with("[runup]\nto = \"80 Hz\"\nramp_time = \"5 s\"\n"));
  ASSERT_EQ(up.profile.points().size(), 2u);
  EXPECT_EQ(up.profile.points()[0], (std::pair<Real, Real>{0.0, 0.0}));
  EXPECT_EQ(up.profile.points()[1].first, 5.0);
  EXPECT_DOUBLE_EQ(up.profile.points()[1].second, 80.0 * hz);
  EXPECT_EQ(up.duration, 5.0);

  // A run-down; an explicit duration (longer than the ramp: the speed is then held)
  // replaces the ramp time.
  const TransientOptions down = runup_of(read_with(R"([runup]
from = "6000 rpm"
to = 0
ramp_time = "1500 ms"
duration = "2 s"
)"));
  ASSERT_EQ(down.profile.points().size(), 2u);
  EXPECT_DOUBLE_EQ(down.profile.points()[0].second, 6000.0 * rpm);
  EXPECT_DOUBLE_EQ(down.profile.points()[1].first, 1.5);
  EXPECT_EQ(down.profile.points()[1].second, 0.0);
  EXPECT_EQ(down.duration, 2.0);
}

TEST(ModelReaderRunup, TableGivesThePointsAndItsLastTimeIsTheDefaultDuration) {
  const ModelFile file = read_with(R"([runup]
table = [["0 s", "0 Hz"], ["2 s", "50 Hz"], [5, "3000 rpm"], ["5500 ms", 10]]
)");
  const TransientOptions t = runup_of(file);
  const auto& p = t.profile.points();
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0], (std::pair<Real, Real>{0.0, 0.0}));
  EXPECT_EQ(p[1].first, 2.0);
  EXPECT_DOUBLE_EQ(p[1].second, 50.0 * hz);
  EXPECT_EQ(p[2].first, 5.0);
  EXPECT_DOUBLE_EQ(p[2].second, 3000.0 * rpm);
  EXPECT_DOUBLE_EQ(p[3].first, 5.5);
  EXPECT_EQ(p[3].second, 10.0);  // a bare speed is in rad/s
  EXPECT_DOUBLE_EQ(t.duration, 5.5);

  // One point at t = 0 is a constant speed: no default duration.
  const ModelFile single = read_with("[runup]\ntable = [[0, \"20 Hz\"]]\n");
  ASSERT_EQ(single.spec.runup.table.size(), 1u);
  EXPECT_DOUBLE_EQ(single.spec.runup.table[0].second, 20.0 * hz);
  EXPECT_THROW((void)runup_of(single), Error);
}

TEST(ModelReaderRunup, EveryIntegratorNameIsAccepted) {
  for (const char* name : {"trapezoidal", "rk3", "wolfbrandt", "ros34pw2"}) {
    SCOPED_TRACE(name);
    const ModelFile file = read_with(std::string("[runup]\nintegrator = \"") + name + "\"\n");
    EXPECT_EQ(file.spec.runup.integrator, name);
    RunupSpec constant;  // the profile may be left to the analysis
    constant.speed = 10.0;
    constant.duration = 1.0;
    EXPECT_EQ(runup_options(file, constant).integrator, name);
  }
}

TEST(ModelReaderRunup, StepTolerancesAndOutput) {
  const ModelFile file = read_with(R"([runup]
dt = 1e-4
rel_tol = 1e-6
abs_tol = 2e-9
output_interval = "0.5 ms"
modes = 12
)");
  RunupSpec constant;
  constant.speed = 10.0;
  constant.duration = 1.0;
  const TransientOptions t = runup_options(file, constant);
  EXPECT_EQ(t.settings.dt, 1e-4);
  EXPECT_EQ(t.reduced_modes, 12);
  EXPECT_EQ(t.settings.rel_tol, 1e-6);
  EXPECT_EQ(t.settings.abs_tol, 2e-9);
  EXPECT_DOUBLE_EQ(t.output_interval, 0.5e-3);
  EXPECT_FALSE(file.spec.runup.duration);
  EXPECT_FALSE(read_with("[runup]\ndt = 1e-4\n").spec.runup.modes);
}

TEST(ModelReaderRunup, ProbesAndNamedSpringsInTheOrderGiven) {
  const ModelFile file = read_with(R"(
[[springs]]
node = 2
ky = 1e5

[[springs]]
name = "left"
node = 1
to = 2
kz = 1e5

[[springs]]
name = "right"
node = 3
to = 2
kz = 1e5

[runup]
probes = [2, 1]
springs = ["right", "left"]
)");
  const Model& m = file.model;
  RunupSpec constant;
  constant.speed = 10.0;
  constant.duration = 1.0;
  const TransientOptions t = runup_options(file, constant);
  EXPECT_EQ(t.probes, (std::vector<Index>{1, 0}));
  EXPECT_EQ(t.springs, (std::vector<Index>{element_index(m, "right"), element_index(m, "left")}));
  EXPECT_EQ(element_as<SpringDamper>(m, "left").node_a(), 0);
}

TEST(ModelReaderForces, PhaseMayBeNegativeAndAmplitudeTakesAUnit) {
  const ModelFile file = read_with(R"(
[[forces]]
node = 2
direction = "z"
amplitude = "0.2 kN"
phase = "-90 deg"
)");
  const auto forces = forces_of<HarmonicForce>(file.model);
  ASSERT_EQ(forces.size(), 1u);
  const HarmonicForce& f = forces[0].first;
  EXPECT_EQ(forces[0].second, "force 1");
  EXPECT_EQ(f.node, 1);
  EXPECT_EQ(f.direction, Dof::w);
  EXPECT_DOUBLE_EQ(f.amplitude, 200.0);
  EXPECT_DOUBLE_EQ(f.phase, -pi / 2.0);
}

TEST(ModelReaderNumbering, DefaultNumbersSkipNumbersClaimedLater) {
  // The shaft takes 1-3. The first extra node would be 4, but a later entry claims
  // 4, so it becomes 5; a second shaft continues after the highest number so far.
  const std::string text = std::string(steel_and_shaft) + R"(
[[nodes]]
name = "a"
x = 0

[[nodes]]
name = "b"
number = 4
x = 0

[[nodes]]
name = "c"
x = 0
number = 100

[[nodes]]
name = "d"
x = 0
)";
  try {
    (void)read_model_string(text, "numbers.toml");
  } catch (const ModelError& e) {
    // The extra nodes have no mass: check_model rejects the model, which is fine
    // here; numbering is checked on the message's node.
    EXPECT_NE(e.message().find("node 5 (a) has no mass"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().line, 12);  // the [[nodes]] table of "a"
    return;
  }
  FAIL() << "a massless node must be rejected";
}

TEST(ModelReaderNumbering, QuotedDigitsAreANameNotANumber) {
  // Node "2" is the extra node (number 4), not shaft node 2.
  const std::string text = std::string(steel_and_shaft) + R"(
[[nodes]]
name = "2"
x = 0.05
rotating = true

[[rigid_bodies]]
node = "2"
mass = 1
Ja = 0.01
Jp = 0.01

[[springs]]
node = 1
kx = 1e6
ky = 1e6
kz = 1e6
krx = 1e3

[[springs]]
node = 3
ky = 1e6
kz = 1e6

[[springs]]
node = "2"
to = 2
kx = 1e6
ky = 1e6
kz = 1e6
krx = 1e3
kry = 1e3
krz = 1e3
)";
  const ModelFile file = read_model_string(text, "digits.toml");
  const Model& m = file.model;
  EXPECT_EQ(element_as<RigidBody>(m, "rigid body 1").node(), 3);
  EXPECT_EQ(element_as<SpringDamper>(m, "spring 3").node_a(), 3);
  EXPECT_EQ(element_as<SpringDamper>(m, "spring 3").node_b(), 1);
}

TEST(ModelReaderStructure, CheckModelMessagesAreLocatedAtTheNode) {
  // Torsion is free; check_model's message passes through, located at the shaft's
  // first node (the [[shafts]] table on line 8 of steel_and_shaft).
  const std::string text = std::string(steel_and_shaft) + R"(
[[springs]]
node = 1
kx = 1e6
ky = 1e6
kz = 1e6

[[springs]]
node = 3
ky = 1e6
kz = 1e6
)";
  try {
    (void)read_model_string(text, "torsion.toml");
    FAIL() << "free torsion must be rejected";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 8) << e.what();
    EXPECT_NE(e.message().find("torsion"), std::string::npos) << e.what();
  }
  // Allowed with free_motions, the same model reads.
  EXPECT_NO_THROW((void)read_model_string(text + "\n[options]\nfree_motions = [\"torsion\"]\n", "torsion.toml"));
}

// ---------------------------------------------------------------------------------
// docs/model-format.md: its complete examples (```toml blocks starting with
// "# Example:") must read, and have the nodes the text says; its [runup] snippets
// (blocks starting with "[runup]") must read when added to the first example.

TEST(ModelFormatDocs, CompleteExamplesRead) {
  std::ifstream in(std::string(FERAN_SOURCE_DIR) + "/docs/model-format.md");
  ASSERT_TRUE(in) << "docs/model-format.md not found";
  struct Example {
    std::string name, text;
  };
  std::vector<Example> examples;
  std::vector<std::string> runup_snippets;
  std::string line, block;
  bool in_block = false;
  while (std::getline(in, line)) {
    if (!in_block && line == "```toml") {
      in_block = true;
      block.clear();
    } else if (in_block && line == "```") {
      in_block = false;
      const std::string tag = "# Example: ";
      if (block.rfind(tag, 0) == 0)
        examples.push_back({block.substr(tag.size(), block.find('\n') - tag.size()), block});
      else if (block.rfind("[runup]\n", 0) == 0)
        runup_snippets.push_back(block);
    } else if (in_block) {
      block += line + "\n";
    }
  }
  ASSERT_EQ(examples.size(), 4u);
  // Node counts and named node numbers as the document states them.
  const std::vector<std::vector<std::pair<std::string, int>>> named = {
      {{"left", 1}, {"disk", 2}, {"right", 3}},
      {{"bearing 1", 1}, {"disk 1", 3}, {"disk 2", 7}, {"bearing 2", 9}},
      {{"journal a", 1}, {"journal b", 4}, {"tip", 6}, {"stator a", 7}, {"stator b", 8}},
      {{"left", 1}, {"disk", 3}, {"right", 5}}};
  const std::vector<std::size_t> n_nodes = {3, 9, 8, 5};
  for (std::size_t i = 0; i < examples.size(); ++i) {
    SCOPED_TRACE(examples[i].name);
    try {
      const ModelFile file = read_model_string(examples[i].text, "docs/model-format.md example");
      EXPECT_EQ(file.model.nodes.size(), n_nodes[i]);
      if (i == 3) {  // the loads example, as its text describes it
        EXPECT_EQ(file.model.n_forces("harmonic_force"), 2u);
        EXPECT_EQ(file.model.n_forces("static_load"), 1u);
        ResponseSpec one_point;
        one_point.points = 1;
        EXPECT_EQ(response_of(file, one_point).probes, (std::vector<Index>{2, 0}));
        EXPECT_EQ(static_of(file).gravity, Eigen::Vector3d(0.0, 0.0, -9.81));
      }
      for (const auto& [name, number] : named[i]) {
        const Index node = file.model.find_node(name);
        ASSERT_GE(node, 0) << name;
        EXPECT_EQ(file.model.nodes[static_cast<std::size_t>(node)].number, number) << name;
      }
    } catch (const ModelError& e) {
      ADD_FAILURE() << e.what();
    }
  }

  ASSERT_EQ(runup_snippets.size(), 3u);
  for (const std::string& snippet : runup_snippets) {
    SCOPED_TRACE(snippet);
    try {
      const ModelFile file = read_model_string(examples[0].text + "\n" + snippet, "docs/model-format.md snippet");
      // A complete run-up: profile and duration (the run-up's options are refused otherwise).
      EXPECT_GT(runup_of(file).duration, 0.0);
    } catch (const ModelError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  // The first snippet is the paper's Fig. 5 run-up.
  const ModelFile fig5 = read_model_string(examples[0].text + "\n" + runup_snippets[0], "fig5");
  const auto profile = runup_of(fig5).profile.points();
  ASSERT_EQ(profile.size(), 2u);
  EXPECT_EQ(profile[0], (std::pair<Real, Real>{0.0, 0.0}));
  EXPECT_EQ(profile[1].first, 5.0);
  EXPECT_DOUBLE_EQ(profile[1].second, 80.0 * hz);
}

// [options] rotary_inertia, shear_coefficient, kappa and the Rayleigh damping reach
// the shaft elements; a shaft's own rayleigh_* replace the global ones.
TEST(ModelReaderOptions, BeamOptionsReachTheShaftElements) {
  const ModelFile file = read_model_file(models + "/valid/beam_options.toml");
  int main = 0, quill = 0;
  for (const Element& e : file.model.elements) {
    const auto* beam = e.target<TimoshenkoBeam>();
    if (beam == nullptr) continue;
    EXPECT_FALSE(beam->options().rotary_inertia);
    EXPECT_EQ(beam->options().shear, ShearCoefficient::hutchinson);
    EXPECT_EQ(beam->options().rayleigh_alpha, 0.5);
    if (e.label().starts_with("shaft main")) {
      ++main;
      EXPECT_DOUBLE_EQ(beam->options().rayleigh_beta, 2e-3);  // "2 ms"
    } else {
      ++quill;
      EXPECT_EQ(beam->options().rayleigh_beta, 0.0);
    }
  }
  EXPECT_EQ(main, 2);
  EXPECT_EQ(quill, 1);
  ModelSpec spec = file.spec;
  spec.options.kappa = 0.8;  // a given κ replaces the formula
  const Model given = build_model(spec);
  EXPECT_EQ(given.elements.front().target<TimoshenkoBeam>()->options().shear, ShearCoefficient::given);
  EXPECT_EQ(given.elements.front().target<TimoshenkoBeam>()->options().kappa, 0.8);
}

}  // namespace
}  // namespace feran::test_model_reader

// Tests of io/node_reference: node and probe references given on the command line.

#include <feran/io/node_reference.hpp>

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace feran::test_node_reference {
namespace {

/// Nodes only: references do not look at elements. The node named "7" has no node
/// number 7; the node named "2" shares its text with node number 2.
Model model_with_nodes() {
  Model m;
  m.nodes = {{1, "drive", 0.0, true}, {2, "", 0.1, true},    {3, "rotor", 0.2, true}, {10, "housing", 0.0, false},
             {11, "7", 0.1, false},   {12, "2", 0.2, false}, {13, "a:b", 0.3, false}};
  return m;
}

/// The message of the feran::Error that @p f throws ("" if it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const ModelError& e) {
    return std::string("unexpected ModelError: ") + e.what();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(NodeReference, DigitsAreANumberAnythingElseAName) {
  const Model m = model_with_nodes();
  EXPECT_EQ(find_node_reference(m, "1", "--probe"), 0);
  EXPECT_EQ(find_node_reference(m, "3", "--probe"), 2);
  EXPECT_EQ(find_node_reference(m, "10", "--probe"), 3);
  EXPECT_EQ(find_node_reference(m, "rotor", "--probe"), 2);
  EXPECT_EQ(find_node_reference(m, "housing", "--probe"), 3);
  // The number wins over a node named "2"; with no node number 7 the name is taken.
  EXPECT_EQ(find_node_reference(m, "2", "--probe"), 1);
  EXPECT_EQ(find_node_reference(m, "7", "--probe"), 4);
}

TEST(NodeReference, UnknownNameSuggestsTheClosestName) {
  const Model m = model_with_nodes();
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "rotr", "--probe"); }),
            "--probe 'rotr': no such node; did you mean 'rotor'?");
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "Housing", "--node"); }),
            "--node 'Housing': no such node; did you mean 'housing'?");
}

TEST(NodeReference, UnknownReferenceListsTheChoices) {
  const Model m = model_with_nodes();
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "99", "--probe"); }),
            "--probe '99': no such node; the node numbers are 1-3 and 10-13");
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "99999999999999999999", "--probe"); }),
            "--probe '99999999999999999999': no such node; the node numbers are 1-3 and 10-13");
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "bearing", "--probe"); }),
            "--probe 'bearing': no such node; the node names are 'drive', 'rotor', 'housing', "
            "'7', '2' and 'a:b', the node numbers 1-3 and 10-13");
  EXPECT_EQ(error_of([&] { (void)find_node_reference(m, "", "--probe"); }),
            "--probe: empty node reference; give a node number or a node name");

  Model unnamed;
  unnamed.nodes = {{1, "", 0.0, true}, {2, "", 0.1, true}, {3, "", 0.2, true}};
  EXPECT_EQ(error_of([&] { (void)find_node_reference(unnamed, "rotor", "--probe"); }),
            "--probe 'rotor': no such node; no node has a name; the node numbers are 1-3");

  // Many names: the first eight are listed with the count.
  Model many;
  for (int i = 1; i <= 12; ++i)
    many.nodes.push_back({i, "station " + std::string(1, static_cast<char>('a' + i - 1)), 0.0, true});
  EXPECT_EQ(error_of([&] { (void)find_node_reference(many, "bearing", "--probe"); }),
            "--probe 'bearing': no such node; the node names include 'station a', 'station b', "
            "'station c', 'station d', 'station e', 'station f', 'station g' and 'station h' "
            "(12 names in all), the node numbers are 1-12");
}

TEST(Probe, NodeAloneOrWithADof) {
  const Model m = model_with_nodes();
  using Probe = std::pair<Index, std::optional<Dof>>;
  EXPECT_EQ(parse_probe(m, "rotor"), (Probe{2, std::nullopt}));
  EXPECT_EQ(parse_probe(m, "3"), (Probe{2, std::nullopt}));
  EXPECT_EQ(parse_probe(m, "rotor:v"), (Probe{2, Dof::v}));
  EXPECT_EQ(parse_probe(m, "7:rz"), (Probe{4, Dof::rz}));
  EXPECT_EQ(parse_probe(m, "1:u"), (Probe{0, Dof::u}));
  EXPECT_EQ(parse_probe(m, "10:w"), (Probe{3, Dof::w}));
  EXPECT_EQ(parse_probe(m, "drive:rx"), (Probe{0, Dof::rx}));
  EXPECT_EQ(parse_probe(m, "drive:ry"), (Probe{0, Dof::ry}));
  // A name containing ':' is matched whole first.
  EXPECT_EQ(parse_probe(m, "a:b"), (Probe{6, std::nullopt}));
  EXPECT_EQ(parse_probe(m, "a:b:w"), (Probe{6, Dof::w}));
}

TEST(Probe, BadDofNamesTheValidOnes) {
  const Model m = model_with_nodes();
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotor:y"); }),
            "probe 'rotor:y': unknown DOF 'y'; the DOFs are u, v, w, rx, ry and rz (did you "
            "mean 'v', the displacement along y?)");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotor:Z"); }),
            "probe 'rotor:Z': unknown DOF 'Z'; the DOFs are u, v, w, rx, ry and rz (did you "
            "mean 'w', the displacement along z?)");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotor:RZ"); }),
            "probe 'rotor:RZ': unknown DOF 'RZ'; the DOFs are u, v, w, rx, ry and rz (did you "
            "mean 'rz'?)");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotor:q"); }),
            "probe 'rotor:q': unknown DOF 'q'; the DOFs are u, v, w, rx, ry and rz");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotor:"); }),
            "probe 'rotor:': no DOF after ':'; the DOFs are u, v, w, rx, ry and rz");
}

TEST(Probe, UnknownNodeIsReportedBeforeTheDof) {
  const Model m = model_with_nodes();
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotr:v"); }), "probe 'rotr': no such node; did you mean 'rotor'?");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "rotr"); }), "probe 'rotr': no such node; did you mean 'rotor'?");
  EXPECT_EQ(error_of([&] { (void)parse_probe(m, "42:q"); }),
            "probe '42': no such node; the node numbers are 1-3 and 10-13");
}

}  // namespace
}  // namespace feran::test_node_reference

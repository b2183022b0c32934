// A mode's shape kind (cylindrical, conical, bending) from its bending fraction β,
// the part of the rotor's lateral motion no straight line holds
// (docs/theory/modal_analysis.md, "Mode shapes and labels"): against closed forms of
// given shapes, and on a rotor whose lowest modes are rigid on soft supports.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/modal/whirl.hpp>
#include <feran/io/model_reader.hpp>

namespace feran {
namespace {

constexpr Real pi = 3.14159265358979323846;

// A shape over 21 nodes at x = 0, 0.05, …, 1 with v = f(x) and w = i·f(x) (a forward
// circle at each node).
template <class F>
std::pair<ComplexVector, std::vector<std::pair<Index, Real>>> shape_of(F f) {
  const Index n = 21;
  ComplexVector s = ComplexVector::Zero(dofs_per_node * n);
  std::vector<std::pair<Index, Real>> nodes;
  for (Index i = 0; i < n; ++i) {
    const Real x = static_cast<Real>(i) / (n - 1);
    s(global_dof(i, Dof::v)) = f(x);
    s(global_dof(i, Dof::w)) = Complex(0, 1) * f(x);
    nodes.emplace_back(i, x);
  }
  return {s, nodes};
}

TEST(ModeShape, StraightLinesAreRigidSinesBend) {
  // Translation: β = 0, cylindrical; a tilt about the middle: β = 0, conical; a
  // translation with a small tilt stays cylindrical.
  auto [a, nodes] = shape_of([](Real) { return 1.0; });
  EXPECT_NEAR(classify_shape(a, nodes).bending, 0.0, 1e-15);
  EXPECT_EQ(classify_shape(a, nodes).kind, ModeShape::cylindrical);
  auto [b, n2] = shape_of([](Real x) { return x - 0.5; });
  EXPECT_NEAR(classify_shape(b, n2).bending, 0.0, 1e-15);
  EXPECT_EQ(classify_shape(b, n2).kind, ModeShape::conical);
  auto [c, n3] = shape_of([](Real x) { return 1.0 + 0.3 * (x - 0.5); });
  EXPECT_EQ(classify_shape(c, n3).kind, ModeShape::cylindrical);
  // The pinned-pinned shaft's modes sin(kπx) on these nodes: β from the discrete
  // least-squares line, 0.2312017200114833 and 0.4822927507914104 (computed with
  // numpy.linalg.lstsq, docs/theory/modal_analysis.md), both bending.
  auto [d, n4] = shape_of([](Real x) { return std::sin(pi * x); });
  EXPECT_NEAR(classify_shape(d, n4).bending, 0.2312017200114833, 1e-13);
  EXPECT_EQ(classify_shape(d, n4).kind, ModeShape::bending);
  auto [e, n5] = shape_of([](Real x) { return std::sin(2 * pi * x); });
  EXPECT_NEAR(classify_shape(e, n5).bending, 0.4822927507914104, 1e-13);
  // One node: a rigid translation; no lateral motion: none.
  EXPECT_EQ(classify_shape(a, {{3, 0.2}}).kind, ModeShape::cylindrical);
  EXPECT_EQ(classify_shape(ComplexVector::Zero(dofs_per_node * 21), nodes).kind, ModeShape::none);
}

TEST(ModeShape, OilFilmModesDoNotPushTheFirstBendingModeUp) {
  // The journal rotor (1.2 m shaft, two disks, short journal bearings): below its
  // first bending mode at about 41 Hz lie two heavily damped oil-film modes in which
  // the shaft moves nearly as a rigid body in its films (damping ratios ~75 % at
  // 500 rpm). They are cylindrical; the first bending mode is "forward bending 1".
  const auto file = read_model_file(FERAN_SOURCE_DIR "/tests/models/valid/journal_rotor.toml");
  CampbellOptions options;
  options.speeds = {500.0 * pi / 30, 3000.0 * pi / 30, 6000.0 * pi / 30};
  options.n_modes = 6;
  const CampbellResult r = run_campbell(file.model, options);
  ASSERT_GE(r.modes.size(), 3u);
  int rigid = 0;
  const TrackedMode* first_bending = nullptr;
  for (const TrackedMode& m : r.modes) {
    if (m.shape_kind == ModeShape::cylindrical || m.shape_kind == ModeShape::conical) ++rigid;
    if (m.shape_kind == ModeShape::bending && (!first_bending || m.frequency_hz[0] < first_bending->frequency_hz[0]))
      first_bending = &m;
  }
  EXPECT_GE(rigid, 2);
  ASSERT_NE(first_bending, nullptr);
  EXPECT_NEAR(first_bending->frequency_hz[0], 41.9, 1.0);
  EXPECT_EQ(first_bending->label.rfind("bending 1"), first_bending->label.size() - 9) << first_bending->label;
}

}  // namespace
}  // namespace feran

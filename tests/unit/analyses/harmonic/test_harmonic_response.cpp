// The sweep shares one sparsity pattern and symbolic LU between points and solves
// them in parallel; each point must still equal a solve of that point alone.
#include <gtest/gtest.h>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/banded_lu.hpp>

#include "test_models.hpp"

namespace feran {
namespace {

Model unbalanced(Model m) {
  Unbalance u;
  u.node = 4;  // the second disk
  u.mass = 1e-3;
  u.radius = 0.1;
  m.forces.emplace_back(u);
  return m;
}

HarmonicOptions sweep(int threads) {
  HarmonicOptions opt;
  for (int i = 1; i <= 30; ++i) opt.speeds.push_back(i * 150.0 * 2 * pi / 60);
  opt.probes = {2, 4};
  opt.n_threads = threads;
  opt.stations = StationOutput::all;
  return opt;
}

void expect_point_equals_alone(const Model& model, const HarmonicResult& r, const HarmonicOptions& opt) {
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_EQ(r.speeds.size(), opt.speeds.size());
  for (std::size_t k = 0; k < opt.speeds.size(); ++k) {
    HarmonicOptions one = opt;
    one.speeds = {opt.speeds[k]};
    const HarmonicResult alone = run_harmonic_response(model, one);
    for (std::size_t p = 0; p < opt.probes.size(); ++p)
      for (std::size_t d = 0; d < dofs_per_node; ++d) {
        const Complex a = alone.probes[p].q[0][d], b = r.probes[p].q[k][d];
        // Same matrix, same ordering: equal to round-off.
        EXPECT_LE(std::abs(a - b), 1e-12 * std::abs(a) + 1e-300) << "point " << k << " probe " << p << " dof " << d;
      }
  }
}

TEST(HarmonicResponse, ResultDoesNotDependOnThreads) {
  const Model model = unbalanced(test::friswell_5_9_1());
  const HarmonicResult a = run_harmonic_response(model, sweep(1));
  const HarmonicResult b = run_harmonic_response(model, sweep(3));
  ASSERT_EQ(a.speeds.size(), b.speeds.size());
  for (std::size_t p = 0; p < a.probes.size(); ++p)
    for (std::size_t k = 0; k < a.speeds.size(); ++k)
      for (std::size_t d = 0; d < dofs_per_node; ++d) EXPECT_EQ(a.probes[p].q[k][d], b.probes[p].q[k][d]);
  ASSERT_EQ(a.stations.size(), b.stations.size());
  for (std::size_t s = 0; s < a.stations.size(); ++s)
    for (std::size_t k = 0; k < a.speeds.size(); ++k)
      EXPECT_EQ(a.stations[s].stress[k].von_mises, b.stations[s].stress[k].von_mises);
  expect_point_equals_alone(model, a, sweep(1));
}

// The station output choice: `summary` keeps per point the largest von Mises stress,
// bending moment and shear force over the stations, with the station, which must be
// the maxima of the `all` output (the same values, bit for bit) and nothing per
// station; `none` computes no station at all. The motion does not depend on it.
TEST(HarmonicResponse, StationOutputChoice) {
  const Model model = unbalanced(test::friswell_5_9_1(12));
  HarmonicOptions all = sweep(2);
  HarmonicOptions summary = all, none = all;
  summary.stations = StationOutput::summary;
  none.stations = StationOutput::none;
  const HarmonicResult a = run_harmonic_response(model, all);
  const HarmonicResult s = run_harmonic_response(model, summary);
  const HarmonicResult n = run_harmonic_response(model, none);
  ASSERT_EQ(a.stations.size(), 24u);  // both ends of 12 elements
  EXPECT_TRUE(s.stations.empty());
  EXPECT_EQ(s.shaft_stations.size(), 24u);
  ASSERT_EQ(s.station_peaks.size(), all.speeds.size());
  EXPECT_TRUE(n.stations.empty() && n.shaft_stations.empty() && n.station_peaks.empty());
  EXPECT_LT(summarize(n).stress.point, 0);
  for (std::size_t k = 0; k < all.speeds.size(); ++k) {
    Real vm = 0, moment = 0, shear = 0;
    for (const StationResponse& st : a.stations) {
      vm = std::max(vm, st.stress[k].von_mises);
      moment = std::max(moment, orbit(st.forces[k].My, st.forces[k].Mz).major);
      shear = std::max(shear, orbit(st.forces[k].Vy, st.forces[k].Vz).major);
    }
    const StationPeaks& p = s.station_peaks[k];
    EXPECT_EQ(p.von_mises.value, vm) << k;
    EXPECT_EQ(p.bending_moment.value, moment) << k;
    EXPECT_EQ(p.shear_force.value, shear) << k;
    EXPECT_EQ(a.stations[static_cast<std::size_t>(p.von_mises.station)].stress[k].von_mises, vm);
    for (std::size_t d = 0; d < dofs_per_node; ++d) EXPECT_EQ(n.probes[0].q[k][d], a.probes[0].q[k][d]);
  }
  EXPECT_EQ(summarize(s).stress.value, summarize(a).stress.value);
  EXPECT_GT(summarize(s).stress.value, 0.0);
}

// A cross-coupled spring between the two disks that switches on part-way through
// the sweep fills entries outside the pattern the sweep started with.
TEST(HarmonicResponse, SpeedDependentEntriesWidenThePattern) {
  Model model = unbalanced(test::friswell_5_9_1());
  SpringDamperCoefficients c;
  c.kyz = SpeedCoefficient(SpeedCoefficient::Step{0.0, 2e5, 1500.0 * 2 * pi / 60});
  c.kzy = SpeedCoefficient(SpeedCoefficient::Step{0.0, -2e5, 1500.0 * 2 * pi / 60});
  model.elements.emplace_back(SpringDamper(2, Index{4}, c));
  for (int threads : {1, 2}) {
    const HarmonicOptions opt = sweep(threads);
    expect_point_equals_alone(model, run_harmonic_response(model, opt), opt);
  }
}

// Issue 12: a sweep from rest on a rotor whose axial and torsional motions are free
// (singular K at Ω = 0) solved nothing and reported "singular at 0 Hz". The unbalance
// force m·e·Ω² is zero there, so the response is zero; the next points are as alone.
TEST(HarmonicResponse, ASweepFromRestWithFreeMotions) {
  Model m = unbalanced(test::friswell_5_9_1());
  m.fixed.clear();  // neither axial nor torsional motion held
  m.free_motions = {FreeMotion::axial, FreeMotion::torsion};
  HarmonicOptions opt;
  opt.speeds = {0.0, 100.0, 200.0};
  opt.probes = {4};
  const HarmonicResult r = run_harmonic_response(m, opt);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_EQ(r.probes[0].q.size(), 3u);
  for (const Complex q : r.probes[0].q[0]) EXPECT_EQ(q, Complex(0.0));
  EXPECT_GT(r.probes[0].orbit[1].major, 0.0);
}

// A pedestal node under the first journal, numbered first (its DOFs next to the
// journal's: a band of about 10) or last (joined across the whole shaft: 41 elements
// put it over 240 unknowns away, beyond the banded LU's 64). The same physics in two
// orders: the last is banded in the reverse Cuthill–McKee order (core/ordering.hpp),
// not left to the sparse LU, and both give the same response — to 1e-9 relative, the
// round-off of eliminating in two orders near the criticals (condition up to ~1e6).
Model pedestal_rotor(bool pedestal_first) {
  Model m;
  const Index pedestal_at_start = pedestal_first ? test::add_node(m, 0.0, false) : -1;
  const Index first = test::add_shaft(m, 0.0, 1.5, 41, 0.05, test::steel());
  const Index pedestal = pedestal_first ? pedestal_at_start : test::add_node(m, 0.0, false);
  const Index last = first + 41;
  m.elements.emplace_back(RigidBody(first + 14, RigidBody::disk(7810, 0.28, 0.05, 0.07), true));
  m.elements.emplace_back(RigidBody(first + 27, RigidBody::disk(7810, 0.35, 0.05, 0.07), true));
  test::add_body(m, pedestal, 20.0, 0.0, 0.0, 0.0, false);
  test::add_isotropic_bearing(m, first, 2e7, 0.0, pedestal);  // journal on its pedestal
  test::add_isotropic_bearing(m, pedestal, 1e8, 3000.0);      // pedestal to ground
  test::add_isotropic_bearing(m, last, 1e6, 200.0);           // second journal to ground
  test::fix(m, pedestal, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  test::fix(m, first, {Dof::u, Dof::rx});
  m.forces.emplace_back(Unbalance{first + 27, 1e-3, 0.1, 0.0, 0.0}, "u");
  return m;
}

TEST(HarmonicResponse, SupportNumberedFarFromItsJournalIsStillBanded) {
  for (const bool first : {true, false}) {
    const Assembler assembled(pedestal_rotor(first));
    const Index b = BandedLU::half_bandwidth(assembled.constant().K);
    if (first)
      EXPECT_LE(b, 16);
    else
      EXPECT_GT(b, 200);
  }
  HarmonicOptions opt;
  for (int i = 1; i <= 40; ++i) opt.speeds.push_back(i * 150.0 * 2 * pi / 60);
  const HarmonicResult near = [&] {
    HarmonicOptions o = opt;
    o.probes = {1 + 27, 0};
    return run_harmonic_response(pedestal_rotor(true), o);
  }();
  const HarmonicResult far = [&] {
    HarmonicOptions o = opt;
    o.probes = {27, 42};
    return run_harmonic_response(pedestal_rotor(false), o);
  }();
  ASSERT_TRUE(near.info.converged()) << near.info.message;
  ASSERT_TRUE(far.info.converged()) << far.info.message;
  EXPECT_EQ(near.info.method, SolverMethod::banded_lu);
  EXPECT_EQ(far.info.method, SolverMethod::banded_lu);
  for (std::size_t p = 0; p < 2; ++p)
    for (std::size_t k = 0; k < opt.speeds.size(); ++k) {
      Real largest = 0.0;
      for (std::size_t d = 0; d < dofs_per_node; ++d) largest = std::max(largest, std::abs(near.probes[p].q[k][d]));
      ASSERT_GT(largest, 0.0);
      for (std::size_t d = 0; d < dofs_per_node; ++d)
        EXPECT_LE(std::abs(near.probes[p].q[k][d] - far.probes[p].q[k][d]), 1e-9 * largest)
            << "probe " << p << " point " << k << " dof " << d;
    }
}

}  // namespace
}  // namespace feran

namespace feran {
namespace {

// A model built in code escapes the builder's physical ranges: an unbalance of
// 1e300 kg·m overflows the load at speed. The non-finite response is a numerical
// failure with a plain message, and the points before it are kept.
TEST(HarmonicResponse, NonFiniteResponseIsANumericalFailure) {
  Model model = test::jeffcott(10.0, 1e6, 100.0, 0.0);
  model.forces.emplace_back(Unbalance{0, 1e300, 1.0, 0.0, 0.0}, "huge");
  HarmonicOptions opt;
  opt.speeds = {0.0, 1e-160, 1e10};  // the load m·e·Ω² is 0, 1e-20 N and then infinite
  opt.probes = {0};
  const HarmonicResult r = run_harmonic_response(model, opt);
  EXPECT_EQ(r.info.status, SolverStatus::numerical_failure);
  EXPECT_NE(r.info.message.find("the response is not finite at"), std::string::npos) << r.info.message;
  ASSERT_EQ(r.speeds.size(), 2u);
  EXPECT_TRUE(std::isfinite(r.probes[0].orbit[1].major));
}

}  // namespace
}  // namespace feran

// Tests of analyses/settings: a request's values come first, then the model file's
// analysis table, then the built-in default; probes default to the unbalanced nodes;
// a response at one speed needs no last speed.

#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/modal/analysis.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/io/model_reader.hpp>

#include <gtest/gtest.h>

#include <string>

namespace feran::test_settings {
namespace {

const std::string examples = std::string(FERAN_SOURCE_DIR) + "/examples";

// The options of analysis A from a file's table and a request (analysis_options()).
template <class A>
typename A::Options options_of(const ModelSpec& spec, const typename A::Spec& request) {
  return analysis_options<A>(spec, Model{}, request, [](std::string_view k) { return std::string(k); });
}

TEST(Settings, RequestThenFileThenBuiltIn) {
  ModelSpec file;
  file.campbell.stop = 100.0;
  file.campbell.points = 11;
  CampbellSpec request;
  CampbellOptions c = options_of<CampbellAnalysis>(file, request);
  EXPECT_EQ(c.speeds.size(), 11u);  // the file's
  EXPECT_EQ(c.speeds.back(), 100.0);
  EXPECT_EQ(c.n_modes, defaults::campbell_modes);  // built in
  EXPECT_EQ(c.orders, std::vector<int>{1});
  EXPECT_EQ(c.n_threads, 1);  // the library runs on one thread
  request.points = 3;
  request.stop = 50.0;
  request.orders = {2};
  c = options_of<CampbellAnalysis>(file, request);
  EXPECT_EQ(c.speeds, (std::vector<Real>{0.0, 25.0, 50.0}));  // the request's
  EXPECT_EQ(c.orders, std::vector<int>{2});
  EXPECT_THROW((void)options_of<CampbellAnalysis>(ModelSpec{}, CampbellSpec{}), Error);  // no stop
  request.start = 60.0;                                                                  // above the last
  EXPECT_THROW((void)options_of<CampbellAnalysis>(file, request), Error);
  request.start.reset();
  request.orders = {0};  // each order checked by its field
  EXPECT_THROW((void)options_of<CampbellAnalysis>(file, request), Error);

  ModelSpec spec;
  spec.modal.speed = 12.0;
  const auto modal = [&](const ModalSpec& asked) {
    return analysis_options<ModalAnalysis>(spec, Model{}, asked, [](std::string_view k) { return std::string(k); });
  };
  EXPECT_EQ(modal({}).speed, 12.0);
  ModalSpec at_rest;
  at_rest.speed = 0.0;
  EXPECT_EQ(modal(at_rest).speed, 0.0);
  spec.modal = {};
  EXPECT_EQ(modal({}).speed, 0.0);
  EXPECT_EQ(modal({}).options.n_modes, 0);  // all (dense) or the sparse solver's
  EXPECT_FALSE(modal({}).options.shapes);
  ModalSpec sparse;
  sparse.solver = "sparse";
  EXPECT_EQ(modal(sparse).options.solver, EigenSolver::sparse);
  sparse.solver = "fast";  // checked by its field's choices
  EXPECT_THROW((void)modal(sparse), Error);
}

// The response options of @p table as a file's [response] and a request
// (analysis_options()), options named by their keys.
HarmonicOptions response_of(const ModelFile& file, const ResponseSpec& table, const ResponseSpec& request) {
  ModelSpec spec = file.spec;
  spec.response = table;
  return analysis_options<ResponseAnalysis>(spec, file.model, request,
                                            [](std::string_view k) { return std::string(k); });
}

TEST(Settings, ProbesDefaultToTheUnbalancedNodes) {
  const ModelFile file = read_model_file(examples + "/01_internal_damping/model.toml");
  // Without probes in [response]: the rotor, where the unbalance is.
  ResponseSpec without_probes = file.spec.response;
  without_probes.probes.clear();
  ResponseSpec request;
  request.stop = 100.0;
  const HarmonicOptions r = response_of(file, without_probes, request);
  EXPECT_EQ(r.probes, default_probes(file.model));
  ASSERT_EQ(r.probes.size(), 1u);
  EXPECT_EQ(r.probes[0], file.model.find_node("rotor"));
  // An added force adds its node, once.
  HarmonicForce f;
  f.node = 0;
  const std::vector<HarmonicForce> forces{f, f};
  EXPECT_EQ(default_probes(file.model, forces), (std::vector<Index>{r.probes[0], 0}));
  // A probe asked for twice, by name and by number, is refused.
  ResponseSpec twice = request;
  twice.probes = {NodeRef{std::string("rotor")},
                  NodeRef{std::int64_t{file.model.nodes[static_cast<std::size_t>(r.probes[0])].number}}};
  EXPECT_THROW((void)response_of(file, without_probes, twice), Error);
}

TEST(Settings, ResponseAtOneSpeed) {
  const ModelFile file = read_model_file(examples + "/01_internal_damping/model.toml");
  ResponseSpec one;
  one.start = 30.0;
  one.points = 1;
  EXPECT_EQ(response_of(file, ResponseSpec{}, one).speeds, std::vector<Real>{30.0});
  ResponseSpec at;
  at.speed = 40.0;
  EXPECT_EQ(response_of(file, ResponseSpec{}, at).speeds, std::vector<Real>{40.0});
  ResponseSpec sweep;
  sweep.start = 30.0;  // more than one point needs a last speed
  EXPECT_THROW((void)response_of(file, ResponseSpec{}, sweep), Error);
}

// A response's speed sweep and its fixed speed are alternatives: a request that asks
// for one takes none of the other from the file; one that asks for both is refused.
TEST(Settings, ResponseSweepsAreAlternatives) {
  const ModelFile file = read_model_file(examples + "/01_internal_damping/model.toml");
  ResponseSpec speeds;  // the file's speed sweep
  speeds.start = 10.0;
  speeds.stop = 50.0;
  speeds.points = 5;
  ResponseSpec at;
  at.speed = 40.0;
  EXPECT_EQ(response_of(file, speeds, at).speeds, std::vector<Real>{40.0});
  ResponseSpec last;  // the file's start and points stay
  last.stop = 90.0;
  EXPECT_EQ(response_of(file, speeds, last).speeds, (std::vector<Real>{10.0, 30.0, 50.0, 70.0, 90.0}));

  ResponseSpec frequencies;  // the file's frequency sweep at 20 rad/s
  frequencies.speed = 20.0;
  frequencies.freq_start = 1.0;
  frequencies.freq_stop = 3.0;
  frequencies.freq_points = 3;
  frequencies.forces = {"rotor:y:1N"};
  const HarmonicOptions f = response_of(file, frequencies, {});
  EXPECT_EQ(f.frequencies, (std::vector<Real>{1.0, 2.0, 3.0}));
  EXPECT_EQ(f.speed, 20.0);
  ASSERT_EQ(f.extra_forces.size(), 1u);
  EXPECT_EQ(f.extra_forces[0].node, file.model.find_node("rotor"));
  EXPECT_EQ(response_of(file, frequencies, at).speed, 40.0);  // the same sweep at another speed
  const HarmonicOptions s = response_of(file, frequencies, last);
  EXPECT_TRUE(s.frequencies.empty());  // a speed sweep instead, from the default start
  EXPECT_EQ(s.speeds.front(), 0.0);
  EXPECT_EQ(s.speeds.back(), 90.0);

  ResponseSpec both = last;
  both.speed = 40.0;
  EXPECT_THROW((void)response_of(file, ResponseSpec{}, both), Error);
  ResponseSpec half;
  half.freq_start = 1.0;  // a frequency sweep needs its last frequency
  EXPECT_THROW((void)response_of(file, ResponseSpec{}, half), Error);
  half.freq_start = 5.0;  // the file's last frequency, 3 rad/s, is below it
  EXPECT_THROW((void)response_of(file, frequencies, half), Error);
  ResponseSpec wrong;
  wrong.stop = 90.0;
  wrong.forces = {"rotor:q:1N"};  // no direction q
  EXPECT_THROW((void)response_of(file, ResponseSpec{}, wrong), Error);
}

// The static options of a file's [static] table and a request (analysis_options()).
StaticOptions static_of(const StaticSpec& table, const StaticSpec& request) {
  ModelSpec spec;
  spec.static_ = table;
  return analysis_options<StaticAnalysis>(spec, Model{}, request, [](std::string_view k) { return std::string(k); });
}

TEST(Settings, StaticGravity) {
  StaticSpec file;
  EXPECT_EQ(static_of(file, {}).gravity, Eigen::Vector3d(0.0, -defaults::gravity, 0.0));
  file.gravity = "+x";
  file.g = 1.62;
  EXPECT_EQ(static_of(file, {}).gravity, Eigen::Vector3d(1.62, 0.0, 0.0));
  StaticSpec request;
  request.g = 3.0;  // a magnitude asked for applies to the file's direction
  EXPECT_EQ(static_of(file, request).gravity, Eigen::Vector3d(3.0, 0.0, 0.0));
  request = {};
  request.gravity = "-z";  // a direction asked for takes the built-in magnitude
  EXPECT_EQ(static_of(file, request).gravity, Eigen::Vector3d(0.0, 0.0, -defaults::gravity));
  request.gravity = "none";
  EXPECT_EQ(static_of(file, request).gravity, Eigen::Vector3d::Zero());
  request.g = 5.0;  // a magnitude without a direction
  EXPECT_THROW((void)static_of(file, request), Error);
  request = {};
  request.gravity = "down";  // checked by its field's choices
  EXPECT_THROW((void)static_of(file, request), Error);
  request = {};
  request.speed = -1.0;  // and bounds
  EXPECT_THROW((void)static_of(file, request), Error);
  // Flags: the defaults unless asked; the file may set them too.
  EXPECT_TRUE(static_of(file, {}).loads);
  EXPECT_TRUE(static_of(file, {}).stability);
  request.speed.reset();
  request.loads = false;
  EXPECT_FALSE(static_of(file, request).loads);
  file.stability = false;
  EXPECT_FALSE(static_of(file, {}).stability);
}

TEST(Settings, RunupProfileForms) {
  const ModelFile file = read_model_file(examples + "/01_internal_damping/model.toml");
  // The file's ramp (0 → 80 Hz in 5 s) with its duration.
  const TransientOptions from_file = runup_options(file);
  EXPECT_EQ(from_file.profile.points().size(), 2u);
  EXPECT_EQ(from_file.duration, 5.0);
  // A request's profile replaces the file's, and its own length is the duration.
  RunupSpec ramp;
  ramp.to = 100.0;
  ramp.ramp_time = 2.0;
  EXPECT_EQ(runup_options(file, ramp).duration, 2.0);
  RunupSpec two = ramp;
  two.speed = 10.0;
  EXPECT_THROW((void)runup_options(file, two), Error);
  RunupSpec half;
  half.to = 10.0;  // a ramp needs its time
  EXPECT_THROW((void)runup_options(file, half), Error);
  EXPECT_THROW((void)spring_element(file.model, "no such spring"), Error);
}

// A run-up that keeps no samples keeps the same envelopes, peaks and end state: the
// samples are only recorded, never used by the integration (an invariant of the run).
TEST(Settings, RunupWithoutSamplesKeepsItsPeaks) {
  const ModelFile file = read_model_file(examples + "/01_internal_damping/model.toml");
  RunupSpec shorter;
  shorter.duration = 0.2;
  const TransientOptions with = runup_options(file, shorter);
  EXPECT_TRUE(with.keep_samples);  // the default
  shorter.samples = false;
  const TransientOptions without = runup_options(file, shorter);
  EXPECT_FALSE(without.keep_samples);
  const TransientResult a = run_transient(file.model, with), b = run_transient(file.model, without);
  ASSERT_TRUE(a.info.converged() && b.info.converged());
  EXPECT_EQ(a.samples.size(), 201u);  // 0.2 s every 1 ms, both ends
  EXPECT_TRUE(b.samples.empty());
  ASSERT_EQ(a.envelopes.size(), b.envelopes.size());
  for (std::size_t p = 0; p < a.envelopes.size(); ++p) {
    EXPECT_EQ(a.envelopes[p].peak, b.envelopes[p].peak);  // bit for bit
    EXPECT_EQ(a.envelopes[p].peak_time, b.envelopes[p].peak_time);
  }
  EXPECT_EQ(a.t_end, b.t_end);
  EXPECT_EQ(a.steps, b.steps);
}

// A tabulated coefficient evaluated beyond its speeds is held at its last value; the
// analyses say so once per table (issue 12).
TEST(Settings, WarningsForTablesEvaluatedBeyondTheirRange) {
  const ModelFile file = read_model_file(std::string(FERAN_TEST_MODELS) + "/valid/speed_table.toml");
  const Real table_end = 2 * pi * 50.0;
  EXPECT_TRUE(range_warnings(file.model, 0.0, table_end).empty());  // up to its end: none
  EXPECT_TRUE(range_warnings(file.model, 10.0, 0.5 * table_end).empty());
  const std::vector<std::string> beyond = range_warnings(file.model, 0.0, 2 * table_end);
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_NE(beyond[0].find("'left': coefficient 'ky' is tabulated from 0 to 50 Hz"), std::string::npos);
  EXPECT_NE(beyond[0].find("reaches 100 Hz"), std::string::npos);
}

}  // namespace
}  // namespace feran::test_settings

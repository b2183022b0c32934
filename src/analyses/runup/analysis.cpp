// The run-up's room: its options ([runup]), their defaults and checks, its run with the
// CSV streamed and the progress told, and its study quantities
// (analyses/runup/analysis.hpp). Its writers are in writers.cpp.
#include <feran/analyses/runup/analysis.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/settings.hpp>
#include <feran/integrators/integrator.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/request.hpp>
#include <feran/study/design_analyses.hpp>

namespace feran {

namespace spec {

namespace {
constexpr std::string_view runup_starts[] = {"rest", "equilibrium", "steady"};
constexpr std::string_view jacobians[] = {"exact", "linear"};

// The integrators of the registry (integrator_names()), as a field's choices.
std::span<const std::string_view> integrator_choices() {
  static const std::vector<std::string> names = integrator_names();
  static const std::vector<std::string_view> views(names.begin(), names.end());
  return views;
}
}  // namespace

template <>
const FieldTable<RunupSpec>& fields_of<RunupSpec>() {
  using S = RunupSpec;
  using K = FieldKind;
  const Bound non_negative{Bound::Kind::non_negative};
  const Bound positive{Bound::Kind::positive};
  static const FieldTable<S> table = {
      {.key = "speed",
       .kind = K::quantity,
       .member = &S::speed,
       .doc = "a constant rotor speed",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .group = "profile",
       .short_name = "s"},
      {.key = "from",
       .kind = K::quantity,
       .member = &S::from,
       .doc = "speed at t = 0 of a ramp (only with `to` and `ramp_time`)",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "`0`",
       .group = "profile"},
      {.key = "to",
       .kind = K::quantity,
       .member = &S::to,
       .doc = "speed at the end of the ramp; below `from` for a run-down",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "required for a ramp",
       .group = "profile"},
      {.key = "ramp_time",
       .kind = K::quantity,
       .member = &S::ramp_time,
       .doc = "time the ramp takes",
       .quantity = Quantity::time,
       .bound = positive,
       .default_text = "required for a ramp",
       .group = "profile"},
      {.key = "table",
       .kind = K::time_table,
       .member = &S::table,
       .doc = "at least one pair; the first time is 0 and the times strictly increase; speeds ≥ 0 (on the command "
              "line TIME:SPEED,…, e.g. 0s:0Hz,2s:50Hz,5s:50Hz)",
       .quantity = Quantity::speed,
       .unit = "Hz",
       .group = "profile"},
      {.key = "duration",
       .kind = K::quantity,
       .member = &S::duration,
       .doc = "length of the run; longer than the profile, the last speed is held",
       .quantity = Quantity::time,
       .bound = positive,
       .default_text = "the ramp time, or the last time of `table` (when > 0)",
       .follows = "profile",
       .short_name = "t"},
      {.key = "integrator",
       .kind = K::choice,
       .member = &S::integrator,
       .doc = "the time integrator, one of the registry's (docs/theory/time_integration.md)",
       .choices = integrator_choices(),
       .short_name = "i"},
      {.key = "dt",
       .kind = K::quantity,
       .member = &S::dt,
       .doc = "the fixed step, or the initial step of the adaptive `\"ros34pw2\"`",
       .quantity = Quantity::time,
       .bound = positive},
      {.key = "rel_tol",
       .kind = K::number,
       .member = &S::rel_tol,
       .doc = "relative error tolerance of adaptive stepping",
       .bound = positive,
       .option = "rtol"},
      {.key = "abs_tol",
       .kind = K::number,
       .member = &S::abs_tol,
       .doc = "absolute error tolerance of adaptive stepping (in the units of the state: m, rad, m/s, rad/s)",
       .bound = positive,
       .option = "atol"},
      {.key = "output_interval",
       .kind = K::quantity,
       .member = &S::output_interval,
       .doc = "time between recorded samples",
       .quantity = Quantity::time,
       .bound = positive},
      {.key = "probes",
       .kind = K::node_list,
       .member = &S::probes,
       .doc = "non-empty, no node twice: the nodes whose motion is recorded (one per option on the command line)",
       .default_text = "every node carrying an unbalance",
       .if_empty = "leave it out for the analysis's default",
       .option = "probe"},
      {.key = "springs",
       .kind = K::text_list,
       .member = &S::springs,
       .doc = "non-empty, no spring twice: the spring–dampers whose forces are recorded, each the `name` of a "
              "`[[springs]]` entry (one per option on the command line)",
       .default_text = "none",
       .if_empty = "leave it out for the analysis's default",
       .option = "spring"},
      {.key = "modes",
       .kind = K::integer,
       .member = &S::modes,
       .doc = "integrate in a basis of this many undamped modes (at 5 speeds of the run) plus static corrections "
              "instead of the full model; lets rk3 take long steps (docs/theory/time_integration.md, \"Modal "
              "reduction\")",
       .bound = {Bound::Kind::at_least, 1},
       .default_text = "— (full model)"},
      {.key = "gravity",
       .kind = K::flag,
       .member = &S::gravity,
       .doc = "apply the gravity of `[static]` (its `gravity` and `g`; 9.81 m/s² along −y when not given) as a "
              "constant force M·g"},
      {.key = "static_loads",
       .kind = K::flag,
       .member = &S::static_loads,
       .doc = "apply the `[[static_loads]]` as constant forces"},
      {.key = "start",
       .kind = K::choice,
       .member = &S::start,
       .doc = "the state at t = 0: at rest; at the static equilibrium at the first speed under the run's gravity and "
              "static loads (with journal bearings the first speed must be above 0); or steady, that equilibrium plus "
              "the steady unbalance response at the first speed (linearised about it)",
       .choices = runup_starts},
      {.key = "drive",
       .kind = K::flag,
       .member = &S::drive,
       .doc = "torque-driven: the speed is a state, driven by the model's `[drive]` from the profile's first speed "
              "(`speed` or `from`; the rest of the profile is not used; needs `duration`)"},
      {.key = "newton_tol",
       .kind = K::number,
       .member = &S::newton_tol,
       .doc = "trapezoidal: the Newton iteration's tolerance",
       .bound = positive},
      {.key = "newton_max_iter",
       .kind = K::integer,
       .member = &S::newton_max_iter,
       .doc = "trapezoidal: the most Newton iterations of a step",
       .bound = {Bound::Kind::at_least, 1, 10000}},
      {.key = "allow_unstable",
       .kind = K::flag,
       .member = &S::allow_unstable,
       .doc = "rk3: warn instead of refusing a step above the method's stability limit"},
      {.key = "jacobian",
       .kind = K::choice,
       .member = &S::jacobian,
       .doc = "W-methods: the Jacobian of the forces, `\"exact\"` (with the friction tangents) or `\"linear\"`",
       .choices = jacobians},
      {.key = "jacobian_interval",
       .kind = K::integer,
       .member = &S::jacobian_interval,
       .doc = "W-methods: steps between Jacobian refreshes",
       .bound = {Bound::Kind::at_least, 1, 1000000}},
      {.key = "blowup",
       .kind = K::quantity,
       .member = &S::blowup,
       .doc = "a displacement at which the run ends as diverged",
       .quantity = Quantity::length,
       .bound = positive,
       .unit = "m"},
      {.key = "samples",
       .kind = K::flag,
       .member = &S::samples,
       .doc = "whether the result keeps every sample (the JSON's time histories, Python's arrays); false keeps the "
              "envelopes, peaks and clearance use only, for long runs (the CSV still gets every sample)"},
  };
  return table;
}

}  // namespace spec

const RunupSpec& RunupAnalysis::defaults() {
  static const RunupSpec d = [] {
    const IntegratorSettings s;
    RunupSpec r;
    r.integrator = "trapezoidal";
    r.dt = defaults::runup_dt;
    r.rel_tol = s.rel_tol;
    r.abs_tol = s.abs_tol;
    r.output_interval = defaults::output_interval;
    r.gravity = false;
    r.static_loads = false;
    r.start = "rest";
    r.drive = false;
    r.newton_tol = s.newton_tol;
    r.newton_max_iter = s.newton_max_iterations;
    r.allow_unstable = s.allow_unstable_step;
    r.jacobian = s.exact_jacobian ? "exact" : "linear";
    r.jacobian_interval = s.jacobian_interval;
    r.blowup = TransientOptions{}.blowup_limit;
    r.samples = true;
    return r;
  }();
  return d;
}

namespace {

// A table asked for, by the file's rule: from time 0, strictly increasing times.
void check_table(const std::vector<std::pair<Real, Real>>& table, const std::string& name) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Real time = table[i].first;
    if (!(table[i].second >= 0))
      throw Error(
          fmt::format("{} point {}: must not be negative, got {:g} Hz", name, i + 1, rad_to_hz(table[i].second)));
    if (i == 0 && time != 0.0)
      throw Error(fmt::format("{} must start at time 0, where the run-up starts, but its first time is {}", name,
                              format_quantity(time, Quantity::time)));
    if (i > 0 && !(time > table[i - 1].first))
      throw Error(fmt::format(
          "{}: the times must be strictly increasing, but point {} ({}) does not come after point {} ({})", name, i + 1,
          format_quantity(time, Quantity::time), i, format_quantity(table[i - 1].first, Quantity::time)));
  }
}

// The speed profile asked for and the run's duration.
void set_profile(TransientOptions& options, const RunupSpec& asked, const OptionName& named) {
  const bool ramp = asked.from || asked.to || asked.ramp_time;
  const int forms =
      static_cast<int>(asked.speed.has_value()) + static_cast<int>(ramp) + static_cast<int>(!asked.table.empty());
  if (forms > 1)
    throw Error(fmt::format("runup: give one speed profile: {}, {}/{}/{}, or {}", named("speed"), named("from"),
                            named("to"), named("ramp_time"), named("table")));
  check_table(asked.table, named("table"));
  std::optional<Real> natural_duration;
  if (asked.speed) {
    options.profile = SpeedProfile::constant(*asked.speed);
  } else if (ramp) {
    if (!asked.to || !asked.ramp_time)
      throw Error(fmt::format("runup: a ramp needs {} and {}", named("to"), named("ramp_time")));
    options.profile = SpeedProfile::ramp(asked.from.value_or(0.0), *asked.to, *asked.ramp_time);
    natural_duration = *asked.ramp_time;
  } else if (!asked.table.empty()) {
    options.profile = SpeedProfile(asked.table);
    natural_duration = asked.table.back().first;
  } else {
    throw Error(fmt::format("runup: give a speed profile ({}, {}/{}/{} or {}) or a [runup] table", named("speed"),
                            named("from"), named("to"), named("ramp_time"), named("table")));
  }
  if (asked.duration)
    options.duration = *asked.duration;
  else if (natural_duration && *natural_duration > 0)
    options.duration = *natural_duration;
  else
    throw Error(fmt::format("runup: give the simulated time with {} (e.g. 2s)", named("duration")));
}

// The integrator and its settings, with the bounds on the run's work and output.
void set_integration(TransientOptions& options, const RunupSpec& resolved) {
  options.integrator = *resolved.integrator;
  IntegratorSettings& s = options.settings;
  s.dt = *resolved.dt;
  s.rel_tol = *resolved.rel_tol;
  s.abs_tol = *resolved.abs_tol;
  s.newton_tol = *resolved.newton_tol;
  s.newton_max_iterations = *resolved.newton_max_iter;
  s.allow_unstable_step = *resolved.allow_unstable;
  s.exact_jacobian = *resolved.jacobian == "exact";
  s.jacobian_interval = *resolved.jacobian_interval;
  options.reduced_modes = resolved.modes.value_or(0);
  options.output_interval = *resolved.output_interval;
  options.blowup_limit = *resolved.blowup;
  options.keep_samples = *resolved.samples;
  const Real samples = options.duration / options.output_interval;
  if (samples > defaults::max_runup_samples)
    throw Error(
        fmt::format("runup: a duration of {:g} s sampled every {:g} s is {:.3g} samples; at most {:g} are "
                    "recorded (a longer output interval or a shorter duration)",
                    options.duration, options.output_interval, samples, defaults::max_runup_samples));
  const Real steps = options.duration / s.dt;
  if (steps > defaults::max_runup_steps && !make_integrator(options.integrator, s)->adaptive())
    throw Error(
        fmt::format("runup: a duration of {:g} s at a step of {:g} s is {:.3g} steps; at most {:g} are "
                    "taken (a longer step or a shorter duration)",
                    options.duration, s.dt, steps, defaults::max_runup_steps));
}

// The nodes and springs recorded: those asked for, each once.
void set_recorded(TransientOptions& options, const Model& model, const RunupSpec& resolved, const OptionName& named) {
  options.probes = distinct_nodes(model, resolved.probes, named("probes"));
  if (options.probes.empty()) options.probes = default_probes(model);
  for (const std::string& name : resolved.springs) {
    Index e = -1;
    try {
      e = spring_element(model, name);
    } catch (const Error&) {
      throw Error(fmt::format("{} '{}': no spring-damper has that name", named("springs"), name));
    }
    if (std::find(options.springs.begin(), options.springs.end(), e) != options.springs.end())
      throw Error(fmt::format("{}: spring '{}' is given twice", named("springs"), name));
    options.springs.push_back(e);
  }
}

}  // namespace

TransientOptions RunupAnalysis::settings(const Model& model, const RunupSpec& asked, const RunupSpec& resolved,
                                         const OptionName& named) {
  TransientOptions options;
  set_profile(options, asked, named);
  set_integration(options, resolved);
  options.static_loads = *resolved.static_loads;
  if (*resolved.gravity) options.gravity = model.gravity;
  const std::string& start = *resolved.start;
  options.start = start == "rest"          ? RunupStart::rest
                  : start == "equilibrium" ? RunupStart::equilibrium
                                           : RunupStart::steady_state;
  options.driven = *resolved.drive;
  if (options.driven && !model.drive)
    throw Error("runup: a torque-driven run needs a [drive] table in the model (its motor and load torques)");
  set_recorded(options, model, resolved, named);
  return options;
}

TransientResult RunupAnalysis::run(const Model& model, const TransientOptions& options, const RunContext& context) {
  TransientOptions o = options;
  o.stop = context.stop;
  if (!o.assembled) o.assembled = context.assembler;
  SampleSink on_sample;
  if (context.csv) {
    context.csv(runup_csv_header(model, o));
    on_sample = [&](const TransientSample& s) { context.csv(runup_csv_row(s)); };
  }
  ProgressSink progress;
  if (context.progress)
    progress = [&](Real t, Real dt) {
      const std::string speed =
          o.driven ? std::string() : fmt::format(", speed {:.4g} Hz", rad_to_hz(o.profile.speed(t)));
      context.progress(t / o.duration, fmt::format("{}: t = {:.4g} / {:.4g} s{}, step {:.3g} s", o.integrator, t,
                                                   o.duration, speed, dt));
    };
  const auto t0 = std::chrono::steady_clock::now();
  TransientResult result = run_transient(model, o, on_sample, progress);
  result.wall_seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - t0).count();
  // Refused before the first step (rk3 above its stability limit): a bad option.
  if (result.info.status == SolverStatus::numerical_failure && result.steps == 0) throw Error(result.info.message);
  return result;
}

std::vector<std::string> RunupAnalysis::warnings(const Model& model, const TransientOptions& options,
                                                 const TransientResult& result) {
  // The speeds the run went through: its samples', else those its profile visits.
  auto [low, high] = speed_span(model, options);
  if (!result.samples.empty()) {
    const auto [a, b] = std::minmax_element(result.samples.begin(), result.samples.end(),
                                            [](const auto& x, const auto& y) { return x.speed < y.speed; });
    low = a->speed;
    high = b->speed;
  }
  return range_warnings(model, low, high);
}

TransientOptions runup_options(const ModelFile& file, const RunupSpec& request) {
  return analysis_options<RunupAnalysis>(file, request, file_key_name<RunupAnalysis>());
}

// ---- study quantities ----------------------------------------------------------------

namespace {

Real runup_peak(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const TransientResult& r = a.result<RunupAnalysis>();
  const std::vector<Index>& nodes = a.options<RunupAnalysis>().probes;
  if (nodes.empty()) throw Error("the run-up records no probe: give the quantity a 'probe'");
  const Index node = q.probe ? node_index(a.model(), *q.probe) : nodes.front();
  const auto at = std::find(nodes.begin(), nodes.end(), node);
  return r.envelopes[static_cast<std::size_t>(at - nodes.begin())].peak;
}

Real runup_spring_force(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const TransientResult& r = a.result<RunupAnalysis>();
  const std::vector<Index>& springs = a.options<RunupAnalysis>().springs;
  const Index only = q.spring ? spring_element(a.model(), *q.spring) : -1;
  Real peak = 0;
  for (const auto& sample : r.samples)
    for (std::size_t i = 0; i < springs.size(); ++i)
      if (only < 0 || springs[i] == only) peak = std::max(peak, std::hypot(sample.springs[i][1], sample.springs[i][2]));
  return peak;
}

}  // namespace

const std::vector<QuantityRow>& RunupAnalysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "runup_peak",
       .doc = "largest |r| at a probe during the run-up",
       .analysis = "runup",
       .unit = Quantity::length,
       .evaluate = runup_peak},
      {.name = "runup_spring_force",
       .doc = "largest lateral force of a spring (or of all) during the run-up",
       .analysis = "runup",
       .unit = Quantity::force,
       .evaluate = runup_spring_force},
  };
  return rows;
}

RunupSpec RunupAnalysis::study_request(const Model& model, std::span<const QuantitySpec> quantities) {
  RunupSpec request;
  request.probes = quantity_probes(model, quantities, name);
  // The samples only where a spring's force is read off them (the peaks need none).
  request.samples = std::any_of(quantities.begin(), quantities.end(),
                                [](const QuantitySpec& q) { return q.kind == "runup_spring_force"; });
  std::vector<Index> springs;
  const auto add_spring = [&](Index e) {
    if (std::find(springs.begin(), springs.end(), e) != springs.end()) return;
    springs.push_back(e);
    request.springs.push_back(model.elements[static_cast<std::size_t>(e)].label());
  };
  for (const QuantitySpec& q : quantities) {
    if (q.kind != "runup_spring_force") continue;
    if (q.spring) {
      add_spring(spring_element(model, *q.spring));
    } else {
      for (Index e = 0; e < static_cast<Index>(model.elements.size()); ++e)
        if (model.elements[static_cast<std::size_t>(e)].connection()) add_spring(e);  // every spring–damper
    }
  }
  return request;
}

}  // namespace feran

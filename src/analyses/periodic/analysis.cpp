// The periodic orbits' room: its options ([orbits]), their defaults and checks, the run
// (the condensation, the branches asked for, the orbits at the probes) and its study
// quantities (analyses/periodic/analysis.hpp). The writers are in writers.cpp.
#include <feran/analyses/periodic/analysis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include <feran/analyses/periodic/aft.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/spec/build_model.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/study/design_analyses.hpp>

namespace feran {

namespace spec {

namespace {
constexpr std::string_view branch_choices[] = {"auto", "forced", "whirl", "equilibrium"};
constexpr std::string_view direction_choices[] = {"up", "down", "both"};
constexpr std::string_view speed_range = "speed range", parameter_range = "parameter range";
}  // namespace

template <>
const FieldTable<OrbitsSpec>& fields_of<OrbitsSpec>() {
  using S = OrbitsSpec;
  using K = FieldKind;
  const Bound non_negative{Bound::Kind::non_negative};
  static const FieldTable<S> table = {
      {.key = "from",
       .kind = K::quantity,
       .member = &S::from,
       .doc = "the lowest speed of the branches",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "required for a speed range",
       .alternative = speed_range},
      {.key = "to",
       .kind = K::quantity,
       .member = &S::to,
       .doc = "the highest speed of the branches, above `from`",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "required for a speed range",
       .alternative = speed_range},
      {.key = "parameter",
       .kind = K::text,
       .member = &S::parameter,
       .doc = "a parameter path (as studies and --set name them, e.g. `journal_bearings[bearing A].viscosity`) "
              "continued at the fixed `speed` instead of the speed",
       .default_text = "none: the branches are over speed",
       .alternative = parameter_range},
      {.key = "parameter_from",
       .kind = K::text,
       .member = &S::parameter_from,
       .doc = "the parameter's first value, with its unit (`\"10 mPa*s\"`) or in SI",
       .default_text = "required with `parameter`",
       .alternative = parameter_range},
      {.key = "parameter_to",
       .kind = K::text,
       .member = &S::parameter_to,
       .doc = "the parameter's last value, above `parameter_from`",
       .default_text = "required with `parameter`",
       .alternative = parameter_range},
      {.key = "speed",
       .kind = K::quantity,
       .member = &S::speed,
       .doc = "the rotor speed of a branch in `parameter`",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "required with `parameter`",
       .short_name = "s",
       .alternative = parameter_range},
      {.key = "branch",
       .kind = K::choice,
       .member = &S::branch,
       .doc = "which steady states: `forced` the orbits at the rotor speed the unbalances drive, `whirl` the static "
              "equilibrium without the unbalances and the self-excited orbits leaving each of its Hopf points, "
              "`equilibrium` the equilibrium alone, `auto` forced when an unbalance acts, else whirl",
       .choices = branch_choices},
      {.key = "direction",
       .kind = K::choice,
       .member = &S::direction,
       .doc = "a forced branch followed up from the range's start, down from its end (a run-down), or both (its "
              "hysteresis); a branch from `start_at` followed from there up, down or both",
       .choices = direction_choices,
       .default_text = "`\"up\"`; `\"both\"` with `start_at`"},
      {.key = "start_at",
       .kind = K::text,
       .member = &S::start_at,
       .doc = "a value within the range — a speed (`\"90 Hz\"`) over speed, the parameter's value with its unit in "
              "a parameter branch — where a run at constant speed finds the orbit the rotor settles on (from its "
              "equilibrium, nudged); the branch through that orbit is followed from it instead of the branches from "
              "the equilibrium: an orbit beyond a fold, or a whirl where the equilibrium is unstable over the whole "
              "range",
       .default_text = "none: the branches start from the equilibrium or the range's end"},
      {.key = "settle",
       .kind = K::quantity,
       .member = &S::settle,
       .doc = "the longest simulated time of the run of `start_at`; it ends as soon as its motion repeats",
       .quantity = Quantity::time,
       .bound = {Bound::Kind::positive},
       .unit = "s",
       .default_text = "2000 revolutions"},
      {.key = "harmonics",
       .kind = K::integer,
       .member = &S::harmonics,
       .doc = "harmonics of the base frequency in each orbit",
       .bound = {Bound::Kind::at_least, 1, 64}},
      {.key = "samples",
       .kind = K::integer,
       .member = &S::samples,
       .doc = "time samples per period of the alternating frequency–time step; at least 2·harmonics + 1",
       .bound = {Bound::Kind::at_least, 3, 4096},
       .default_text = "8 · harmonics"},
      {.key = "modes",
       .kind = K::integer,
       .member = &S::modes,
       .doc = "fixed-interface modes kept in the condensation onto the nonlinear forces' DOFs",
       .bound = {Bound::Kind::at_least, 0, 10000}},
      {.key = "points",
       .kind = K::integer,
       .member = &S::points,
       .doc = "most steady states on each branch",
       .bound = {Bound::Kind::at_least, 2, 100000}},
      {.key = "probes",
       .kind = K::node_list,
       .member = &S::probes,
       .doc = "non-empty, no node twice: the nodes whose orbits are reported (one per option on the command line)",
       .default_text = "every node carrying an unbalance, then every node of a nonlinear force",
       .if_empty = "leave it out for the analysis's default",
       .option = "probe"},
      {.key = "gravity",
       .kind = K::flag,
       .member = &S::gravity,
       .doc = "apply the gravity of [static] (its default: -y at 9.81 m/s²)"},
      {.key = "static_loads", .kind = K::flag, .member = &S::static_loads, .doc = "apply the [[static_loads]]"},
  };
  return table;
}

}  // namespace spec

const OrbitsSpec& OrbitsAnalysis::defaults() {
  static const OrbitsSpec d = [] {
    OrbitsSpec s;
    s.branch = "auto";
    s.direction = "up";
    s.harmonics = 8;
    s.modes = 12;
    s.points = 200;
    s.gravity = true;
    s.static_loads = true;
    return s;
  }();
  return d;
}

namespace {

// The probes: those asked for, else the unbalances' nodes and the nonlinear forces'.
std::vector<Index> probes_of(const Model& model, const OrbitsSpec& resolved, const OptionName& named) {
  std::vector<Index> probes = distinct_nodes(model, resolved.probes, named("probes"));
  if (!probes.empty()) return probes;
  probes = default_probes(model);
  for (const Force& f : model.forces)
    if (f.is_nonlinear())
      for (const Index node : f.nodes())
        if (std::find(probes.begin(), probes.end(), node) == probes.end()) probes.push_back(node);
  return probes;
}

// A parameter value written with its unit (or in SI), in SI.
Real parameter_value(const ModelSpec& spec, const std::string& path, const std::string& text,
                     const std::string& option) {
  ModelSpec copy = spec;
  try {
    set_parameter(copy, path, text);
    return get_parameter(copy, path).value;
  } catch (const ParameterError& e) {
    throw Error(fmt::format("{} '{}': {}", option, text, e.what()));
  }
}

// The branch in a parameter path at a fixed speed.
void set_parameter_range(OrbitsOptions& options, const ModelSpec& spec, const OrbitsSpec& asked,
                         const OptionName& named) {
  if (asked.from || asked.to)
    throw Error(fmt::format("{} continues in a parameter at the fixed {}; leave out {} and {} (the speed range)",
                            named("parameter"), named("speed"), named("from"), named("to")));
  if (!asked.parameter_from || !asked.parameter_to || !asked.speed)
    throw Error(fmt::format("{} needs {}, {} and {}", named("parameter"), named("parameter_from"),
                            named("parameter_to"), named("speed")));
  Parameter p;
  try {
    p = get_parameter(spec, *asked.parameter);
  } catch (const ParameterError& e) {
    throw Error(fmt::format("{}: {}", named("parameter"), e.what()));
  }
  if (p.integer) throw Error(fmt::format("{} '{}' is a count; a branch follows a number", named("parameter"), p.path));
  options.parameter = p.path;
  options.parameter_quantity = p.quantity;
  options.parameter_unit = p.unit;
  options.from = parameter_value(spec, p.path, *asked.parameter_from, named("parameter_from"));
  options.to = parameter_value(spec, p.path, *asked.parameter_to, named("parameter_to"));
  if (!(options.to > options.from))
    throw Error(fmt::format("{} ({}) must be above {} ({})", named("parameter_to"), *asked.parameter_to,
                            named("parameter_from"), *asked.parameter_from));
  options.speed = *asked.speed;
  // Each member of the family is the file's model with the parameter set; a value the
  // model refuses ends the branch with build_model's reason.
  options.build = [spec = std::make_shared<const ModelSpec>(spec), path = p.path](Real value) {
    ModelSpec s = *spec;
    set_parameter(s, path, value);
    return build_model(s);
  };
}

// Where the run that finds the branch's first orbit is made.
void set_start(OrbitsOptions& options, const ModelSpec& spec, const std::string& text, const OptionName& named) {
  if (options.branch == "equilibrium")
    throw Error(
        fmt::format("{} finds the orbit a run settles on, and branch \"equilibrium\" follows no orbit: "
                    "leave out one of them",
                    named("start_at")));
  Real at = 0;
  if (options.build) {
    at = parameter_value(spec, options.parameter, text, named("start_at"));
  } else {
    char* end = nullptr;
    (void)std::strtod(text.c_str(), &end);
    if (end != text.c_str() && *end == '\0')
      throw Error(fmt::format("{} '{}': give a speed with its unit ('90 Hz', '5400 rpm')", named("start_at"), text));
    try {
      at = parse_quantity(text, Quantity::speed);
    } catch (const QuantityError& e) {
      throw Error(fmt::format("{} '{}': {}", named("start_at"), text, e.what()));
    }
    if (!(at > 0)) throw Error(fmt::format("{} ({}) must be a speed above 0", named("start_at"), text));
  }
  if (at < options.from || at > options.to)
    throw Error(fmt::format("{} ({}) must lie within the branch's range, {} to {}", named("start_at"), text,
                            options.build ? fmt::format("{:g}", options.from) : rpm(options.from),
                            options.build ? fmt::format("{:g}", options.to) : rpm(options.to)));
  options.start_at = at;
}

}  // namespace

OrbitsOptions OrbitsAnalysis::settings(const Model& model, const ModelSpec& spec, const OrbitsSpec& asked,
                                       const OrbitsSpec& resolved, const OptionName& named) {
  OrbitsOptions options;
  if (asked.parameter || asked.parameter_from || asked.parameter_to) {
    if (!asked.parameter)
      throw Error(fmt::format("{} and {} need {} (the path they are values of)", named("parameter_from"),
                              named("parameter_to"), named("parameter")));
    set_parameter_range(options, spec, asked, named);
  } else {
    if (asked.speed)
      throw Error(fmt::format("{} is the fixed speed of a branch in {}; over speed give {} and {}", named("speed"),
                              named("parameter"), named("from"), named("to")));
    if (!asked.from || !asked.to)
      throw Error(fmt::format("orbits: give the speed range with {} and {} (e.g. {} 50Hz {} 150Hz)", named("from"),
                              named("to"), named("from"), named("to")));
    if (!(*asked.to > *asked.from))
      throw Error(fmt::format("{} ({}) must be above {} ({})", named("to"), format_quantity(*asked.to, Quantity::speed),
                              named("from"), format_quantity(*asked.from, Quantity::speed)));
    options.from = *asked.from;
    options.to = *asked.to;
  }
  options.branch = *resolved.branch;
  const std::string direction = asked.start_at && !asked.direction ? "both" : *resolved.direction;
  options.up = direction != "down";
  options.down = direction != "up";
  if (asked.start_at) set_start(options, spec, *asked.start_at, named);
  if (asked.settle && !asked.start_at)
    throw Error(fmt::format("{} is the longest time of the run of {}; give {} as well", named("settle"),
                            named("start_at"), named("start_at")));
  options.settle = asked.settle.value_or(0.0);
  const int H = *resolved.harmonics;
  const int samples = resolved.samples.value_or(8 * H);
  if (samples < 2 * H + 1)
    throw Error(fmt::format("{} ({}) must be at least 2·{} + 1 = {}: fewer samples alias the harmonics",
                            named("samples"), samples, named("harmonics"), 2 * H + 1));
  options.fourier = {.harmonics = H, .samples = samples};
  options.modes = *resolved.modes;
  options.points = *resolved.points;
  options.probes = probes_of(model, resolved, named);
  if (*resolved.gravity) options.gravity = static_options(spec, model).gravity;
  options.static_loads = *resolved.static_loads;
  return options;
}

OrbitsOptions orbits_options(const ModelFile& file, const OrbitsSpec& request) {
  return analysis_options<OrbitsAnalysis>(file, request, file_key_name<OrbitsAnalysis>());
}

// ---- the run ------------------------------------------------------------------------

namespace {

// The rows of the condensed coordinates that give v and w of each probe.
Matrix probe_rows(const CondensedRotor& rotor, const std::vector<Index>& probes) {
  const Matrix full = rotor.assembler().dof_map().transformation() * rotor.basis();
  Matrix P(2 * static_cast<Index>(probes.size()), rotor.size());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    P.row(2 * static_cast<Index>(i)) = full.row(global_dof(probes[i], Dof::v));
    P.row(2 * static_cast<Index>(i) + 1) = full.row(global_dof(probes[i], Dof::w));
  }
  return P;
}

// The orbit of each probe for a state of a branch computed on @p fourier.
std::vector<ProbeOrbit> probe_orbits(const Matrix& P, const SteadyState& s, const FourierBasis& fourier) {
  const Index n = P.cols(), np = P.rows();
  const bool moving = s.frequency > 0 && fourier.harmonics > 0;
  const FourierBasis f = moving ? fourier : FourierBasis{.harmonics = 0, .samples = 1};
  const Index terms = s.X.size() / n;
  Vector Xp(np * terms);
  for (Index j = 0; j < terms; ++j) Xp.segment(j * np, np) = P * s.X.segment(j * n, n);
  std::vector<ProbeOrbit> out(static_cast<std::size_t>(np / 2));
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].mean_v = Xp(2 * static_cast<Index>(i));
    out[i].mean_w = Xp(2 * static_cast<Index>(i) + 1);
    out[i].v.resize(terms);
    out[i].w.resize(terms);
    for (Index j = 0; j < terms; ++j) {
      out[i].v(j) = Xp(j * np + 2 * static_cast<Index>(i));
      out[i].w(j) = Xp(j * np + 2 * static_cast<Index>(i) + 1);
    }
  }
  const Index samples = moving ? std::max<Index>(4 * f.samples, 64) : 1;
  Vector x, v;
  for (Index k = 0; k < samples; ++k) {
    motion_at(f, 1.0, Xp, 2.0 * pi * static_cast<Real>(k) / static_cast<Real>(samples), x, v);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Real y = x(2 * static_cast<Index>(i)), z = x(2 * static_cast<Index>(i) + 1);
      out[i].amplitude = std::max(out[i].amplitude, std::hypot(y - out[i].mean_v, z - out[i].mean_w));
      out[i].largest = std::max(out[i].largest, std::hypot(y, z));
    }
  }
  return out;
}

OrbitsBranch with_probes(std::string name, OrbitBranch branch, const Matrix& P) {
  OrbitsBranch out{.name = std::move(name), .branch = std::move(branch), .probes = {}, .bifurcation = {}};
  for (const SteadyState& s : out.branch.orbits) out.probes.push_back(probe_orbits(P, s, out.branch.fourier));
  for (const Bifurcation& b : out.branch.bifurcations)
    out.bifurcation.push_back(probe_orbits(P, b.at, out.branch.fourier));
  return out;
}

// Runs the branches one after the other, each kept as it ends; a branch that cannot
// start ends the run with its reason, the branches so far kept.
class BranchRunner {
 public:
  BranchRunner(const OrbitsOptions& options, const RunContext& context, const RotorFamily& family, OrbitsResult& result)
      : options_(options),
        context_(context),
        family_(family),
        result_(result),
        P_(probe_rows(family.base(), options.probes)) {
    settings_.fourier = options.fourier;
    settings_.continuation.p_min = options.from;
    settings_.continuation.p_max = options.to;
    settings_.continuation.max_points = options.points;
    // At most a fiftieth of the range per step (with fewer than 100 points, two over
    // their number), so that the branch is drawn and its stability changes bracketed
    // finely enough to locate.
    settings_.continuation.max_parameter_step = std::max(0.02, 2.0 / static_cast<Real>(options.points));
    settings_.monitor = [this](const SteadyState& s) { return watch(s); };
  }

  // The branch @p make computes, named @p name; false when the run must end.
  template <class F>
  bool run(std::string name, F&& make) {
    if (!result_.info.converged()) return false;
    current_ = name;
    try {
      OrbitBranch b = make(settings_);
      const bool stopped = b.ended_by == "stopped";
      result_.branches.push_back(with_probes(std::move(name), std::move(b), P_));
      if (stopped) result_.info.fail(SolverStatus::interrupted, fmt::format("stopped on the {} branch", current_));
      return !stopped;
    } catch (const Error& e) {
      result_.info.fail(SolverStatus::not_converged, e.what());
      return false;
    }
  }
  const OrbitSettings& settings() const { return settings_; }

  // The branch through the orbit a run at parameter @p at settles on (within @p settle
  // seconds; 0: the default), up and down as the options say.
  void run_from(Real at, Real settle) {
    current_ = "run";
    SettleSettings how{.duration = settle,
                       .steps = std::max<Index>(64, options_.fourier.samples),
                       .watch = [this, at](Real t, Real end) {
                         if (context_.stop.requested()) return false;
                         if (context_.progress)
                           context_.progress(std::clamp(t / end, 0.0, 1.0),
                                             fmt::format("run at {} = {:.5g}, t = {:.4g} s", family_.name(), at, t));
                         return true;
                       }};
    try {
      result_.settled = settle_orbit(family_, at, settings_, how);
    } catch (const Error& e) {
      if (context_.stop.requested())
        result_.info.fail(SolverStatus::interrupted, "stopped during the run that finds the first orbit");
      else
        result_.info.fail(SolverStatus::not_converged, e.what());
      return;
    }
    const SettledOrbit& s = *result_.settled;
    if (options_.down)
      run("from run (down)", [&](const OrbitSettings& o) { return branch_through(family_, s.start, s.kind, o, true); });
    if (options_.up)
      run("from run (up)", [&](const OrbitSettings& o) { return branch_through(family_, s.start, s.kind, o, false); });
  }

 private:
  bool watch(const SteadyState& s) {
    if (context_.stop.requested()) return false;
    if (context_.progress) {
      const Real span = options_.to - options_.from;
      const Real done = span > 0 ? std::clamp((s.parameter - options_.from) / span, 0.0, 1.0) : 0.0;
      context_.progress(done, fmt::format("{} branch, {} = {:.5g}, {}", current_, family_.name(), s.parameter,
                                          s.stable ? "stable" : "unstable"));
    }
    return true;
  }

  const OrbitsOptions& options_;
  const RunContext& context_;
  const RotorFamily& family_;
  OrbitsResult& result_;
  Matrix P_;
  OrbitSettings settings_;
  std::string current_;
};

}  // namespace

OrbitsResult OrbitsAnalysis::run(const Model& model, const OrbitsOptions& options, const RunContext& context) {
  OrbitsResult result;
  result.info.method = SolverMethod::harmonic_balance;
  const bool parameter = options.build != nullptr;
  const Real middle = parameter ? options.speed : 0.5 * (options.from + options.to);
  const auto condense = [&](bool unbalance) {
    return std::make_unique<CondensedRotor>(model, context.assembler,
                                            CondensationOptions{.modes = options.modes,
                                                                .gravity = options.gravity,
                                                                .static_loads = options.static_loads,
                                                                .unbalance = unbalance,
                                                                .reference_speed = middle});
  };
  std::unique_ptr<CondensedRotor> rotor = condense(options.branch != "whirl" && options.branch != "equilibrium");
  result.branch = options.branch == "auto" ? (rotor->forced() ? "forced" : "whirl") : options.branch;
  if (result.branch == "forced" && !rotor->forced())
    throw Error(
        "orbits: branch \"forced\" needs a load at the rotor speed, and the model has no unbalance or synchronous "
        "harmonic force; its steady states are the equilibrium and the whirl (branch \"whirl\")");
  if (result.branch != "forced" && rotor->forced()) rotor = condense(false);
  result.dofs = rotor->assembler().dof_map().n_reduced();
  result.coordinates = rotor->size();
  // The parameter's first model is the base of the family (the file's own model when
  // the parameter's value is the file's).
  std::unique_ptr<Model> first;
  std::unique_ptr<CondensedRotor> base;
  if (parameter) {
    first = std::make_unique<Model>(options.build(options.from));
    base = std::make_unique<CondensedRotor>(*first, nullptr, *rotor);
  }
  const RotorFamily family =
      parameter ? RotorFamily(*base, options.speed, options.build, options.parameter) : RotorFamily(*rotor);
  BranchRunner runner(options, context, family, result);
  if (options.start_at) {
    runner.run_from(*options.start_at, options.settle);
    return result;
  }
  if (result.branch == "forced") {
    if (options.up) runner.run("forced (up)", [&](const OrbitSettings& s) { return forced_branch(family, s, false); });
    if (options.down)
      runner.run("forced (down)", [&](const OrbitSettings& s) { return forced_branch(family, s, true); });
    return result;
  }
  if (!runner.run("equilibrium", [&](const OrbitSettings& s) { return equilibrium_branch(family, s); })) return result;
  if (result.branch == "equilibrium" || !family.base().nonlinear()) return result;
  const std::vector<Bifurcation> hopfs = result.branches.front().branch.bifurcations;
  int k = 0;
  for (const Bifurcation& h : hopfs) {
    if (h.kind != Bifurcation::Kind::hopf) continue;
    if (!runner.run(fmt::format("whirl {}", ++k), [&](const OrbitSettings& s) { return hopf_branch(family, h, s); }))
      break;
  }
  return result;
}

namespace {

// The branch parameter's value as messages give it: a speed in rpm, else with its unit.
std::string parameter_text(const OrbitsOptions& o, Real p) {
  if (!o.build) return rpm(p);
  return o.parameter_quantity ? format_quantity(p, *o.parameter_quantity, o.parameter_unit) : fmt::format("{:g}", p);
}

// A stretch of a branch where its stability changes back and forth within a hundredth
// of the range: a multiplier that hovers at the unit circle within the method's
// accuracy (a branch turning vertical, a mode whose damping vanishes). Each change is
// located and reported; this says what they are worth. Empty when there is none.
std::string flickering(const OrbitsBranch& b, const OrbitsOptions& options) {
  const std::vector<SteadyState>& s = b.branch.orbits;
  const Real near = 0.01 * std::abs(options.to - options.from);
  std::vector<Real> changes;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k].stable != s[k - 1].stable) changes.push_back(s[k].parameter);
  for (std::size_t i = 0; i + 2 < changes.size(); ++i) {
    std::size_t j = i;
    while (j + 1 < changes.size() && std::abs(changes[j + 1] - changes[j]) < near) ++j;
    if (j >= i + 2)
      return fmt::format(
          "orbits: on the {} branch the stability changes {} times between {} = {} and {}: a multiplier "
          "stays at the unit circle there within the method's accuracy, so those states are neither surely stable "
          "nor surely unstable (more harmonics may settle it)",
          b.name, j - i + 1, options.build ? options.parameter : "speed",
          parameter_text(options, std::min(changes[i], changes[j])),
          parameter_text(options, std::max(changes[i], changes[j])));
    i = j;
  }
  return {};
}

}  // namespace

std::vector<std::string> OrbitsAnalysis::warnings(const Model& model, const OrbitsOptions& options,
                                                  const OrbitsResult& result) {
  std::vector<std::string> out = options.build ? range_warnings(model, options.speed, options.speed)
                                               : range_warnings(model, options.from, options.to);
  if (result.branch != "forced" && model.count_forces([](const Force& f) { return f.has_harmonic(); }) > 0)
    out.push_back(fmt::format(
        "orbits: the model's unbalances and synchronous forces are left out of the {} branches (branch \"forced\" "
        "follows the orbits they drive; a whirl together with them is quasi-periodic, which is not computed)",
        result.branch));
  if (result.branch == "whirl") {
    bool nonlinear = false;
    for (const Force& f : model.forces) nonlinear = nonlinear || f.is_nonlinear();
    if (!nonlinear)
      out.emplace_back(
          "orbits: the rotor has no nonlinear force, so no orbit of finite size leaves its Hopf points (the linear "
          "rotor's whirl grows without bound past them): only the equilibrium branch is computed");
  }
  constexpr Real truncation_limit = 1e-3;
  for (const OrbitsBranch& b : result.branches) {
    if (const std::string w = flickering(b, options); !w.empty()) out.push_back(w);
    Real worst = 0;
    for (const SteadyState& s : b.branch.orbits) worst = std::max(worst, s.truncation);
    if (worst > truncation_limit)
      out.push_back(
          fmt::format("orbits: on the {} branch the harmonics left out are estimated at up to {:.2g} of "
                      "the motion (above {:g}): give more harmonics",
                      b.name, worst, truncation_limit));
    if (!b.branch.clipped && b.branch.ended_by != "points" && b.branch.ended_by != "stopped")
      out.push_back(fmt::format("orbits: the {} branch ended before the range's end: {}", b.name, b.branch.ended_by));
    if (b.branch.ended_by == "points")
      out.push_back(fmt::format("orbits: the {} branch ended after {} points before the range's end (more points)",
                                b.name, b.branch.orbits.size()));
  }
  return out;
}

// ---- study quantities ----------------------------------------------------------------

namespace {

// The speed at which a run-down leaves the whirl (the lowest speed of a stable
// self-excited orbit), or a run-up's forced orbit jumps down (the first fold met going
// up at which the stable orbits end).
Real jump_down_speed(DesignAnalyses& a, const QuantitySpec&, std::string& clipped) {
  const OrbitsResult& r = a.result<OrbitsAnalysis>();
  const OrbitsOptions& o = a.options<OrbitsAnalysis>();
  if (o.build) throw Error("jump_down_speed is a speed: the [orbits] branch must be over speed, not a parameter");
  Real lowest = std::numeric_limits<Real>::infinity();
  for (const OrbitsBranch& b : r.branches) {
    if (b.branch.kind == OrbitBranch::Kind::self_excited) {
      for (const SteadyState& s : b.branch.orbits)
        if (s.stable) lowest = std::min(lowest, s.parameter);
      // A fold where the stable orbits turn back (a subcritical whirl's) is their end.
      for (const Bifurcation& f : b.branch.bifurcations)
        if (f.kind == Bifurcation::Kind::fold && f.after + 1 < b.branch.orbits.size() &&
            (b.branch.orbits[f.after].stable || b.branch.orbits[f.after + 1].stable))
          lowest = std::min(lowest, f.at.parameter);
    } else if (b.branch.kind == OrbitBranch::Kind::forced && b.name.ends_with("(up)")) {
      for (const Bifurcation& f : b.branch.bifurcations)
        if (f.kind == Bifurcation::Kind::fold && f.after < b.branch.orbits.size() && b.branch.orbits[f.after].stable) {
          lowest = std::min(lowest, f.at.parameter);
          break;
        }
    }
  }
  if (!std::isfinite(lowest))
    throw Error(r.branch == "forced"
                    ? "the forced branch going up has no fold after stable orbits: no jump in the range"
                    : "no stable self-excited orbit in the range: no whirl to jump down from");
  if (lowest <= o.from * (1 + 1e-9))
    clipped = fmt::format("the stable whirl reaches the range's lowest speed, {}", parameter_text(o, o.from));
  return lowest;
}

// The largest orbit (distance from the centre) among the stable steady states.
Real largest_stable_orbit(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const OrbitsResult& r = a.result<OrbitsAnalysis>();
  const std::vector<Index>& probes = a.options<OrbitsAnalysis>().probes;
  if (probes.empty()) throw Error("the orbits analysis reports no probe: give the quantity a 'probe'");
  const Index node = q.probe ? node_index(a.model(), *q.probe) : probes.front();
  const auto at = static_cast<std::size_t>(std::find(probes.begin(), probes.end(), node) - probes.begin());
  Real largest = -1;
  for (const OrbitsBranch& b : r.branches)
    for (std::size_t k = 0; k < b.branch.orbits.size(); ++k)
      if (b.branch.orbits[k].stable) largest = std::max(largest, b.probes[k][at].amplitude);
  if (largest < 0) throw Error("no steady state in the range is stable");
  return largest;
}

}  // namespace

const std::vector<QuantityRow>& OrbitsAnalysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "jump_down_speed",
       .doc = "the speed below which no stable whirl orbit exists (where a run-down drops out of the whirl), or, "
              "for a forced branch, the fold at which a run-up's stable orbit ends",
       .analysis = name,
       .unit = Quantity::speed,
       .evaluate = jump_down_speed},
      {.name = "largest_stable_orbit",
       .doc = "the largest orbit (distance from its centre) at a probe among the stable steady states of every "
              "branch",
       .analysis = name,
       .unit = Quantity::length,
       .evaluate = largest_stable_orbit},
  };
  return rows;
}

OrbitsSpec OrbitsAnalysis::study_request(const Model& model, std::span<const QuantitySpec> quantities) {
  OrbitsSpec request;
  request.probes = quantity_probes(model, quantities, name);
  return request;
}

}  // namespace feran

#include <feran/analyses/settings.hpp>

#include <algorithm>

#include <fmt/format.h>

#include <feran/analyses/transient/integrator.hpp>
#include <feran/core/error.hpp>
#include <feran/core/suggestions.hpp>

namespace feran {

namespace {

std::vector<Real> linspace(Real a, Real b, int n) {
  if (n == 1) return {a};
  std::vector<Real> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
  return out;
}

void add_once(std::vector<Index>& nodes, Index node) {
  if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
}

std::vector<Index> node_indices(const Model& model, const std::vector<NodeRef>& refs) {
  std::vector<Index> out;
  for (const NodeRef& ref : refs) out.push_back(node_index(model, ref));
  return out;
}

Real positive_time(Real t, const char* what) {
  if (!(t > 0.0)) throw Error(fmt::format("runup: {} must be positive, got {} s", what, t));
  return t;
}

}  // namespace

std::vector<Index> default_probes(const Model& model, std::span<const HarmonicForce> extra) {
  std::vector<Index> probes;
  for (const Force& f : model.forces)
    if (f.kind() == "unbalance")
      for (const Index node : f.nodes()) add_once(probes, node);
  for (const HarmonicForce& f : extra) add_once(probes, f.node);
  return probes;
}

Index node_index(const Model& model, const NodeRef& ref) {
  const Index found = std::holds_alternative<std::int64_t>(ref)
                          ? model.find_node(static_cast<int>(std::get<std::int64_t>(ref)))
                          : model.find_node(std::get<std::string>(ref));
  if (found < 0)
    throw Error(std::holds_alternative<std::int64_t>(ref)
                    ? fmt::format("node {} does not exist", std::get<std::int64_t>(ref))
                    : fmt::format("node '{}' does not exist", std::get<std::string>(ref)));
  return found;
}

void check_analysis_tables(const ModelSpec& spec) {
  if (!spec.runup.integrator) return;
  const std::string& name = *spec.runup.integrator;
  const std::vector<std::string> names = integrator_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string message =
      fmt::format("'integrator' must be {}, got \"{}\"", detail::join_list(names, "or", '"'), name);
  if (const auto m = detail::closest_match(name, names, 2))
    message += fmt::format("; did you mean \"{}\"?", *m);
  throw SpecError("runup.integrator", message);
}

std::vector<std::string> range_warnings(const Model& model, Real low, Real high) {
  std::vector<std::string> out;
  // Round-off of the sweep's own arithmetic is not "beyond" (1e-9 relative).
  const auto beyond = [](Real x, Real edge, bool above) {
    const Real margin = 1e-9 * std::max(std::abs(x), std::abs(edge));
    return above ? x > edge + margin : x < edge - margin;
  };
  for (const Element& e : model.elements)
    for (const SpeedRange& r : e.speed_ranges()) {
      const bool over = beyond(high, r.high, true), under = beyond(low, r.low, false);
      if (!over && !under) continue;
      out.push_back(fmt::format(
          "'{}': {} is tabulated from {:.6g} to {:.6g} Hz; the analysis reaches {:.6g} Hz, where "
          "its {} value is held",
          e.label(), r.what, rad_to_hz(r.low), rad_to_hz(r.high), rad_to_hz(over ? high : low),
          over ? "last" : "first"));
    }
  return out;
}

std::pair<Real, Real> speed_span(const TransientOptions& options) {
  Real low = options.profile.speed(0.0), high = low;
  for (const auto& [t, w] : options.profile.points())
    if (t <= options.duration) low = std::min(low, w), high = std::max(high, w);
  low = std::min(low, options.profile.speed(options.duration));
  high = std::max(high, options.profile.speed(options.duration));
  return {low, high};
}

Index spring_element(const Model& model, const std::string& name) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (model.elements[e].kind() == "spring_damper" && model.elements[e].label() == name)
      return static_cast<Index>(e);
  throw Error(fmt::format("no spring-damper is named '{}'", name));
}

ModalSettings modal_settings(const ModalSpec& file, const ModalRequest& request) {
  ModalSettings s;
  s.speed = request.speed.value_or(file.speed.value_or(0.0));
  s.options.solver = request.solver;
  s.options.n_modes = request.modes.value_or(file.modes.value_or(0));
  s.options.shapes = request.shapes;
  return s;
}

CampbellOptions campbell_settings(const CampbellSpec& file, const CampbellRequest& request) {
  const Real start = request.start.value_or(file.start.value_or(0.0));
  const std::optional<Real> stop = request.stop ? request.stop : file.stop;
  if (!stop)
    throw Error("campbell: give the last speed with --stop (e.g. --stop 80Hz) or in the model's "
                "[campbell] table");
  if (!(*stop > start)) throw Error("campbell: the last speed must be above the first");
  const int points = request.points.value_or(file.points.value_or(defaults::campbell_points));
  if (points < 2) throw Error("campbell: at least 2 speeds are needed");
  CampbellOptions options;
  options.speeds = linspace(start, *stop, points);
  options.n_modes = request.modes.value_or(file.modes.value_or(defaults::campbell_modes));
  options.orders = !request.orders.empty() ? request.orders
                   : !file.orders.empty()  ? file.orders
                                           : std::vector<int>{1};
  options.modal.solver = request.solver;
  options.n_threads = request.n_threads;
  return options;
}

StationOutput station_output(std::string_view name) {
  for (StationOutput o : {StationOutput::all, StationOutput::summary, StationOutput::none})
    if (name == to_string(o)) return o;
  throw Error(fmt::format("stations must be all, summary or none, got '{}'", name));
}

HarmonicOptions response_settings(const Model& model, const ResponseSpec& file,
                                  const ResponseRequest& request) {
  HarmonicOptions options;
  options.unbalance = request.unbalance;
  options.n_threads = request.n_threads;
  options.loss_factor = request.loss_factor.value_or(file.loss_factor.value_or(0.0));
  options.stations = request.stations ? *request.stations
                     : file.stations  ? station_output(*file.stations)
                                      : StationOutput::summary;
  options.extra_forces = request.extra_forces;
  // Forces that excite at the swept frequency (all harmonic ones but unbalances).
  const bool any_force =
      std::any_of(model.forces.begin(), model.forces.end(),
                  [](const Force& f) { return f.has_harmonic() && f.kind() != "unbalance"; }) ||
      !options.extra_forces.empty();

  if (request.freq_start || request.freq_stop) {
    if (!request.freq_start || !request.freq_stop)
      throw Error("response: a frequency sweep needs both --freq-start and --freq-stop");
    if (!(*request.freq_stop > *request.freq_start))
      throw Error("response: --freq-stop must be above --freq-start");
    options.frequencies = linspace(*request.freq_start, *request.freq_stop,
                                   request.freq_points.value_or(defaults::frequency_points));
    options.speed = request.speed.value_or(0.0);
    if (!any_force)
      throw Error("response: a frequency sweep needs a harmonic force: add --force "
                  "NODE:DIRECTION:AMPLITUDE or [[forces]] in the model");
  } else if (request.speed && !request.start && !request.stop) {
    options.speeds = {*request.speed};  // the response at one speed
  } else {
    const Real start = request.start.value_or(file.start.value_or(0.0));
    const int points = request.points.value_or(file.points.value_or(defaults::response_points));
    const std::optional<Real> stop = request.stop ? request.stop : file.stop;
    if (points == 1) {
      options.speeds = {start};
    } else {
      if (!stop)
        throw Error("response: give the last speed with --stop (e.g. --stop 80Hz) or in the "
                    "model's [response] table (or one point: --points 1 or --speed)");
      if (!(*stop > start)) throw Error("response: the last speed must be above the first");
      options.speeds = linspace(start, *stop, points);
    }
  }
  if (options.frequencies.empty() && (model.n_forces("unbalance") == 0 || !options.unbalance) &&
      !any_force)
    throw Error("response: nothing excites the rotor: the model has no [[unbalances]] or "
                "[[forces]] and no --force was given");

  options.probes = !request.probes.empty() ? request.probes
                   : !file.probes.empty()  ? node_indices(model, file.probes)
                                           : default_probes(model, options.extra_forces);
  return options;
}

StaticOptions static_settings(const StaticSpec& file, const StaticRequest& request) {
  StaticOptions options;
  const std::string direction = request.gravity.value_or(file.gravity.value_or("-y"));
  // A magnitude asked for applies to the file's direction too; the file's own 'g'
  // only to its own direction.
  const Real g = request.g ? *request.g
                 : (!request.gravity && file.gravity) ? file.g.value_or(defaults::gravity)
                                                      : defaults::gravity;
  if (!(g > 0.0)) throw Error("--g must be positive");
  if (direction != "none") {
    const bool signed_direction = direction.size() == 2 && (direction[0] == '+' || direction[0] == '-');
    const char axis = direction.back();
    if ((direction.size() != 1 && !signed_direction) || axis < 'x' || axis > 'z')
      throw Error(fmt::format("static: gravity must be +x, -x, +y, -y, +z, -z or none, got '{}'",
                              direction));
    options.gravity(axis - 'x') = direction.front() == '-' ? -g : g;
  }
  options.speed = request.speed.value_or(file.speed.value_or(0.0));
  options.loads = request.loads;
  return options;
}

TransientOptions runup_settings(const Model& model, const RunupSpec& file,
                                const RunupRequest& request) {
  TransientOptions options;
  const bool ramp = request.from || request.to || request.ramp_time;
  const int forms = static_cast<int>(request.speed.has_value()) + static_cast<int>(ramp) +
                    static_cast<int>(!request.table.empty());
  if (forms > 1)
    throw Error("runup: give one speed profile: --speed, --from/--to/--ramp-time, or --table");
  std::optional<Real> natural_duration;
  if (request.speed) {
    options.profile = SpeedProfile::constant(*request.speed);
  } else if (ramp) {
    if (!request.to || !request.ramp_time) throw Error("runup: a ramp needs --to and --ramp-time");
    const Real time = positive_time(*request.ramp_time, "the ramp time");
    options.profile = SpeedProfile::ramp(request.from.value_or(0.0), *request.to, time);
    natural_duration = time;
  } else if (!request.table.empty()) {
    options.profile = SpeedProfile(request.table);
    natural_duration = request.table.back().first;
  } else if (file.speed) {
    options.profile = SpeedProfile::constant(*file.speed);
  } else if (file.to) {
    options.profile = SpeedProfile::ramp(file.from.value_or(0.0), *file.to, *file.ramp_time);
    natural_duration = *file.ramp_time;
  } else if (!file.table.empty()) {
    options.profile = SpeedProfile(file.table);
    natural_duration = file.table.back().first;
  } else {
    throw Error("runup: give a speed profile (--speed, --from/--to/--ramp-time or --table) or a "
                "[runup] table");
  }
  if (request.duration)
    options.duration = positive_time(*request.duration, "the duration");
  else if (forms == 0 && file.duration)
    options.duration = *file.duration;
  else if (natural_duration && *natural_duration > 0)
    options.duration = *natural_duration;
  else
    throw Error("runup: give the simulated time with --duration (e.g. --duration 2s)");

  options.integrator = request.integrator.value_or(file.integrator.value_or("trapezoidal"));
  IntegratorSettings& s = options.settings;
  s.dt = positive_time(request.dt.value_or(file.dt.value_or(defaults::runup_dt)), "the time step");
  if (const auto v = request.rel_tol ? request.rel_tol : file.rel_tol) s.rel_tol = *v;
  if (const auto v = request.abs_tol ? request.abs_tol : file.abs_tol) s.abs_tol = *v;
  if (request.newton_tol) s.newton_tol = *request.newton_tol;
  if (request.newton_max_iterations) s.newton_max_iterations = *request.newton_max_iterations;
  s.allow_unstable_step = request.allow_unstable_step;
  s.exact_jacobian = request.exact_jacobian;
  if (request.jacobian_interval) s.jacobian_interval = *request.jacobian_interval;
  options.reduced_modes = request.modes.value_or(file.modes.value_or(0));
  options.output_interval = positive_time(
      request.output_interval.value_or(file.output_interval.value_or(defaults::output_interval)),
      "the output interval");
  const Real samples = options.duration / options.output_interval;
  if (samples > defaults::max_runup_samples)
    throw Error(fmt::format("runup: a duration of {:g} s sampled every {:g} s is {:.3g} samples; at most {:g} are "
                            "recorded (a longer output interval or a shorter duration)",
                            options.duration, options.output_interval, samples, defaults::max_runup_samples));
  const Real steps = options.duration / s.dt;
  const auto known = integrator_names();
  if (std::find(known.begin(), known.end(), options.integrator) != known.end() && steps > defaults::max_runup_steps &&
      !make_integrator(options.integrator, s)->adaptive())
    throw Error(fmt::format("runup: a duration of {:g} s at a step of {:g} s is {:.3g} steps; at most {:g} are "
                            "taken (a longer step or a shorter duration)",
                            options.duration, s.dt, steps, defaults::max_runup_steps));
  if (request.blowup_limit) {
    if (!(*request.blowup_limit > 0)) throw Error("--blowup must be positive");
    options.blowup_limit = *request.blowup_limit;
  }
  options.static_loads = request.static_loads;
  options.probes = !request.probes.empty() ? request.probes
                   : !file.probes.empty()  ? node_indices(model, file.probes)
                                           : default_probes(model);
  if (!request.springs.empty()) {
    options.springs = request.springs;
  } else {
    for (const std::string& name : file.springs) options.springs.push_back(spring_element(model, name));
  }
  return options;
}

}  // namespace feran

// The steady-state response's room: its options ([response]), their defaults and checks
// (analyses/response/analysis.hpp). Its writers are in writers.cpp, its study
// quantities in quantities.cpp.
#include <feran/analyses/response/analysis.hpp>

#include <algorithm>

#include <fmt/format.h>

#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/io/option_text.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/request.hpp>

namespace feran {

namespace spec {

namespace {
constexpr std::string_view station_outputs[] = {"all", "summary", "none"};
constexpr std::string_view speed_sweep = "speed sweep", fixed_speed = "fixed speed";
}  // namespace

template <>
const FieldTable<ResponseSpec>& fields_of<ResponseSpec>() {
  using S = ResponseSpec;
  using K = FieldKind;
  const Bound non_negative{Bound::Kind::non_negative};
  const Bound count{Bound::Kind::at_least, 1, max_sweep_points};
  static const FieldTable<S> table = {
      {.key = "start",
       .kind = K::quantity,
       .member = &S::start,
       .doc = "first rotor speed of a speed sweep",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .alternative = speed_sweep},
      {.key = "stop",
       .kind = K::quantity,
       .member = &S::stop,
       .doc = "last rotor speed of a speed sweep; > `start`",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .default_text = "required unless `points` is 1",
       .alternative = speed_sweep},
      {.key = "points",
       .kind = K::integer,
       .member = &S::points,
       .doc = "number of speeds of a speed sweep; 1: the response at `start` alone",
       .bound = count,
       .short_name = "p",
       .alternative = speed_sweep},
      {.key = "speed",
       .kind = K::quantity,
       .member = &S::speed,
       .doc = "rotor speed of a frequency sweep; alone (no `start`, `stop` or `points`), the response at that one "
              "speed",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .short_name = "s",
       .alternative = fixed_speed},
      {.key = "freq_start",
       .kind = K::quantity,
       .member = &S::freq_start,
       .doc = "first excitation frequency of a frequency sweep (with `freq_stop`), the rotor held at `speed`",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .alternative = fixed_speed},
      {.key = "freq_stop",
       .kind = K::quantity,
       .member = &S::freq_stop,
       .doc = "last excitation frequency of a frequency sweep; > `freq_start`",
       .quantity = Quantity::speed,
       .bound = non_negative,
       .unit = "Hz",
       .alternative = fixed_speed},
      {.key = "freq_points",
       .kind = K::integer,
       .member = &S::freq_points,
       .doc = "number of frequencies of a frequency sweep",
       .bound = count,
       .alternative = fixed_speed},
      {.key = "probes",
       .kind = K::node_list,
       .member = &S::probes,
       .doc = "non-empty, no node twice: the nodes whose response is reported (one per option on the command line)",
       .default_text = "every node carrying an unbalance or a force",
       .if_empty = "leave it out for the analysis's default",
       .option = "probe"},
      {.key = "forces",
       .kind = K::text_list,
       .member = &S::forces,
       .doc = "harmonic forces added for the analysis, each `\"NODE:DIRECTION:AMPLITUDE[:PHASE]\"` with DIRECTION x, "
              "y, z, rx, ry, rz (fixed in space), rotating or rotating_moment (turning with the shaft), e.g. "
              "`\"rotor:y:10N:90deg\"`",
       .default_text = "none",
       .if_empty = "leave it out to add no force",
       .option = "force"},
      {.key = "loss_factor",
       .kind = K::number,
       .member = &S::loss_factor,
       .doc =
           "global hysteretic loss factor η: adds j·η·K_e for every element, on top of the elements' own loss factors",
       .bound = non_negative},
      {.key = "stations",
       .kind = K::choice,
       .member = &S::stations,
       .doc = "what is kept of the section forces and stresses at both ends of every shaft element: `\"all\"` (every "
              "station at every point), `\"summary\"` (per point the largest values and their place) or `\"none\"`",
       .choices = station_outputs},
      {.key = "unbalance",
       .kind = K::flag,
       .member = &S::unbalance,
       .doc = "whether the model's [[unbalances]] act (a speed sweep's; a frequency sweep excites with the forces "
              "only)"},
      {.key = "stability",
       .kind = K::flag,
       .member = &S::stability,
       .doc = "whether to judge the rotor's stability at each point: where it is unstable the response is no steady "
              "state the rotor reaches"},
  };
  return table;
}

}  // namespace spec

const ResponseSpec& ResponseAnalysis::defaults() {
  static const ResponseSpec d = [] {
    ResponseSpec s;
    s.start = 0.0;
    s.points = defaults::response_points;
    s.speed = 0.0;
    s.freq_points = defaults::frequency_points;
    s.loss_factor = 0.0;
    s.stations = "summary";
    s.unbalance = true;
    s.stability = true;
    return s;
  }();
  return d;
}

namespace {

StationOutput station_output_named(const std::string& name) {
  for (StationOutput o : {StationOutput::all, StationOutput::summary, StationOutput::none})
    if (name == to_string(o)) return o;
  throw std::logic_error("unknown station output " + name);  // the field's choices were checked
}

// The points of the sweep asked for: its speeds, or its frequencies and speed.
void set_points(HarmonicOptions& options, const ResponseSpec& asked, const ResponseSpec& resolved,
                const OptionName& named) {
  const bool speed_sweep = asked.start || asked.stop || asked.points;
  const bool frequency_sweep = asked.freq_start || asked.freq_stop || asked.freq_points;
  if (speed_sweep && (frequency_sweep || asked.speed))
    throw Error(fmt::format(
        "response: {}, {} and {} make a speed sweep; {} and the frequency sweep's {}, {} and {} hold the rotor at "
        "one speed: give one or the other",
        named("start"), named("stop"), named("points"), named("speed"), named("freq_start"), named("freq_stop"),
        named("freq_points")));
  if (frequency_sweep) {
    if (!asked.freq_start || !asked.freq_stop)
      throw Error(
          fmt::format("response: a frequency sweep needs both {} and {}", named("freq_start"), named("freq_stop")));
    if (!(*asked.freq_stop > *asked.freq_start))
      throw Error(fmt::format("response: {} must be above {}", named("freq_stop"), named("freq_start")));
    options.frequencies = evenly_spaced(*asked.freq_start, *asked.freq_stop, *resolved.freq_points);
    options.speed = *resolved.speed;
  } else if (asked.speed) {
    options.speeds = {*asked.speed};  // the response at one speed
  } else if (*resolved.points == 1) {
    options.speeds = {*resolved.start};
  } else {
    if (!resolved.stop)
      throw Error(fmt::format(
          "response: give the last speed with {} (e.g. 80Hz) or in the model's [response] table (or one point: {} 1 "
          "or {})",
          named("stop"), named("points"), named("speed")));
    if (!(*resolved.stop > *resolved.start))
      throw Error(
          fmt::format("response: the last speed ({}) must be above the first ({})", named("stop"), named("start")));
    options.speeds = evenly_spaced(*resolved.start, *resolved.stop, *resolved.points);
  }
}

// The nodes reported: those asked for, each once, else the default probes.
std::vector<Index> probe_nodes(const Model& model, const ResponseSpec& resolved, const HarmonicOptions& options,
                               const OptionName& named) {
  const std::vector<Index> probes = distinct_nodes(model, resolved.probes, named("probes"));
  return probes.empty() ? default_probes(model, options.extra_forces) : probes;
}

}  // namespace

HarmonicOptions ResponseAnalysis::settings(const Model& model, const ResponseSpec& asked, const ResponseSpec& resolved,
                                           const OptionName& named) {
  HarmonicOptions options;
  options.unbalance = *resolved.unbalance;
  options.stability = *resolved.stability;
  options.loss_factor = *resolved.loss_factor;
  options.stations = station_output_named(*resolved.stations);
  for (const std::string& text : resolved.forces)
    options.extra_forces.push_back(parse_force_text(model, text, named("forces")));
  set_points(options, asked, resolved, named);
  // Forces that excite at the swept frequency (all harmonic ones but unbalances).
  const bool any_force =
      std::any_of(model.forces.begin(), model.forces.end(), is_harmonic_force) || !options.extra_forces.empty();
  if (!options.frequencies.empty() && !any_force)
    throw Error(fmt::format(
        "response: a frequency sweep needs a harmonic force: add {} NODE:DIRECTION:AMPLITUDE or [[forces]] in the "
        "model",
        named("forces")));
  if (options.frequencies.empty() && (model.count_forces(is_unbalance) == 0 || !options.unbalance) && !any_force)
    throw Error(fmt::format(
        "response: nothing excites the rotor: the model has no [[unbalances]]{} or [[forces]] and no {} was given",
        model.count_forces(is_unbalance) > 0 ? " that act" : "", named("forces")));
  options.probes = probe_nodes(model, resolved, options, named);
  return options;
}

HarmonicResult ResponseAnalysis::run(const Model& model, const HarmonicOptions& options, const RunContext& context) {
  HarmonicOptions o = options;
  o.n_threads = context.threads;
  o.stop = context.stop;
  return run_harmonic_response(model, o);
}

std::vector<std::string> ResponseAnalysis::warnings(const Model& model, const HarmonicOptions& options,
                                                    const HarmonicResult& result) {
  // The speeds and frequencies solved (those asked for when none was).
  const bool solved = !result.speeds.empty(), by_frequency = !options.frequencies.empty();
  const std::vector<Real> speeds = solved         ? result.speeds
                                   : by_frequency ? std::vector<Real>{options.speed}
                                                  : options.speeds;
  const auto [low, high] = std::minmax_element(speeds.begin(), speeds.end());
  std::optional<std::pair<Real, Real>> span;  // a speed sweep's are synchronous
  if (by_frequency) {
    const std::vector<Real>& frequencies = solved ? result.frequencies : options.frequencies;
    const auto [f_low, f_high] = std::minmax_element(frequencies.begin(), frequencies.end());
    span = std::pair{*f_low, *f_high};
  }
  std::vector<std::string> out = range_warnings(model, *low, *high, span);
  for (std::string& w : clearance_warnings(result, model)) out.push_back(std::move(w));
  return out;
}

HarmonicOptions response_options(const ModelFile& file, const ResponseSpec& request) {
  return analysis_options<ResponseAnalysis>(file, request, file_key_name<ResponseAnalysis>());
}

}  // namespace feran

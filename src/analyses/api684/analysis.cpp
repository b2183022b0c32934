// The API 617 / API 684 analyses' room: their options ([api684]), their defaults and
// checks, and their study quantities (analyses/api684/analysis.hpp). The writers are in
// writers.cpp.
#include <feran/analyses/api684/analysis.hpp>

#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/api684/critical_speed_map.hpp>
#include <feran/analyses/api684/level1_stability.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/request.hpp>
#include <feran/study/design_analyses.hpp>

namespace feran {

namespace spec {

namespace {
constexpr std::string_view unbalance_sources[] = {"4W/N", "model"};
}  // namespace

template <>
const FieldTable<Api684Spec>& fields_of<Api684Spec>() {
  using S = Api684Spec;
  using K = FieldKind;
  static const FieldTable<S> table = {
      {.key = "min_speed",
       .kind = K::quantity,
       .member = &S::min_speed,
       .doc = "minimum operating speed",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::positive},
       .unit = "rpm",
       .default_text = "required by `feran api684`"},
      {.key = "max_speed",
       .kind = K::quantity,
       .member = &S::max_speed,
       .doc = "maximum continuous speed (N of 4W/N, the speed of the stability analysis); ≥ `min_speed`",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::positive},
       .unit = "rpm",
       .default_text = "required by `feran api684`"},
      {.key = "stop",
       .kind = K::quantity,
       .member = &S::stop,
       .doc = "last speed of the unbalance responses (they start at 0)",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::positive},
       .unit = "rpm",
       .default_text = "2 × `max_speed`"},
      {.key = "points",
       .kind = K::integer,
       .member = &S::points,
       .doc = "speeds of the unbalance responses; `modes` × `points` at most 200000 (one response per mode)",
       .bound = {Bound::Kind::at_least, 3, max_sweep_points},
       .short_name = "p"},
      {.key = "modes",
       .kind = K::integer,
       .member = &S::modes,
       .doc = "forward modes excited in turn by the analytical unbalance, the lowest at `max_speed`",
       .bound = {Bound::Kind::at_least, 1},
       .short_name = "n"},
      {.key = "unbalance",
       .kind = K::choice,
       .member = &S::unbalance,
       .doc = "`\"4W/N\"`: the analytical unbalance of API 617 placed for each mode (docs/theory/api684.md); "
              "`\"model\"`: the model's own `[[unbalances]]` in one response",
       .choices = unbalance_sources},
      {.key = "unbalance_multiple",
       .kind = K::number,
       .member = &S::unbalance_multiple,
       .doc = "the analytical unbalance is this many times 4W/N",
       .bound = {Bound::Kind::positive}},
      {.key = "probes",
       .kind = K::node_list,
       .member = &S::probes,
       .doc = "non-empty, no node twice: the nodes whose responses are judged",
       .default_text = "the bearings' nodes and the unbalances' nodes",
       .if_empty = "leave it out for the analysis's default",
       .option = "probe"},
      {.key = "bearings",
       .kind = K::text_list,
       .member = &S::bearings,
       .doc = "non-empty, no spring twice: the bearings (each the `name` of a `[[springs]]` entry)",
       .default_text = "every spring holding a rotating node to the ground or a non-rotating node",
       .if_empty = "leave it out for the analysis's default",
       .option = "bearing"},
      {.key = "map_low",
       .kind = K::quantity,
       .member = &S::map_low,
       .doc = "lowest bearing stiffness of the critical speed map",
       .quantity = Quantity::stiffness,
       .bound = {Bound::Kind::positive},
       .default_text = "the bearings' stiffness at `max_speed` / 100"},
      {.key = "map_high",
       .kind = K::quantity,
       .member = &S::map_high,
       .doc = "highest bearing stiffness of the map; > `map_low`",
       .quantity = Quantity::stiffness,
       .bound = {Bound::Kind::positive},
       .default_text = "the bearings' stiffness at `max_speed` × 100"},
      {.key = "map_points",
       .kind = K::integer,
       .member = &S::map_points,
       .doc = "stiffness values of the map, evenly spaced in log k; `map_points` × `map_criticals` at most 100000",
       .bound = {Bound::Kind::at_least, 2, max_sweep_points}},
      {.key = "map_criticals",
       .kind = K::integer,
       .member = &S::map_criticals,
       .doc = "critical speeds on the map",
       .bound = {Bound::Kind::at_least, 1}},
      {.key = "stability_node",
       .kind = K::node,
       .member = &S::stability_node,
       .doc = "where the cross-coupled stiffness Q of the level I stability analysis acts (a rotating node)",
       .default_text = "the node where the first forward mode at `max_speed` moves most"},
      {.key = "anticipated_q",
       .kind = K::quantity,
       .member = &S::anticipated_q,
       .doc = "the anticipated cross-coupling q_A of the stages (API 617; docs/theory/api684.md), for the level I "
              "screening",
       .quantity = Quantity::stiffness,
       .bound = {Bound::Kind::positive},
       .default_text = "— (no screening)"},
      {.key = "map", .kind = K::flag, .member = &S::map, .doc = "whether to compute the undamped critical speed map"},
      {.key = "stability",
       .kind = K::flag,
       .member = &S::stability,
       .doc = "whether to run the level I stability analysis"},
  };
  return table;
}

}  // namespace spec

const Api684Spec& Api684Analysis::defaults() {
  static const Api684Spec d = [] {
    Api684Spec s;
    s.points = 401;
    s.modes = 2;
    s.unbalance = "4W/N";
    s.unbalance_multiple = 1.0;
    s.map_points = 41;
    s.map_criticals = 4;
    s.map = true;
    s.stability = true;
    return s;
  }();
  return d;
}

namespace {

// The unbalance responses' speeds and cases, bounded in the work they ask for.
void set_responses(Api684Options& o, const Api684Spec& resolved, Real stop, const OptionName& named) {
  const int points = *resolved.points;
  for (int i = 0; i < points; ++i) o.speeds.push_back(stop * i / (points - 1));
  o.modes = *resolved.modes;
  o.model_unbalance = *resolved.unbalance == "model";
  o.unbalance_multiple = *resolved.unbalance_multiple;
  // Each count within its bounds, the work they multiply into bounded too: one
  // unbalance response (each point a solve and a stability decision) per mode.
  constexpr long long max_response_points = 200000;
  const long long cases = o.model_unbalance ? 1 : o.modes;
  if (cases * points > max_response_points)
    throw Error(
        fmt::format("[api684] the unbalance responses would take {} × {} = {} points (modes × points, "
                    "from {} and {}): at most {}; ask for fewer",
                    cases, points, cases * points, named("modes"), named("points"), max_response_points));
}

// The critical speed map: two decades either side of the bearings' mean lateral
// stiffness at the maximum continuous speed (geometric mean over bearings and
// directions), unless asked otherwise.
CriticalSpeedMapOptions map_options(const Model& lin, const Api684Options& o, const Api684Spec& resolved, Real stop,
                                    const OptionName& named) {
  CriticalSpeedMapOptions map;
  map.springs = o.bearings;
  Real log_sum = 0;
  int count = 0;
  for (const Index e : o.bearings) {
    std::optional<Transmission> t;
    try {
      t = lin.elements[static_cast<std::size_t>(e)].transmission(o.high);
    } catch (const Error&) {  // no journal equilibrium there: the analysis itself will say why
    }
    if (t)
      for (const Dof d : {Dof::v, Dof::w})
        if (const Real k = (*t).K(static_cast<Index>(d), static_cast<Index>(d)); k > 0) log_sum += std::log(k), ++count;
  }
  const Real centre = count > 0 ? std::exp(log_sum / count) : 1e7;
  map.k_low = resolved.map_low.value_or(centre / 100);
  map.k_high = resolved.map_high.value_or(centre * 100);
  map.points = *resolved.map_points;
  map.criticals = *resolved.map_criticals;
  constexpr long long max_map_work = 100000;
  if (static_cast<long long>(map.points) * map.criticals > max_map_work)
    throw Error(
        fmt::format("[api684] the critical speed map would take {} × {} = {} critical speeds ({} × {}): at "
                    "most {}; ask for fewer",
                    map.points, map.criticals, static_cast<long long>(map.points) * map.criticals, named("map_points"),
                    named("map_criticals"), max_map_work));
  map.curve_stop = stop;
  return map;
}

}  // namespace

Api684Options Api684Analysis::settings(const Model& model, const ModelSpec& spec, const Api684Spec&,
                                       const Api684Spec& resolved, const OptionName& named) {
  if (!resolved.min_speed || !resolved.max_speed)
    throw Error(
        fmt::format("the API 684 analyses need the operating speed range: give [api684] min_speed and "
                    "max_speed in the model, or {} and {}",
                    named("min_speed"), named("max_speed")));
  if (*resolved.max_speed < *resolved.min_speed)
    throw Error(
        fmt::format("the maximum continuous speed ({:.6g} rpm) is below the minimum operating speed "
                    "({:.6g} rpm)",
                    *resolved.max_speed * 30 / pi, *resolved.min_speed * 30 / pi));
  Api684Options o;
  o.low = *resolved.min_speed;
  o.high = *resolved.max_speed;
  const Real stop = resolved.stop.value_or(2 * o.high);
  set_responses(o, resolved, stop, named);
  o.probes = distinct_nodes(model, resolved.probes, named("probes"));
  for (const std::string& label : resolved.bearings) o.bearings.push_back(bearing_element(model, label));
  // The bearings as the analysis numbers them: journal and rolling bearings after
  // the model's own elements (linearised(), analyses/static/equilibrium.hpp).
  const Model lin = linearised(model);
  if (o.bearings.empty()) o.bearings = bearing_elements(lin);
  // Gravity (for the journal loads) as the file's [static] table gives it.
  o.gravity = static_options(spec, model);
  if (*resolved.map) o.map = map_options(lin, o, resolved, stop, named);
  if (*resolved.stability) {
    StabilitySweepOptions s;
    s.speed = o.high;
    s.node = resolved.stability_node ? find_node_reference(model, spec::detail::node_text(*resolved.stability_node),
                                                           named("stability_node"))
                                     : largest_forward_motion_node(model, o.high);
    s.anticipated = resolved.anticipated_q;
    o.stability = s;
  }
  return o;
}

Api684Result Api684Analysis::run(const Model& model, const Api684Options& options, const RunContext& context) {
  Api684Options o = options;
  o.stop = context.stop;
  o.n_threads = context.threads;
  if (o.map) o.map->n_threads = context.threads;
  return run_api684(model, o);
}

std::vector<std::string> Api684Analysis::warnings(const Model& model, const Api684Options& options,
                                                  const Api684Result&) {
  return range_warnings(model, options.speeds.front(), options.speeds.back());
}

// ---- study quantities ----------------------------------------------------------------

namespace {

Real undamped_critical_speed(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  // As API 684's: journal and rolling bearings by their direct stiffness about
  // the equilibrium at each critical speed, the search starting from the
  // operating range's top (or the Campbell range's end) on an oil film.
  SolverInfo info;
  const Model lin = has_supports(a.model()) ? linearised(a.model()) : Model();
  const Model* rotor = &a.model();
  Model direct;
  if (has_supports(a.model())) {
    direct = with_direct_bearing_stiffness(lin, bearing_elements(lin));
    rotor = &direct;
  }
  const Real start = !needs_speed(a.model()) ? 0.0
                     : q.operating_high > 0  ? q.operating_high
                                             : a.result<CampbellAnalysis>().speeds.back();
  const auto criticals = undamped_critical_speeds(*rotor, q.n, true, &info, start);
  if (!info.converged()) throw Error(fmt::format("the undamped critical speeds failed: {}", info.message));
  if (static_cast<int>(criticals.size()) < q.n)
    throw Error(fmt::format("the rotor has {} forward undamped critical speeds, not {}", criticals.size(), q.n));
  return criticals[static_cast<std::size_t>(q.n - 1)].speed;
}

Real level1_q_zero(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  StabilitySweepOptions s;
  s.speed = *q.speed;  // the reader requires it
  s.node = q.probe ? node_index(a.model(), *q.probe) : largest_forward_motion_node(a.model(), s.speed);
  s.points = 2;
  const StabilitySweepResult r = run_stability_sweep(a.model(), s);
  if (!r.q_zero)
    throw Error(
        fmt::format("no Q₀: the first forward mode at {} is {}", rpm(s.speed),
                    r.log_decrement.front() <= 0 ? "unstable without cross-coupling" : "stable up to 1e13 N/m"));
  return *r.q_zero;
}

}  // namespace

const std::vector<QuantityRow>& Api684Analysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "undamped_critical_speed",
       .doc = "the n-th forward undamped critical speed with the bearings as given",
       .analysis = "api684",
       .unit = Quantity::speed,
       .evaluate = undamped_critical_speed},
      {.name = "level1_q_zero",
       .doc = "API 617 level I: the cross-coupling Q at the probe where the first forward mode's log decrement is 0 "
              "at the speed",
       .analysis = "api684",
       .unit = Quantity::stiffness,
       .evaluate = level1_q_zero,
       .needs_speed = true},
  };
  return rows;
}

}  // namespace feran

#include <feran/analyses/settings.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

#include <feran/io/node_reference.hpp>
#include <feran/spec/request.hpp>
#include <fmt/ranges.h>

#include <feran/analyses/static/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/analyses/transient/integrator.hpp>
#include <feran/core/error.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/units.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/request.hpp>

namespace feran {

namespace {

void add_once(std::vector<Index>& nodes, Index node) {
  if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
}

// A value asked for (an option of the command line, named @p option in the message)
// checked by the rule of the model file's key @p key of table S: its bound and, for
// a quantity, the physical range of that quantity; so "-3 Hz" or "1e308 Hz" is
// refused wherever it is given.
template <class S>
std::optional<Real> checked(std::optional<Real> value, std::string_view key, std::string_view option) {
  if (!value) return value;
  const spec::Field<S>& f = spec::field_of<S>(key);
  spec::detail::check_number(*value, f.bound,
                             f.kind == spec::FieldKind::quantity ? std::optional<Quantity>(f.quantity) : std::nullopt,
                             f.unit, option);
  return value;
}

// A count asked for, checked by the bound of the model file's key @p key of table S.
template <class S>
std::optional<int> checked_count(std::optional<int> value, std::string_view key, std::string_view option) {
  if (!value) return value;
  spec::detail::check_integer(*value, spec::field_of<S>(key).bound, option);
  return value;
}

}  // namespace

std::vector<Index> distinct_nodes(const Model& model, const std::vector<NodeRef>& refs, const std::string& option) {
  std::vector<Index> nodes;
  for (const NodeRef& ref : refs) {
    const Index node = find_node_reference(model, spec::detail::node_text(ref), option);
    if (std::find(nodes.begin(), nodes.end(), node) != nodes.end())
      throw Error(fmt::format("{}: node {} is given twice", option, model.node_label(node)));
    nodes.push_back(node);
  }
  return nodes;
}

std::vector<Real> evenly_spaced(Real a, Real b, int n) {
  if (n == 1) return {a};
  std::vector<Real> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
  return out;
}

std::vector<Index> default_probes(const Model& model, std::span<const HarmonicForce> extra) {
  std::vector<Index> probes;
  for (const Force& f : model.forces)
    if (is_unbalance(f))
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

Api684Options api684_settings(const Model& model, const ModelSpec& file, const Api684Request& request) {
  const Api684Spec& f = file.api684;
  const std::optional<Real> low = request.min_speed ? request.min_speed : f.min_speed;
  const std::optional<Real> high = request.max_speed ? request.max_speed : f.max_speed;
  if (!low || !high)
    throw Error(
        "the API 684 analyses need the operating speed range: give [api684] min_speed and max_speed, or "
        "--min-speed and --max-speed");
  checked<Api684Spec>(request.min_speed, "min_speed", "--min-speed");
  checked<Api684Spec>(request.max_speed, "max_speed", "--max-speed");
  checked<Api684Spec>(request.stop, "stop", "--stop");
  checked<Api684Spec>(request.map_low, "map_low", "--map-low");
  checked<Api684Spec>(request.map_high, "map_high", "--map-high");
  checked<Api684Spec>(request.anticipated_q, "anticipated_q", "--anticipated-q");
  checked_count<Api684Spec>(request.points, "points", "--points");
  checked_count<Api684Spec>(request.modes, "modes", "--modes");
  checked_count<Api684Spec>(request.map_points, "map_points", "--map-points");
  checked_count<Api684Spec>(request.map_criticals, "map_criticals", "--map-criticals");
  if (*high < *low)
    throw Error(
        fmt::format("the maximum continuous speed ({:.6g} rpm) is below the minimum operating speed "
                    "({:.6g} rpm)",
                    *high * 30 / std::numbers::pi, *low * 30 / std::numbers::pi));
  Api684Options o;
  o.low = *low;
  o.high = *high;
  const Real stop = request.stop.value_or(f.stop.value_or(2 * *high));
  const int points = request.points.value_or(f.points.value_or(401));
  for (int i = 0; i < points; ++i) o.speeds.push_back(stop * i / (points - 1));
  o.modes = request.modes.value_or(f.modes.value_or(2));
  o.model_unbalance = request.model_unbalance.value_or(f.unbalance.value_or("4W/N") == "model");
  // Each count within its bounds, the work they multiply into bounded too: one
  // unbalance response (each point a solve and a stability decision) per mode.
  constexpr long long max_response_points = 200000;
  const long long cases = o.model_unbalance ? 1 : o.modes;
  if (cases * points > max_response_points)
    throw Error(
        fmt::format("[api684] the unbalance responses would take {} × {} = {} points (modes × points, "
                    "from --modes/modes and --points/points): at most {}; ask for fewer",
                    cases, points, cases * points, max_response_points));
  o.unbalance_multiple = request.unbalance_multiple.value_or(f.unbalance_multiple.value_or(1.0));
  checked<Api684Spec>(request.unbalance_multiple, "unbalance_multiple", "--unbalance-multiple");
  o.probes = request.probes;
  if (o.probes.empty())
    for (const NodeRef& p : f.probes) o.probes.push_back(node_index(model, p));
  o.bearings = request.bearings;
  if (o.bearings.empty())
    for (const std::string& name : f.bearings) o.bearings.push_back(bearing_element(model, name));
  // The bearings as the analysis numbers them: journal and rolling bearings after
  // the model's own elements (linearised(), analyses/static/equilibrium.hpp).
  const Model lin = linearised(model);
  if (o.bearings.empty()) o.bearings = bearing_elements(lin);
  // Gravity (for the journal loads) as the file's [static] table gives it.
  o.gravity = static_options(file, model);
  o.n_threads = request.n_threads;

  if (request.map) {
    CriticalSpeedMapOptions map;
    map.springs = o.bearings;
    // Two decades either side of the bearings' mean lateral stiffness at the
    // maximum continuous speed (geometric mean over bearings and directions).
    Real log_sum = 0;
    int count = 0;
    for (const Index e : o.bearings) {
      std::optional<Transmission> t;
      try {
        t = lin.elements[static_cast<std::size_t>(e)].transmission(*high);
      } catch (const Error&) {  // no journal equilibrium there: the analysis itself will say why
      }
      if (t)
        for (const Dof d : {Dof::v, Dof::w})
          if (const Real k = (*t).K(static_cast<Index>(d), static_cast<Index>(d)); k > 0)
            log_sum += std::log(k), ++count;
    }
    const Real centre = count > 0 ? std::exp(log_sum / count) : 1e7;
    map.k_low = request.map_low.value_or(f.map_low.value_or(centre / 100));
    map.k_high = request.map_high.value_or(f.map_high.value_or(centre * 100));
    map.points = request.map_points.value_or(f.map_points.value_or(41));
    map.criticals = request.map_criticals.value_or(f.map_criticals.value_or(4));
    constexpr long long max_map_work = 100000;
    if (static_cast<long long>(map.points) * map.criticals > max_map_work)
      throw Error(
          fmt::format("[api684] the critical speed map would take {} × {} = {} critical speeds "
                      "(map_points × map_criticals, from --map-points/map_points and "
                      "--map-criticals/map_criticals): at most {}; ask for fewer",
                      map.points, map.criticals, static_cast<long long>(map.points) * map.criticals, max_map_work));
    map.curve_stop = stop;
    map.n_threads = request.n_threads;
    o.map = map;
  }
  if (request.stability) {
    StabilitySweepOptions s;
    s.speed = *high;
    s.node = request.stability_node ? *request.stability_node
             : f.stability_node     ? node_index(model, *f.stability_node)
                                    : largest_forward_motion_node(model, *high);
    s.anticipated = request.anticipated_q ? request.anticipated_q : f.anticipated_q;
    o.stability = s;
  }
  return o;
}

std::optional<std::pair<Real, Real>> frequency_span(std::span<const Real> frequencies_hz) {
  std::optional<std::pair<Real, Real>> span;
  for (const Real f : frequencies_hz) {
    if (!std::isfinite(f)) continue;
    const Real w = 2.0 * pi * std::abs(f);
    span = span ? std::pair{std::min(span->first, w), std::max(span->second, w)} : std::pair{w, w};
  }
  return span;
}

std::vector<std::string> range_warnings(const Model& model, Real low, Real high,
                                        std::optional<std::pair<Real, Real>> frequencies) {
  std::vector<std::string> out;
  // Round-off of the sweep's own arithmetic is not "beyond" (1e-9 relative).
  const auto beyond = [](Real x, Real edge, bool above) {
    const Real margin = 1e-9 * std::max(std::abs(x), std::abs(edge));
    return above ? x > edge + margin : x < edge - margin;
  };
  const auto check = [&](const Element& e, const SpeedRange& r, Real lo, Real hi, std::string_view axis) {
    const bool over = beyond(hi, r.high, true), under = beyond(lo, r.low, false);
    if (!over && !under) return;
    out.push_back(
        fmt::format("'{}': {} is tabulated from {:.6g} to {:.6g} Hz{}; the analysis reaches {:.6g} Hz, where "
                    "its {} value is held",
                    e.label(), r.what, rad_to_hz(r.low), rad_to_hz(r.high), axis, rad_to_hz(over ? hi : lo),
                    over ? "last" : "first"));
  };
  const auto [f_low, f_high] = frequencies.value_or(std::pair{std::abs(low), std::abs(high)});
  for (const Element& e : model.elements) {
    for (const SpeedRange& r : e.speed_ranges()) check(e, r, low, high, "");
    for (const SpeedRange& r : e.frequency_ranges()) check(e, r, f_low, f_high, " in frequency");
  }
  return out;
}

std::pair<Real, Real> speed_span(const Model& model, const TransientOptions& options) {
  Real low = options.profile.speed(0.0), high = low;
  if (options.driven && model.drive) {
    const Real top = model.drive->motor.free_speed();
    return {std::min(low, top), std::max(low, top)};
  }
  for (const auto& [t, w] : options.profile.points())
    if (t <= options.duration) low = std::min(low, w), high = std::max(high, w);
  low = std::min(low, options.profile.speed(options.duration));
  high = std::max(high, options.profile.speed(options.duration));
  return {low, high};
}

// The model's connecting elements (connection(), model/element.hpp) are its
// spring–dampers: the bearings its analyses name.
Index spring_element(const Model& model, const std::string& name) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (model.elements[e].connection() && model.elements[e].label() == name) return static_cast<Index>(e);
  throw Error(fmt::format("no spring-damper is named '{}'", name));
}

Index bearing_element(const Model& model, const std::string& name) {
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (model.elements[e].connection() && model.elements[e].label() == name) return static_cast<Index>(e);
  Index k = static_cast<Index>(model.elements.size());
  std::vector<std::string> names;
  for (const Force& f : model.forces) {
    if (!f.supports()) continue;
    if (f.label() == name) return k;
    ++k;
    if (!f.label().empty()) names.push_back(fmt::format("'{}'", f.label()));
  }
  for (const Element& e : model.elements)
    if (e.connection() && !e.label().empty()) names.push_back(fmt::format("'{}'", e.label()));
  throw Error(
      fmt::format("no spring-damper, journal or rolling bearing is named '{}'{}", name,
                  names.empty() ? std::string() : fmt::format(" (the named ones: {})", fmt::join(names, ", "))));
}

}  // namespace feran

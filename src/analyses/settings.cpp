#include <feran/analyses/settings.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <feran/analyses/static/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/integrators/integrator.hpp>
#include <feran/core/error.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/units.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/request.hpp>

namespace feran {

namespace {

void add_once(std::vector<Index>& nodes, Index node) {
  if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
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

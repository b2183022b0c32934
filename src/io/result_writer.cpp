#include <feran/io/result_writer.hpp>

#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/static/equilibrium.hpp>

#include "result_text.hpp"

#include <feran/core/error.hpp>

namespace feran {

namespace {

using nlohmann::json;

using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

}  // namespace

std::string parameters_json(const std::vector<Parameter>& parameters, const ResultSource& source) {
  json out = header("params", source);
  json list = json::array();
  for (const Parameter& p : parameters)
    list.push_back({{"path", p.path},
                    {"value", json_number(p.value)},
                    {"si_unit", p.quantity ? std::string(si_unit(*p.quantity)) : std::string()},
                    {"quantity", p.quantity ? std::string(quantity_name(*p.quantity)) : std::string()},
                    {"integer", p.integer},
                    {"text", p.text()},
                    {"doc", p.doc}});
  out["parameters"] = std::move(list);
  return detail::json_text(out, 2);
}

namespace {

Real rpm_of(Real speed) { return rad_to_hz(speed) * 60.0; }

json rpms(const std::vector<Real>& speeds) {
  json a = json::array();
  for (const Real s : speeds) a.push_back(json_number(rpm_of(s)));
  return a;
}

json optional_number(const std::optional<Real>& x) { return x ? json_number(*x) : json(nullptr); }

json case_json(const Api684Case& c, const Model& model) {
  json jc = {{"name", c.name}, {"passes", c.passes}, {"solver", solver_json(c.response.info)}};
  jc["mode"] = c.mode ? json{{"frequency_hz", json_number(c.mode->frequency_hz)},
                             {"log_decrement", json_number(c.mode->log_decrement)},
                             {"damping_ratio", json_number(c.mode->damping_ratio)}}
                      : json(nullptr);
  json unbalances = json::array();
  for (const PlacedUnbalance& u : c.unbalances) {
    json ju = node_json(model, u.node);
    ju["amount_kg_m"] = u.amount;
    ju["amount_g_mm"] = u.amount * 1e6;
    ju["phase_deg"] = u.phase * 180.0 / pi;
    ju["journal_mass_kg"] = u.mass;
    ju["basis"] = u.basis;
    unbalances.push_back(ju);
  }
  jc["unbalances"] = unbalances;
  jc["speeds_rpm"] = rpms(c.response.speeds);
  json probes = json::array();
  for (std::size_t p = 0; p < c.response.probes.size(); ++p) {
    const ProbeResponse& pr = c.response.probes[p];
    json jp = node_json(model, pr.node);
    json amplitude = json::array();
    for (const Orbit& o : pr.orbit) amplitude.push_back(json_number(o.major));
    jp["amplitude_m"] = amplitude;
    json peaks = json::array();
    for (const SeparationCheck& k : c.checks[p])
      peaks.push_back({{"speed_rpm", json_number(rpm_of(k.peak.speed))},
                       {"amplitude_m", json_number(k.peak.amplitude)},
                       {"lower_half_power_rpm",
                        k.peak.lower_half_power ? json_number(rpm_of(*k.peak.lower_half_power)) : json(nullptr)},
                       {"upper_half_power_rpm",
                        k.peak.upper_half_power ? json_number(rpm_of(*k.peak.upper_half_power)) : json(nullptr)},
                       {"amplification_factor", json_number(k.peak.amplification_factor)},
                       {"actual_margin", json_number(k.actual_margin)},
                       {"required_margin", optional_number(k.required_margin)},
                       {"passes", k.passes ? json(*k.passes) : json(nullptr)},
                       {"unstable", k.unstable}});
    jp["peaks"] = peaks;
    probes.push_back(jp);
  }
  jc["probes"] = probes;
  jc["stability"] = point_stability_json(c.response.stability);
  return jc;
}

json map_json(const CriticalSpeedMapResult& map, const Model& model) {
  json jm = {
      {"bearings", json::array()}, {"stiffness_n_per_m", numbers(map.stiffness)}, {"solver", solver_json(map.info)}};
  for (const Index e : map.springs) jm["bearings"].push_back(element_label(model, e));
  const std::size_t nc = map.criticals.empty() ? 0 : map.criticals.front().size();
  json lines = json::array();
  for (std::size_t n = 0; n < nc; ++n) {
    json line = json::array();
    for (const auto& row : map.criticals) line.push_back(json_number(rpm_of(row[n])));
    lines.push_back(line);
  }
  jm["criticals_rpm"] = lines;
  json curves = json::array();
  for (const BearingCurve& c : map.curves)
    curves.push_back({{"bearing", element_label(model, c.element)},
                      {"direction", c.direction},
                      {"speeds_rpm", rpms(c.speeds)},
                      {"stiffness_n_per_m", numbers(c.stiffness)}});
  jm["curves"] = curves;
  json crossings = json::array();
  for (const MapIntersection& x : map.intersections)
    crossings.push_back({{"bearing", element_label(model, x.element)},
                         {"direction", x.direction},
                         {"critical", x.critical},
                         {"speed_rpm", json_number(rpm_of(x.speed))},
                         {"stiffness_n_per_m", json_number(x.stiffness)}});
  jm["intersections"] = crossings;
  return jm;
}

json stability_json(const StabilitySweepResult& s, const Model& model) {
  json js = node_json(model, s.node);
  js["speed_rpm"] = rpm_of(s.speed);
  js["q_n_per_m"] = numbers(s.q);
  js["log_decrement"] = numbers(s.log_decrement);
  js["frequency_hz"] = numbers(s.frequency_hz);
  js["q_zero_n_per_m"] = optional_number(s.q_zero);
  js["anticipated_n_per_m"] = optional_number(s.anticipated);
  js["log_decrement_at_anticipated"] = optional_number(s.log_decrement_at_anticipated);
  js["screening_passes"] = s.screening_passes ? json(*s.screening_passes) : json(nullptr);
  js["solver"] = solver_json(s.info);
  return js;
}

}  // namespace

std::string api684_json(const Api684Result& result, const Model& model, const ResultSource& source) {
  json j = header("api684", source);
  j["operating"] = {{"min_rpm", rpm_of(result.low)}, {"max_rpm", rpm_of(result.high)}};
  j["solver"] = solver_json(result.info);
  {
    const OperatingStability& v = result.stability_verdict;
    json speeds = json::array(), unstable = json::array(), growth = json::array();
    for (const StabilityPoint& p : v.points) {
      speeds.push_back(json_number(rpm_of(p.speed)));
      unstable.push_back(p.known ? json(p.unstable) : json(nullptr));
      growth.push_back(json_number(p.growth_rate));
    }
    j["operating_stability"] = {{"passes", v.passes},
                                {"reason", v.reason},
                                {"speeds_rpm", speeds},
                                {"unstable", unstable},
                                {"growth_rate_per_s", growth}};
  }
  json journals = json::array();
  for (const JournalLoad& l : result.journals) {
    json jl = node_json(model, l.node);
    jl["bearing"] = element_label(model, l.element);
    jl["force_n"] = l.force;
    jl["mass_kg"] = l.mass;
    journals.push_back(jl);
  }
  j["journal_loads"] = journals;
  j["bearings"] = json::array();
  for (const Index e : result.bearings) j["bearings"].push_back(element_label(model, e));
  json undamped = json::array();
  for (const UndampedCritical& c : result.undamped)
    undamped.push_back({{"speed_rpm", json_number(rpm_of(c.speed))}, {"directivity", json_number(c.directivity)}});
  j["undamped_criticals"] = undamped;
  json cases = json::array();
  bool passes = true;
  for (const Api684Case& c : result.cases) {
    cases.push_back(case_json(c, model));
    passes = passes && c.passes;
  }
  j["cases"] = cases;
  j["separation_margins_pass"] = passes;
  j["map"] = result.map ? map_json(*result.map, model) : json(nullptr);
  j["stability"] = result.stability ? stability_json(*result.stability, model) : json(nullptr);
  return detail::json_text(j, 2);
}

}  // namespace feran

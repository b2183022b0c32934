// The API 617 / API 684 analyses' writers: their JSON, CSV and terminal report
// (analyses/api684/analysis.hpp), in the writers' shared vocabulary (result_text.hpp).
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/api684/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/text.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace {

Real rpm_of(Real speed) { return rad_to_hz(speed) * 60.0; }

Json rpms(const std::vector<Real>& speeds) {
  Json a = Json::array();
  for (const Real s : speeds) a.push_back(json_number(rpm_of(s)));
  return a;
}

Json optional_number(const std::optional<Real>& x) { return x ? json_number(*x) : Json(nullptr); }

Json case_json(const Api684Case& c, const Model& model) {
  Json jc = {{"name", c.name}, {"passes", c.passes}, {"solver", solver_json(c.response.info)}};
  jc["mode"] = c.mode ? Json{{"frequency_hz", json_number(c.mode->frequency_hz)},
                             {"log_decrement", json_number(c.mode->log_decrement)},
                             {"damping_ratio", json_number(c.mode->damping_ratio)}}
                      : Json(nullptr);
  Json unbalances = Json::array();
  for (const PlacedUnbalance& u : c.unbalances) {
    Json ju = node_json(model, u.node);
    ju["amount_kg_m"] = u.amount;
    ju["amount_g_mm"] = u.amount * 1e6;
    ju["phase_deg"] = u.phase * 180.0 / pi;
    ju["journal_mass_kg"] = u.mass;
    ju["basis"] = u.basis;
    unbalances.push_back(ju);
  }
  jc["unbalances"] = unbalances;
  jc["speeds_rpm"] = rpms(c.response.speeds);
  Json probes = Json::array();
  for (std::size_t p = 0; p < c.response.probes.size(); ++p) {
    const ProbeResponse& pr = c.response.probes[p];
    Json jp = node_json(model, pr.node);
    Json amplitude = Json::array();
    for (const Orbit& o : pr.orbit) amplitude.push_back(json_number(o.major));
    jp["amplitude_m"] = amplitude;
    Json peaks = Json::array();
    for (const SeparationCheck& k : c.checks[p])
      peaks.push_back({{"speed_rpm", json_number(rpm_of(k.peak.speed))},
                       {"amplitude_m", json_number(k.peak.amplitude)},
                       {"lower_half_power_rpm",
                        k.peak.lower_half_power ? json_number(rpm_of(*k.peak.lower_half_power)) : Json(nullptr)},
                       {"upper_half_power_rpm",
                        k.peak.upper_half_power ? json_number(rpm_of(*k.peak.upper_half_power)) : Json(nullptr)},
                       {"amplification_factor", json_number(k.peak.amplification_factor)},
                       {"actual_margin", json_number(k.actual_margin)},
                       {"required_margin", optional_number(k.required_margin)},
                       {"passes", k.passes ? Json(*k.passes) : Json(nullptr)},
                       {"unstable", k.unstable}});
    jp["peaks"] = peaks;
    probes.push_back(jp);
  }
  jc["probes"] = probes;
  jc["stability"] = point_stability_json(c.response.stability);
  return jc;
}

Json map_json(const CriticalSpeedMapResult& map, const Model& model) {
  Json jm = {
      {"bearings", Json::array()}, {"stiffness_n_per_m", numbers(map.stiffness)}, {"solver", solver_json(map.info)}};
  for (const Index e : map.springs) jm["bearings"].push_back(element_label(model, e));
  const std::size_t nc = map.criticals.empty() ? 0 : map.criticals.front().size();
  Json lines = Json::array();
  for (std::size_t n = 0; n < nc; ++n) {
    Json line = Json::array();
    for (const auto& row : map.criticals) line.push_back(json_number(rpm_of(row[n])));
    lines.push_back(line);
  }
  jm["criticals_rpm"] = lines;
  Json curves = Json::array();
  for (const BearingCurve& c : map.curves)
    curves.push_back({{"bearing", element_label(model, c.element)},
                      {"direction", c.direction},
                      {"speeds_rpm", rpms(c.speeds)},
                      {"stiffness_n_per_m", numbers(c.stiffness)}});
  jm["curves"] = curves;
  Json crossings = Json::array();
  for (const MapIntersection& x : map.intersections)
    crossings.push_back({{"bearing", element_label(model, x.element)},
                         {"direction", x.direction},
                         {"critical", x.critical},
                         {"speed_rpm", json_number(rpm_of(x.speed))},
                         {"stiffness_n_per_m", json_number(x.stiffness)}});
  jm["intersections"] = crossings;
  return jm;
}

Json stability_json(const StabilitySweepResult& s, const Model& model) {
  Json js = node_json(model, s.node);
  js["speed_rpm"] = rpm_of(s.speed);
  js["q_n_per_m"] = numbers(s.q);
  js["log_decrement"] = numbers(s.log_decrement);
  js["frequency_hz"] = numbers(s.frequency_hz);
  js["q_zero_n_per_m"] = optional_number(s.q_zero);
  js["anticipated_n_per_m"] = optional_number(s.anticipated);
  js["log_decrement_at_anticipated"] = optional_number(s.log_decrement_at_anticipated);
  js["screening_passes"] = s.screening_passes ? Json(*s.screening_passes) : Json(nullptr);
  js["solver"] = solver_json(s.info);
  return js;
}

}  // namespace

std::string Api684Analysis::json(const Outcome<Api684Analysis>& o) {
  const Api684Result& result = o.result;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  Json j = header("api684", source);
  j["operating"] = {{"min_rpm", rpm_of(result.low)}, {"max_rpm", rpm_of(result.high)}};
  j["solver"] = solver_json(result.info);
  {
    const OperatingStability& v = result.stability_verdict;
    Json speeds = Json::array(), unstable = Json::array(), growth = Json::array();
    for (const StabilityPoint& p : v.points) {
      speeds.push_back(json_number(rpm_of(p.speed)));
      unstable.push_back(p.known ? Json(p.unstable) : Json(nullptr));
      growth.push_back(json_number(p.growth_rate));
    }
    j["operating_stability"] = {{"passes", v.passes},
                                {"reason", v.reason},
                                {"speeds_rpm", speeds},
                                {"unstable", unstable},
                                {"growth_rate_per_s", growth}};
  }
  Json journals = Json::array();
  for (const JournalLoad& l : result.journals) {
    Json jl = node_json(model, l.node);
    jl["bearing"] = element_label(model, l.element);
    jl["force_n"] = l.force;
    jl["mass_kg"] = l.mass;
    journals.push_back(jl);
  }
  j["journal_loads"] = journals;
  j["bearings"] = Json::array();
  for (const Index e : result.bearings) j["bearings"].push_back(element_label(model, e));
  Json undamped = Json::array();
  for (const UndampedCritical& c : result.undamped)
    undamped.push_back({{"speed_rpm", json_number(rpm_of(c.speed))}, {"directivity", json_number(c.directivity)}});
  j["undamped_criticals"] = undamped;
  Json cases = Json::array();
  bool passes = true;
  for (const Api684Case& c : result.cases) {
    cases.push_back(case_json(c, model));
    passes = passes && c.passes;
  }
  j["cases"] = cases;
  j["separation_margins_pass"] = passes;
  j["map"] = result.map ? map_json(*result.map, model) : Json(nullptr);
  j["stability"] = result.stability ? stability_json(*result.stability, model) : Json(nullptr);
  return detail::json_text(j, 2);
}

std::string Api684Analysis::csv(const Outcome<Api684Analysis>& o) {
  std::ostringstream out;
  out << "case,probe,speed_rpm,amplitude_m,amplification_factor,required_margin,actual_margin,passes,unstable\n";
  for (const Api684Case& c : o.result.cases)
    for (std::size_t p = 0; p < c.response.probes.size(); ++p)
      for (const SeparationCheck& k : c.checks[p])
        out << csv_field(c.name) << ',' << csv_field(o.model().node_label(c.response.probes[p].node)) << ','
            << csv_number(rad_to_hz(k.peak.speed) * 60.0) << ',' << csv_number(k.peak.amplitude) << ','
            << csv_number(k.peak.amplification_factor) << ','
            << (k.required_margin ? csv_number(*k.required_margin) : std::string()) << ','
            << csv_number(k.actual_margin) << ',' << (k.passes ? (*k.passes ? "1" : "0") : "") << ','
            << (k.unstable ? 1 : 0) << '\n';
  return out.str();
}

namespace {

std::string bearing_name(const Model& model, Index e) { return element_name(model, e); }

std::string api684_cases(const Api684Result& result, const Model& model, const std::string& unit) {
  std::string out;
  for (const Api684Case& c : result.cases) {
    out += fmt::format("\n{}", c.name);
    if (c.mode)
      out += fmt::format(" ({} at the maximum continuous speed, log. decr. {:.3f})",
                         frequency_text(c.mode->frequency_hz, unit), c.mode->log_decrement);
    out += fmt::format(": {}\n", c.passes ? "passes" : "FAILS");
    for (const PlacedUnbalance& u : c.unbalances)
      out += fmt::format("  unbalance {:.4g} g mm at node {}, {:.0f} deg (W = {:.4g} kg, {})\n", u.amount * 1e6,
                         model.node_label(u.node), u.phase * 180.0 / pi, u.mass, printable(u.basis));
    out += fmt::format("  {:<16} {:>11} {:>13} {:>8} {:>10} {:>10}  {}\n", "probe", fmt::format("peak [{}]", unit),
                       "amplitude [um]", "AF", "SM req.", "SM actual", "verdict");
    for (std::size_t p = 0; p < c.response.probes.size(); ++p)
      for (const SeparationCheck& k : c.checks[p])
        out += fmt::format(
            "  {:<16} {} {:>13.4g} {} {} {:>9.1f}%  {}\n", printable(model.node_label(c.response.probes[p].node)),
            cell(speed_value(k.peak.speed, unit), unit == "rpm" ? ".0f" : ".2f", 11, unit == "rpm" ? 0 : 2),
            k.peak.amplitude * 1e6, cell(k.peak.amplification_factor, ".2f", 8, 2),
            k.required_margin ? fmt::format("{:>9.1f}%", 100 * *k.required_margin) : fmt::format("{:>10}", "-"),
            100 * k.actual_margin,
            k.unstable  ? "FAIL (rotor unstable here: no steady state)"
            : !k.passes ? "not judged (no half-power points)"
            : *k.passes ? "pass"
                        : "FAIL");
  }
  return out;
}

}  // namespace

std::string Api684Analysis::terminal(const Outcome<Api684Analysis>& o) {
  const Api684Result& result = o.result;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  std::string out = source_line("api684", source);
  out += fmt::format("operating range {} to {}\n", speed_short(result.low, source.speed_unit),
                     speed_short(result.high, source.speed_unit));
  out += fmt::format("stability in the operating range: {} ({})\n",
                     result.stability_verdict.passes ? "passes" : "FAILS", result.stability_verdict.reason);
  if (!result.journals.empty()) {
    out += "\njournal loads:";
    for (const JournalLoad& j : result.journals)
      out += fmt::format(" {} {:.4g} N ({:.4g} kg);", bearing_name(model, j.element), j.force, j.mass);
    out.back() = '\n';
  }
  out += "undamped critical speeds (forward, bearings as given):";
  for (const UndampedCritical& c : result.undamped) out += " " + speed_short(c.speed, source.speed_unit);
  out += "\n";
  out += api684_cases(result, model, source.speed_unit);
  if (result.map) {
    const CriticalSpeedMapResult& m = *result.map;
    out += fmt::format("\nundamped critical speed map: {} stiffness values from {:.3g} to {:.3g} N/m\n",
                       m.stiffness.size(), m.stiffness.empty() ? 0.0 : m.stiffness.front(),
                       m.stiffness.empty() ? 0.0 : m.stiffness.back());
    for (const MapIntersection& x : m.intersections)
      out += fmt::format("  {} ({}) meets critical {} at {} ({:.4g} N/m)\n", bearing_name(model, x.element),
                         x.direction, x.critical, speed_short(x.speed, source.speed_unit), x.stiffness);
    if (!m.info.converged()) out += fmt::format("  warning: {}\n", m.info.message);
  }
  if (result.stability) {
    const StabilitySweepResult& s = *result.stability;
    out += fmt::format("\nlevel I stability at {}, cross-coupling at node {}:\n",
                       speed_short(s.speed, source.speed_unit), model.node_label(s.node));
    if (!s.log_decrement.empty())
      out += fmt::format("  log. decr. without cross-coupling {:.4f}\n", s.log_decrement.front());
    out += s.q_zero ? fmt::format("  Q0 (log. decr. 0) = {:.4g} N/m\n", *s.q_zero)
                    : std::string("  Q0: none found (unstable without cross-coupling, or stable up to 1e13 N/m)\n");
    if (s.anticipated)
      out += fmt::format("  anticipated q_A = {:.4g} N/m: Q0/q_A = {}, log. decr. at q_A {:.4f}: {}\n", *s.anticipated,
                         s.q_zero ? fmt::format("{:.3g}", *s.q_zero / *s.anticipated) : std::string("-"),
                         s.log_decrement_at_anticipated.value_or(NAN),
                         s.screening_passes.value_or(false) ? "passes level I" : "level II required");
  }
  if (!result.info.converged()) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

}  // namespace feran

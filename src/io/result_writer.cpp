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

Real degrees(Complex c) { return std::arg(c) * 180.0 / pi; }

// Amplitude and phase per point of the DOFs whose mask is set, keyed by DOF name.
json dof_series(const std::vector<NodeAmplitudes>& values, const std::array<bool, dofs_per_node>& mask,
                const char* const names[dofs_per_node]) {
  json out = json::object();
  for (int d = 0; d < dofs_per_node; ++d) {
    if (!mask[static_cast<std::size_t>(d)]) continue;
    std::vector<Real> amp, phase;
    for (const NodeAmplitudes& v : values) {
      amp.push_back(std::abs(v[static_cast<std::size_t>(d)]));
      phase.push_back(degrees(v[static_cast<std::size_t>(d)]));
    }
    out[names[d]] = {{"amplitude", numbers(amp)}, {"phase_deg", numbers(phase)}};
  }
  return out;
}

// The rotor's stability at each point of a steady-state result (modal/stability.hpp):
// per point whether it is unstable (null: unknown), the largest growth rate where
// eigenvalues were computed, and the first unstable speed.
json point_stability_json(const std::vector<StabilityPoint>& points) {
  if (points.empty()) return nullptr;
  json unstable = json::array(), growth = json::array(), frequency = json::array(), kind = json::array();
  Index first = -1, count = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const StabilityPoint& p = points[k];
    unstable.push_back(p.known ? json(p.unstable) : json(nullptr));
    growth.push_back(detail::json_number(p.growth_rate));
    frequency.push_back(p.unstable ? detail::json_number(p.frequency_hz) : json(nullptr));
    kind.push_back(stability_kind(p));
    if (p.unstable) {
      ++count;
      if (first < 0) first = static_cast<Index>(k);
    }
  }
  json j = {{"unstable", unstable},
            {"growth_rate_per_s", growth},
            {"unstable_mode_frequency_hz", frequency},
            {"kind", kind},
            {"unstable_points", count}};
  j["first_unstable_speed_hz"] =
      first < 0 ? json(nullptr) : json(rad_to_hz(points[static_cast<std::size_t>(first)].speed));
  j["note"] = count == 0 ? "stable at every point"
                         : "where unstable the response is no steady state the rotor reaches: any disturbance grows";
  return j;
}

}  // namespace

std::string response_json(const HarmonicResult& result, const HarmonicOptions& options, const Model& model,
                          const ResultSource& source) {
  json j = header("response", source);
  const std::size_t n = result.speeds.size();
  const std::size_t wanted = result.frequency_sweep ? options.frequencies.size() : options.speeds.size();
  j["sweep"] = result.frequency_sweep ? "frequency" : "speed";
  j["complete"] = result.info.converged() && n == wanted;
  std::vector<Real> speeds, freqs;
  for (std::size_t k = 0; k < n; ++k) {
    speeds.push_back(rad_to_hz(result.speeds[k]));
    freqs.push_back(rad_to_hz(result.frequencies[k]));
  }
  j["speeds_hz"] = numbers(speeds);
  j["frequencies_hz"] = numbers(freqs);
  j["loss_factor"] = options.loss_factor;
  j["unbalance"] = options.unbalance && !result.frequency_sweep &&
                   std::any_of(model.forces.begin(), model.forces.end(), is_unbalance);
  j["solver"] = solver_json(result.info);
  j["stability"] = point_stability_json(result.stability);

  json probes = json::array();
  for (const ProbeResponse& p : result.probes) {
    json jp = node_json(model, p.node);
    std::vector<Real> major, minor, incl, phase;
    json whirl = json::array();
    for (std::size_t k = 0; k < p.orbit.size(); ++k) {
      major.push_back(p.orbit[k].major);
      minor.push_back(p.orbit[k].minor);
      incl.push_back(p.orbit[k].inclination * 180.0 / pi);
      phase.push_back(degrees(p.q[k][static_cast<std::size_t>(Dof::v)]));
      whirl.push_back(to_string(p.orbit[k].whirl));
    }
    jp["amplitude_m"] = numbers(major);
    jp["phase_deg"] = numbers(phase);
    jp["minor_m"] = numbers(minor);
    jp["inclination_deg"] = numbers(incl);
    jp["whirl"] = whirl;
    jp["dofs"] = dof_series(p.q, all_dofs, dof_names);
    probes.push_back(jp);
  }
  j["probes"] = probes;

  json springs = json::array();
  for (const SpringForceResponse& s : result.springs) {
    const Transmission link = *model.elements[static_cast<std::size_t>(s.element)].transmission(0.0);
    json js = {{"label", element_label(model, s.element)},
               {"node", model.nodes[static_cast<std::size_t>(link.node_a)].number},
               {"peak_lateral_force_n", numbers(s.peak_lateral)},
               {"force", dof_series(s.force, all_dofs, direction_names)}};
    js["to"] = link.node_b ? json(model.nodes[static_cast<std::size_t>(*link.node_b)].number) : json("ground");
    springs.push_back(js);
  }
  j["springs"] = springs;

  json supports = json::array();
  const json operating = detail::operating_json(result.operating, model);
  for (const SupportForceResponse& s : result.supports) {
    const std::vector<Index> at = model.forces[static_cast<std::size_t>(s.force)].nodes();
    json js = {{"label", force_label(model, s.force)},
               {"node", model.nodes[static_cast<std::size_t>(at.front())].number},
               {"peak_lateral_force_n", numbers(s.peak_lateral)},
               {"force", dof_series(s.amplitude, lateral_dofs, direction_names)},
               {"orbit_m", numbers(s.orbit)},
               {"orbit_clearance_ratio", numbers(s.orbit_clearance_ratio)}};
    js["to"] = at.size() > 1 ? json(model.nodes[static_cast<std::size_t>(at[1])].number) : json("ground");
    Real largest = -1;
    for (const Real r : s.orbit_clearance_ratio)
      if (r > largest) largest = r;
    js["largest_orbit_clearance_ratio"] = largest >= 0 ? json(largest) : json(nullptr);
    if (supports.size() < operating.size()) js["operating"] = operating[supports.size()]["operating"];
    supports.push_back(js);
  }
  j["supports"] = supports;

  json reactions = json::array();
  for (const ReactionResponse& r : result.reactions) {
    json jr = node_json(model, r.node);
    jr["peak_lateral_force_n"] = numbers(r.peak_lateral);
    jr["force"] = dof_series(r.force, r.fixed, direction_names);
    reactions.push_back(jr);
  }
  j["reactions"] = reactions;

  json stations = json::array();
  for (const StationResponse& st : result.stations) {
    json js = station_json(model, st.station);
    std::vector<Real> vm, ax, be, to, sh, fn, fv, ft, fm;
    for (const SectionStress& s : st.stress) {
      vm.push_back(s.von_mises), ax.push_back(s.axial), be.push_back(s.bending);
      to.push_back(s.torsion), sh.push_back(s.shear);
    }
    for (const SectionForces& f : st.forces) {
      fn.push_back(std::abs(f.N)), ft.push_back(std::abs(f.T));
      fv.push_back(orbit(f.Vy, f.Vz).major), fm.push_back(orbit(f.My, f.Mz).major);
    }
    js["axial_force_n"] = numbers(fn);
    js["shear_force_n"] = numbers(fv);
    js["torque_nm"] = numbers(ft);
    js["bending_moment_nm"] = numbers(fm);
    js["von_mises_pa"] = numbers(vm);
    js["axial_pa"] = numbers(ax);
    js["bending_pa"] = numbers(be);
    js["torsion_pa"] = numbers(to);
    js["shear_pa"] = numbers(sh);
    stations.push_back(js);
  }
  j["stations"] = stations;
  j["stations_output"] = to_string(options.stations);
  if (result.shaft_stations.empty()) {
    j["station_peaks"] = nullptr;
  } else {
    // Per point, the largest value over the stations and where it is.
    auto peaks = [&](const char* unit, auto member) {
      std::vector<Real> value, x;
      json element = json::array(), end = json::array(), node = json::array();
      for (const StationPeaks& p : result.station_peaks) {
        const StationPeak& peak = p.*member;
        const ShaftStation& st = result.shaft_stations[static_cast<std::size_t>(peak.station)];
        value.push_back(peak.value);
        x.push_back(st.x);
        element.push_back(element_label(model, st.element));
        end.push_back(st.end == 0 ? "start" : "end");
        node.push_back(model.nodes[static_cast<std::size_t>(st.node)].number);
      }
      return json{{unit, numbers(value)}, {"x_m", numbers(x)}, {"element", element}, {"end", end}, {"node", node}};
    };
    j["station_peaks"] = {{"von_mises", peaks("value_pa", &StationPeaks::von_mises)},
                          {"bending_moment", peaks("value_nm", &StationPeaks::bending_moment)},
                          {"shear_force", peaks("value_n", &StationPeaks::shear_force)}};
  }

  const ResponseSummary sum = summarize(result);
  auto at = [&](Index k) {
    return json{{"speed_hz", rad_to_hz(result.speeds[static_cast<std::size_t>(k)])},
                {"frequency_hz", rad_to_hz(result.frequencies[static_cast<std::size_t>(k)])}};
  };
  json summary;
  json peaks = json::array();
  for (std::size_t p = 0; p < sum.probe_peaks.size(); ++p) {
    if (sum.probe_peaks[p].point < 0) continue;
    json jp = node_json(model, result.probes[p].node);
    jp["peak_amplitude_m"] = sum.probe_peaks[p].value;
    jp.update(at(sum.probe_peaks[p].point));
    peaks.push_back(jp);
  }
  summary["probes"] = peaks;
  summary["largest_spring_force"] = nullptr;
  if (sum.spring_force.point >= 0) {
    json js = {{"label", element_label(model, result.springs[static_cast<std::size_t>(sum.spring_force.item)].element)},
               {"peak_lateral_force_n", sum.spring_force.value}};
    js.update(at(sum.spring_force.point));
    summary["largest_spring_force"] = js;
  }
  summary["largest_bearing_force"] = nullptr;
  if (sum.support_force.point >= 0) {
    json js = {{"label", force_label(model, result.supports[static_cast<std::size_t>(sum.support_force.item)].force)},
               {"peak_lateral_force_n", sum.support_force.value}};
    js.update(at(sum.support_force.point));
    summary["largest_bearing_force"] = js;
  }
  summary["largest_reaction"] = nullptr;
  if (sum.reaction_force.point >= 0) {
    json jr = node_json(model, result.reactions[static_cast<std::size_t>(sum.reaction_force.item)].node);
    jr["peak_lateral_force_n"] = sum.reaction_force.value;
    jr.update(at(sum.reaction_force.point));
    summary["largest_reaction"] = jr;
  }
  summary["largest_stress"] = nullptr;
  if (sum.stress.point >= 0) {
    json js = station_json(model, result.shaft_stations[static_cast<std::size_t>(sum.stress.item)]);
    js["von_mises_pa"] = sum.stress.value;
    js.update(at(sum.stress.point));
    summary["largest_stress"] = js;
  }
  j["summary"] = summary;
  return detail::json_text(j, 2);
}

std::string response_csv(const HarmonicResult& result, const Model& model) {
  std::ostringstream out;
  auto node_tag = [&](Index node) { return detail::csv_node_tag(model, node); };
  out << "speed_hz,frequency_hz";
  for (const ProbeResponse& p : result.probes)
    for (const char* suffix :
         {"_amplitude_m", "_minor_m", "_v_amplitude_m", "_v_phase_deg", "_w_amplitude_m", "_w_phase_deg"})
      out << ',' << detail::csv_column(node_tag(p.node), suffix);
  for (const SpringForceResponse& s : result.springs)
    out << ',' << detail::csv_column(element_label(model, s.element), "_peak_lateral_force_n");
  for (const SupportForceResponse& s : result.supports)
    out << ',' << detail::csv_column(force_label(model, s.force), "_peak_lateral_force_n");
  for (const ReactionResponse& r : result.reactions)
    out << ',' << detail::csv_column(node_tag(r.node), "_support_peak_lateral_force_n");
  out << detail::operating_csv_header(result.operating, model);
  const bool peaks = !result.shaft_stations.empty();
  const bool stability = !result.stability.empty();
  out << (peaks ? ",max_von_mises_pa,max_von_mises_x_m" : "") << (stability ? ",unstable,growth_rate_per_s\n" : "\n");
  for (std::size_t k = 0; k < result.speeds.size(); ++k) {
    out << csv_number(rad_to_hz(result.speeds[k])) << ',' << csv_number(rad_to_hz(result.frequencies[k]));
    for (const ProbeResponse& p : result.probes) {
      const Complex v = p.q[k][static_cast<std::size_t>(Dof::v)], w = p.q[k][static_cast<std::size_t>(Dof::w)];
      out << ',' << csv_number(p.orbit[k].major) << ',' << csv_number(p.orbit[k].minor) << ','
          << csv_number(std::abs(v)) << ',' << csv_number(degrees(v)) << ',' << csv_number(std::abs(w)) << ','
          << csv_number(degrees(w));
    }
    for (const SpringForceResponse& s : result.springs) out << ',' << csv_number(s.peak_lateral[k]);
    for (const SupportForceResponse& s : result.supports) out << ',' << csv_number(s.peak_lateral[k]);
    for (const ReactionResponse& r : result.reactions) out << ',' << csv_number(r.peak_lateral[k]);
    out << detail::operating_csv_row(result.operating, k);
    if (peaks) {
      const StationPeak& vm = result.station_peaks[k].von_mises;
      out << ',' << csv_number(vm.value) << ','
          << csv_number(result.shaft_stations[static_cast<std::size_t>(vm.station)].x);
    }
    if (stability) {  // 1 unstable, 0 stable, empty unknown
      const StabilityPoint& p = result.stability[k];
      out << ',' << (p.known ? (p.unstable ? "1" : "0") : "") << ',' << csv_number(p.growth_rate);
    }
    out << '\n';
  }
  return out.str();
}

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

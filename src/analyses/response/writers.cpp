// The steady-state response's writers: its JSON, CSV and terminal report
// (analyses/response/analysis.hpp), in the writers' shared vocabulary (result_text.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/text.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace {

Real degrees(Complex c) { return std::arg(c) * 180.0 / pi; }

// Amplitude and phase per point of the DOFs whose mask is set, keyed by DOF name.
Json dof_series(const std::vector<NodeAmplitudes>& values, const std::array<bool, dofs_per_node>& mask,
                const char* const names[dofs_per_node]) {
  Json out = Json::object();
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

// Per probe: its orbit per point and the amplitude and phase of each DOF.
Json probes_json(const HarmonicResult& result, const Model& model) {
  Json probes = Json::array();
  for (const ProbeResponse& p : result.probes) {
    Json jp = node_json(model, p.node);
    std::vector<Real> major, minor, incl, phase;
    Json whirl = Json::array();
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
  return probes;
}

// Per spring–damper: the force it transmits per point.
Json springs_json(const HarmonicResult& result, const Model& model) {
  Json springs = Json::array();
  for (const SpringForceResponse& s : result.springs) {
    const Transmission link = *model.elements[static_cast<std::size_t>(s.element)].transmission(0.0);
    Json js = {{"label", element_label(model, s.element)},
               {"node", model.nodes[static_cast<std::size_t>(link.node_a)].number},
               {"peak_lateral_force_n", numbers(s.peak_lateral)},
               {"force", dof_series(s.force, all_dofs, direction_names)}};
    js["to"] = link.node_b ? Json(model.nodes[static_cast<std::size_t>(*link.node_b)].number) : Json("ground");
    springs.push_back(js);
  }
  return springs;
}

// Per bearing: the force it transmits, its orbit and its operating state per point.
Json supports_json(const HarmonicResult& result, const Model& model) {
  Json supports = Json::array();
  const Json operating = detail::operating_json(result.operating, model);
  for (const SupportForceResponse& s : result.supports) {
    const std::vector<Index> at = model.forces[static_cast<std::size_t>(s.force)].nodes();
    Json js = {{"label", force_label(model, s.force)},
               {"node", model.nodes[static_cast<std::size_t>(at.front())].number},
               {"peak_lateral_force_n", numbers(s.peak_lateral)},
               {"force", dof_series(s.amplitude, lateral_dofs, direction_names)},
               {"orbit_m", numbers(s.orbit)},
               {"orbit_clearance_ratio", numbers(s.orbit_clearance_ratio)}};
    js["to"] = at.size() > 1 ? Json(model.nodes[static_cast<std::size_t>(at[1])].number) : Json("ground");
    Real largest = -1;
    for (const Real r : s.orbit_clearance_ratio)
      if (r > largest) largest = r;
    js["largest_orbit_clearance_ratio"] = largest >= 0 ? Json(largest) : Json(nullptr);
    if (supports.size() < operating.size()) js["operating"] = operating[supports.size()]["operating"];
    supports.push_back(js);
  }
  return supports;
}

// Per node with fixed DOFs: the force on the support per point.
Json reactions_json(const HarmonicResult& result, const Model& model) {
  Json reactions = Json::array();
  for (const ReactionResponse& r : result.reactions) {
    Json jr = node_json(model, r.node);
    jr["peak_lateral_force_n"] = numbers(r.peak_lateral);
    jr["force"] = dof_series(r.force, r.fixed, direction_names);
    reactions.push_back(jr);
  }
  return reactions;
}

// Per shaft station (StationOutput::all): its section forces and stresses per point.
Json stations_json(const HarmonicResult& result, const Model& model) {
  Json stations = Json::array();
  for (const StationResponse& st : result.stations) {
    Json js = station_json(model, st.station);
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
  return stations;
}

// Per point, the largest value over the stations and where it is (null without stations).
Json station_peaks_json(const HarmonicResult& result, const Model& model) {
  if (result.shaft_stations.empty()) return nullptr;
  auto peaks = [&](const char* unit, auto member) {
    std::vector<Real> value, x;
    Json element = Json::array(), end = Json::array(), node = Json::array();
    for (const StationPeaks& p : result.station_peaks) {
      const StationPeak& peak = p.*member;
      const ShaftStation& st = result.shaft_stations[static_cast<std::size_t>(peak.station)];
      value.push_back(peak.value);
      x.push_back(st.x);
      element.push_back(element_label(model, st.element));
      end.push_back(st.end == 0 ? "start" : "end");
      node.push_back(model.nodes[static_cast<std::size_t>(st.node)].number);
    }
    return Json{{unit, numbers(value)}, {"x_m", numbers(x)}, {"element", element}, {"end", end}, {"node", node}};
  };
  return {{"von_mises", peaks("value_pa", &StationPeaks::von_mises)},
          {"bending_moment", peaks("value_nm", &StationPeaks::bending_moment)},
          {"shear_force", peaks("value_n", &StationPeaks::shear_force)}};
}

// The largest values of the sweep and where they are.
Json summary_json(const HarmonicResult& result, const Model& model) {
  const ResponseSummary sum = summarize(result);
  auto at = [&](Index k) {
    return Json{{"speed_hz", rad_to_hz(result.speeds[static_cast<std::size_t>(k)])},
                {"frequency_hz", rad_to_hz(result.frequencies[static_cast<std::size_t>(k)])}};
  };
  Json summary;
  Json peaks = Json::array();
  for (std::size_t p = 0; p < sum.probe_peaks.size(); ++p) {
    if (sum.probe_peaks[p].point < 0) continue;
    Json jp = node_json(model, result.probes[p].node);
    jp["peak_amplitude_m"] = sum.probe_peaks[p].value;
    jp.update(at(sum.probe_peaks[p].point));
    peaks.push_back(jp);
  }
  summary["probes"] = peaks;
  summary["largest_spring_force"] = nullptr;
  if (sum.spring_force.point >= 0) {
    Json js = {{"label", element_label(model, result.springs[static_cast<std::size_t>(sum.spring_force.item)].element)},
               {"peak_lateral_force_n", sum.spring_force.value}};
    js.update(at(sum.spring_force.point));
    summary["largest_spring_force"] = js;
  }
  summary["largest_bearing_force"] = nullptr;
  if (sum.support_force.point >= 0) {
    Json js = {{"label", force_label(model, result.supports[static_cast<std::size_t>(sum.support_force.item)].force)},
               {"peak_lateral_force_n", sum.support_force.value}};
    js.update(at(sum.support_force.point));
    summary["largest_bearing_force"] = js;
  }
  summary["largest_reaction"] = nullptr;
  if (sum.reaction_force.point >= 0) {
    Json jr = node_json(model, result.reactions[static_cast<std::size_t>(sum.reaction_force.item)].node);
    jr["peak_lateral_force_n"] = sum.reaction_force.value;
    jr.update(at(sum.reaction_force.point));
    summary["largest_reaction"] = jr;
  }
  summary["largest_stress"] = nullptr;
  if (sum.stress.point >= 0) {
    Json js = station_json(model, result.shaft_stations[static_cast<std::size_t>(sum.stress.item)]);
    js["von_mises_pa"] = sum.stress.value;
    js.update(at(sum.stress.point));
    summary["largest_stress"] = js;
  }
  return summary;
}

// A steady-state result's stability (modal/stability.hpp), in a few lines: nothing
// when stable everywhere; else where it is unstable and what that means.
std::string stability_text(const HarmonicResult& result, const std::string& unit) {
  const Index first = first_unstable_point(result);
  std::string out;
  Index unknown = 0;
  for (const StabilityPoint& p : result.stability) unknown += p.known ? 0 : 1;
  if (first >= 0) {
    const StabilityPoint& p = result.stability[static_cast<std::size_t>(first)];
    out += fmt::format(
        "WARNING: the rotor is UNSTABLE at {} of {} points, from {}: {}.\n"
        "         There the response is no steady state the rotor reaches: any disturbance grows.\n\n",
        unstable_points(result), result.stability.size(), speed_text(p.speed, unit),
        p.divergence
            ? fmt::format("divergence, a real eigenvalue {:.4g} 1/s", p.growth_rate)
            : fmt::format("a mode at {} grows at {:.4g} 1/s", frequency_text(p.frequency_hz, unit), p.growth_rate));
  }
  if (unknown > 0)
    out += fmt::format("note: the stability is unknown at {} of {} points\n\n", unknown, result.stability.size());
  return out;
}

std::string point_text(const HarmonicResult& r, Index k, const std::string& unit) {
  const auto i = static_cast<std::size_t>(k);
  if (r.frequency_sweep) return frequency_text(rad_to_hz(r.frequencies[i]), unit) + " excitation";
  return speed_text(r.speeds[i], unit);
}

}  // namespace

std::string ResponseAnalysis::json(const Outcome<ResponseAnalysis>& o) {
  const HarmonicResult& result = o.result;
  const HarmonicOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  Json j = header("response", source);
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

  j["probes"] = probes_json(result, model);
  j["springs"] = springs_json(result, model);
  j["supports"] = supports_json(result, model);
  j["reactions"] = reactions_json(result, model);
  j["stations"] = stations_json(result, model);
  j["stations_output"] = to_string(options.stations);
  j["station_peaks"] = station_peaks_json(result, model);
  j["summary"] = summary_json(result, model);
  return json_text(j, 2);
}

std::string ResponseAnalysis::csv(const Outcome<ResponseAnalysis>& o) {
  const HarmonicResult& result = o.result;
  const Model& model = o.model();
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

namespace {

// The sweep in one line: its points, what excites the rotor.
std::string sweep_line(const HarmonicResult& result, const HarmonicOptions& options, const Model& model,
                       const std::string& unit) {
  const std::size_t n = result.speeds.size();
  std::string out;
  if (result.frequency_sweep)
    out += fmt::format("frequency sweep {:.4g} to {} ({} points) at rotor speed {}",
                       frequency_value(rad_to_hz(result.frequencies.front()), unit),
                       frequency_text(rad_to_hz(result.frequencies.back()), unit), n, speed_text(options.speed, unit));
  else if (n == 1)
    out += fmt::format("at speed {}, synchronous excitation", speed_text(result.speeds.front(), unit));
  else
    out += fmt::format("speed sweep {} to {} ({} points), synchronous excitation",
                       speed_text(result.speeds.front(), unit), speed_text(result.speeds.back(), unit), n);
  out += fmt::format(", {} unbalance(s), {} force(s), loss factor {}\n\n",
                     (!result.frequency_sweep && options.unbalance) ? model.count_forces(is_unbalance) : std::size_t{0},
                     model.count_forces(is_harmonic_force) + options.extra_forces.size(), options.loss_factor);
  return out;
}

// The probes' orbit sizes and phases at (at most) 11 points spread over the sweep.
std::string orbit_table(const HarmonicResult& result, const Model& model, const std::string& unit) {
  const std::size_t n = result.speeds.size();
  const std::size_t rows = std::min<std::size_t>(n, 11);
  std::string out = "Orbit size (major semi-axis, = largest |r|) [mm] and phase of v [deg]\n";
  out += fmt::format("{:>12}",
                     result.frequency_sweep ? fmt::format("freq. [{}]", frequency_unit(unit)) : speed_header(unit));
  for (const ProbeResponse& p : result.probes) out += fmt::format(" {:>14} {:>7}", node_name(model, p.node), "phase");
  if (unstable_points(result) > 0) out += "  rotor";
  out += '\n';
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t k = rows == 1 ? 0 : r * (n - 1) / (rows - 1);
    out += result.frequency_sweep
               ? cell(frequency_value(rad_to_hz(result.frequencies[k]), unit), unit == "rpm" ? ".1f" : ".2f", 12, 2)
           : unit == "rpm" ? cell(speed_value(result.speeds[k], "rpm"), ".1f", 12, 1)
                           : cell(rad_to_hz(result.speeds[k]), ".2f", 12, 2);
    for (const ProbeResponse& p : result.probes) {
      out += ' ';
      out += cell(1e3 * p.orbit[k].major, ".5f", 14, 5);
      out += ' ';
      out += cell(std::arg(p.q[k][static_cast<std::size_t>(Dof::v)]) * 180 / pi, ".1f", 7, 1);
    }
    if (unstable_points(result) > 0 && result.stability[k].unstable) out += "  UNSTABLE";
    out += '\n';
  }
  return out + '\n';
}

// The largest orbit, forces and stress of the sweep, and where each is.
std::string peaks_text(const HarmonicResult& result, const Model& model, const std::string& unit) {
  const ResponseSummary sum = summarize(result);
  std::string out = "Peaks:\n";
  for (std::size_t p = 0; p < sum.probe_peaks.size(); ++p)
    if (sum.probe_peaks[p].point >= 0)
      out += fmt::format("  orbit at node {:<18} {:.5g} mm at {}\n", node_name(model, result.probes[p].node),
                         1e3 * sum.probe_peaks[p].value, point_text(result, sum.probe_peaks[p].point, unit));
  if (sum.spring_force.point >= 0)
    out += fmt::format("  largest spring-damper force: {} {:.5g} N at {}\n",
                       element_name(model, result.springs[static_cast<std::size_t>(sum.spring_force.item)].element),
                       sum.spring_force.value, point_text(result, sum.spring_force.point, unit));
  if (sum.support_force.point >= 0)
    out += fmt::format("  largest bearing force: {} {:.5g} N at {}\n",
                       force_name(model, result.supports[static_cast<std::size_t>(sum.support_force.item)].force),
                       sum.support_force.value, point_text(result, sum.support_force.point, unit));
  if (sum.reaction_force.point >= 0)
    out += fmt::format("  largest support force: node {} {:.5g} N at {}\n",
                       node_name(model, result.reactions[static_cast<std::size_t>(sum.reaction_force.item)].node),
                       sum.reaction_force.value, point_text(result, sum.reaction_force.point, unit));
  if (sum.stress.point >= 0) {
    const ShaftStation& st = result.shaft_stations[static_cast<std::size_t>(sum.stress.item)];
    out += fmt::format("  largest equivalent stress: {:.5g} MPa at x = {:.4g} mm ({} {}), at {}\n",
                       1e-6 * sum.stress.value, 1e3 * st.x, element_name(model, st.element),
                       st.end == 0 ? "start" : "end", point_text(result, sum.stress.point, unit));
  }
  for (const SupportForceResponse& sr : result.supports) {
    std::size_t at = sr.orbit_clearance_ratio.size();
    for (std::size_t k = 0; k < sr.orbit_clearance_ratio.size(); ++k)
      if (std::isfinite(sr.orbit_clearance_ratio[k]) &&
          (at == sr.orbit_clearance_ratio.size() || sr.orbit_clearance_ratio[k] > sr.orbit_clearance_ratio[at]))
        at = k;
    if (at < sr.orbit_clearance_ratio.size())
      out += fmt::format("  largest journal orbit in {}: {:.4g} x its clearance ({:.4g} um) at {}\n",
                         force_name(model, sr.force), sr.orbit_clearance_ratio[at], 1e6 * sr.orbit[at],
                         point_text(result, static_cast<Index>(at), unit));
  }
  return out;
}

}  // namespace

std::string ResponseAnalysis::terminal(const Outcome<ResponseAnalysis>& o) {
  const HarmonicResult& result = o.result;
  const Model& model = o.model();
  const std::string& unit = o.source.speed_unit;
  std::string out = source_line("response", o.source);
  if (result.speeds.empty()) return out + "no point could be solved\n";
  out += sweep_line(result, o.options, model, unit);
  if (!result.probes.empty()) out += orbit_table(result, model, unit);
  out += stability_text(result, unit);
  out += peaks_text(result, model, unit);
  if (result.frequency_sweep) {
    out += operating_at_one_speed(result.operating, model);
  } else {
    out += operating_tables(result.operating, model, "at the equilibrium", speed_header(unit),
                            [&](std::size_t k) { return speed_number(result.speeds[k], unit); });
  }
  if (!result.info.converged()) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

}  // namespace feran

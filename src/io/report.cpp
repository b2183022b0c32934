#include <feran/io/report.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/text.hpp>

#include "result_text.hpp"

namespace feran {

namespace {

using namespace detail;  // NOLINT(google-build-using-namespace): the reports' shared vocabulary (result_text.hpp)

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

std::string response_report(const HarmonicResult& result, const HarmonicOptions& options, const Model& model,
                            const ResultSource& source) {
  std::string out = source_line("response", source);
  const std::size_t n = result.speeds.size();
  if (n == 0) return out + "no point could be solved\n";
  if (result.frequency_sweep)
    out += fmt::format("frequency sweep {:.4g} to {} ({} points) at rotor speed {}",
                       frequency_value(rad_to_hz(result.frequencies.front()), source.speed_unit),
                       frequency_text(rad_to_hz(result.frequencies.back()), source.speed_unit), n,
                       speed_text(options.speed, source.speed_unit));
  else if (n == 1)
    out += fmt::format("at speed {}, synchronous excitation", speed_text(result.speeds.front(), source.speed_unit));
  else
    out += fmt::format("speed sweep {} to {} ({} points), synchronous excitation",
                       speed_text(result.speeds.front(), source.speed_unit),
                       speed_text(result.speeds.back(), source.speed_unit), n);
  out += fmt::format(", {} unbalance(s), {} force(s), loss factor {}\n\n",
                     (!result.frequency_sweep && options.unbalance) ? model.count_forces(is_unbalance) : std::size_t{0},
                     model.count_forces(is_harmonic_force) + options.extra_forces.size(), options.loss_factor);

  if (!result.probes.empty()) {
    const std::size_t rows = std::min<std::size_t>(n, 11);
    out += "Orbit size (major semi-axis, = largest |r|) [mm] and phase of v [deg]\n";
    out += fmt::format("{:>12}", result.frequency_sweep ? fmt::format("freq. [{}]", frequency_unit(source.speed_unit))
                                                        : speed_header(source.speed_unit));
    for (const ProbeResponse& p : result.probes) out += fmt::format(" {:>14} {:>7}", node_name(model, p.node), "phase");
    if (unstable_points(result) > 0) out += "  rotor";
    out += '\n';
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t k = rows == 1 ? 0 : r * (n - 1) / (rows - 1);
      out += result.frequency_sweep       ? cell(frequency_value(rad_to_hz(result.frequencies[k]), source.speed_unit),
                                           source.speed_unit == "rpm" ? ".1f" : ".2f", 12, 2)
             : source.speed_unit == "rpm" ? cell(speed_value(result.speeds[k], "rpm"), ".1f", 12, 1)
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
    out += '\n';
  }

  out += stability_text(result, source.speed_unit);
  const ResponseSummary sum = summarize(result);
  out += "Peaks:\n";
  for (std::size_t p = 0; p < sum.probe_peaks.size(); ++p)
    if (sum.probe_peaks[p].point >= 0)
      out +=
          fmt::format("  orbit at node {:<18} {:.5g} mm at {}\n", node_name(model, result.probes[p].node),
                      1e3 * sum.probe_peaks[p].value, point_text(result, sum.probe_peaks[p].point, source.speed_unit));
  if (sum.spring_force.point >= 0)
    out += fmt::format("  largest spring-damper force: {} {:.5g} N at {}\n",
                       element_name(model, result.springs[static_cast<std::size_t>(sum.spring_force.item)].element),
                       sum.spring_force.value, point_text(result, sum.spring_force.point, source.speed_unit));
  if (sum.support_force.point >= 0)
    out += fmt::format("  largest bearing force: {} {:.5g} N at {}\n",
                       force_name(model, result.supports[static_cast<std::size_t>(sum.support_force.item)].force),
                       sum.support_force.value, point_text(result, sum.support_force.point, source.speed_unit));
  if (sum.reaction_force.point >= 0)
    out += fmt::format("  largest support force: node {} {:.5g} N at {}\n",
                       node_name(model, result.reactions[static_cast<std::size_t>(sum.reaction_force.item)].node),
                       sum.reaction_force.value, point_text(result, sum.reaction_force.point, source.speed_unit));
  if (sum.stress.point >= 0) {
    const ShaftStation& st = result.shaft_stations[static_cast<std::size_t>(sum.stress.item)];
    out += fmt::format("  largest equivalent stress: {:.5g} MPa at x = {:.4g} mm ({} {}), at {}\n",
                       1e-6 * sum.stress.value, 1e3 * st.x, element_name(model, st.element),
                       st.end == 0 ? "start" : "end", point_text(result, sum.stress.point, source.speed_unit));
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
                         point_text(result, static_cast<Index>(at), source.speed_unit));
  }
  if (result.frequency_sweep) {
    out += operating_at_one_speed(result.operating, model);
  } else {
    out += operating_tables(result.operating, model, "at the equilibrium", speed_header(source.speed_unit),
                            [&](std::size_t k) { return speed_number(result.speeds[k], source.speed_unit); });
  }
  if (!result.info.converged()) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

std::string runup_report(const TransientResult& result, const TransientOptions& options, const Model& model,
                         const ResultSource& source, double wall_seconds) {
  std::string out = source_line("runup", source);
  const auto number = [&](Real speed) {  // in the chosen unit, without it
    return source.speed_unit == "rpm" ? fmt::format("{:.0f}", speed_value(speed, "rpm"))
                                      : fmt::format("{:.4g}", rad_to_hz(speed));
  };
  out += fmt::format(
      "{} from {:.4g} to {:.4g} s, speed {} -> {} {}{}; {} steps ({} rejected), {} "
      "factorizations, {} Newton iterations",
      options.integrator, 0.0, result.t_end, number(options.profile.speed(0.0)), number(result.speed_end),
      source.speed_unit == "rpm" ? "rpm" : "Hz", options.driven ? " (torque-driven)" : "", result.steps,
      result.rejected, result.factorizations, result.newton_iterations);
  out += wall_seconds >= 0 ? fmt::format("; {:.3g} s wall\n", wall_seconds) : std::string("\n");
  if (result.basis_size > 0)
    out += fmt::format("modal reduction: {} modes at {} speeds, a basis of {} vectors\n", options.reduced_modes,
                       modal_basis_speeds, result.basis_size);
  for (std::size_t p = 0; p < options.probes.size() && p < result.envelopes.size(); ++p) {
    const Envelope& e = result.envelopes[p];
    out += fmt::format("  node {:<16} peak |r| = {:.5g} mm at t = {:.4g} s, speed {}\n",
                       printable(model.node_label(options.probes[p])), 1e3 * e.peak, e.peak_time,
                       speed_short(e.peak_speed, source.speed_unit));
  }
  for (const ClearanceUse& u : result.clearance_use)
    out += fmt::format("  {:<21} largest journal excursion {:.4g} x its clearance at t = {:.4g} s, speed {}\n",
                       force_name(model, u.force), u.largest, u.time, speed_short(u.speed, source.speed_unit));
  if (!result.samples.empty())
    out += operating_tables(result.operating, model, "in the motion", "time [s]",
                            [&](std::size_t k) { return fmt::format("{:.4g}", result.samples[k].t); });
  if (!result.warning.empty()) out += "warning: " + printable(result.warning, true) + "\n";
  return out;
}

std::string parameters_report(const std::vector<Parameter>& parameters, const ResultSource& source) {
  std::size_t path_width = 4, value_width = 5;
  for (const Parameter& p : parameters) {
    path_width = std::max(path_width, printable(p.path).size());
    value_width = std::max(value_width, printable(p.text()).size());
  }
  std::string out = fmt::format("{} settable parameters of {}\n", parameters.size(), printable(source.model_path));
  out += "(set one with --set 'PATH=VALUE' on any analysis, the value with its unit)\n\n";
  out += fmt::format("{:<{}}  {:<{}}  {}\n", "path", path_width, "value", value_width, "meaning");
  for (const Parameter& p : parameters)
    out += fmt::format("{:<{}}  {:<{}}  {}\n", printable(p.path), path_width, printable(p.text()), value_width, p.doc);
  return out;
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

std::string api684_report(const Api684Result& result, const Model& model, const ResultSource& source) {
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

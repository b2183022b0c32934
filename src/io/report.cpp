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

}  // namespace

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

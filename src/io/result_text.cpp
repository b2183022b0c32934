// What every analysis's writers share (result_text.hpp).
#include "result_text.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/text.hpp>

namespace feran::detail {

using nlohmann::json;

json numbers(const std::vector<Real>& xs) {
  json a = json::array();
  for (Real x : xs) a.push_back(json_number(x));
  return a;
}

json solver_json(const SolverInfo& info) {
  return {{"method", to_string(info.method)}, {"converged", info.converged()}, {"status", to_string(info.status)},
          {"n_converged", info.n_converged},  {"iterations", info.iterations}, {"message", info.message}};
}

json header(const std::string& analysis, const ResultSource& source) {
  return {{"program", "feran"},
          {"format_version", 1},
          {"analysis", analysis},
          {"model", {{"path", source.model_path}, {"title", source.title}}},
          {"warnings", source.warnings}};
}

json node_json(const Model& model, Index node) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return {{"node", n.number}, {"name", n.name}, {"x_m", n.x}};
}

std::string element_label(const Model& model, Index element) { return linearised_element_name(model, element); }

json stability_point_json(const StabilityPoint& p) {
  return {{"kind", stability_kind(p)},
          {"unstable", p.known ? json(p.unstable) : json(nullptr)},
          {"growth_rate_per_s", detail::json_number(p.growth_rate)},
          {"unstable_mode_frequency_hz", p.unstable && !p.divergence ? json(p.frequency_hz) : json(nullptr)},
          {"by_energy", p.by_energy},
          {"message", stability_phrase(p)}};
}

json point_stability_json(const std::vector<StabilityPoint>& points) {
  if (points.empty()) return nullptr;
  json unstable = json::array(), growth = json::array(), frequency = json::array(), kind = json::array();
  Index first = -1, count = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const StabilityPoint& p = points[k];
    unstable.push_back(p.known ? json(p.unstable) : json(nullptr));
    growth.push_back(json_number(p.growth_rate));
    frequency.push_back(p.unstable ? json_number(p.frequency_hz) : json(nullptr));
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

json station_json(const Model& model, const ShaftStation& st) {
  json j = node_json(model, st.node);
  j["element"] = element_label(model, st.element);
  j["end"] = st.end == 0 ? "start" : "end";
  return j;
}

std::string source_line(const char* analysis, const ResultSource& source) {
  if (source.title.empty()) return fmt::format("feran {}: {}\n", analysis, printable(source.model_path));
  return fmt::format("feran {}: {} ({})\n", analysis, printable(source.title), printable(source.model_path));
}

// A speed in the unit the user chose ("Hz" or "rpm"), the other in parentheses.
std::string speed_text(Real speed, const std::string& unit) {
  if (unit == "rpm") return fmt::format("{:.6g} rpm ({:.4g} Hz)", rad_to_hz(speed) * 60.0, rad_to_hz(speed));
  return fmt::format("{:.4g} Hz ({:.6g} rpm)", rad_to_hz(speed), rad_to_hz(speed) * 60.0);
}

// A speed column: its header and the value in the chosen unit.
std::string speed_header(const std::string& unit) { return unit == "rpm" ? "speed [rpm]" : "speed [Hz]"; }
Real speed_value(Real speed, const std::string& unit) { return rad_to_hz(speed) * (unit == "rpm" ? 60.0 : 1.0); }

// A speed alone, in the chosen unit ("105.3 Hz", "6318 rpm").
std::string speed_short(Real speed, const std::string& unit) {
  return unit == "rpm" ? fmt::format("{:.0f} rpm", speed_value(speed, unit))
                       : fmt::format("{:.4g} Hz", rad_to_hz(speed));
}

// The same without the unit (under a speed_header()).
std::string speed_number(Real speed, const std::string& unit) {
  return unit == "rpm" ? fmt::format("{:.0f}", speed_value(speed, unit)) : fmt::format("{:.4g}", rad_to_hz(speed));
}

// Frequencies of the motion follow the speed unit, as in the report: Hz with Hz,
// cycles per minute with rpm (a synchronous mode's frequency then reads as its speed).
std::string frequency_unit(const std::string& unit) { return unit == "rpm" ? "cpm" : "Hz"; }
Real frequency_value(Real hz, const std::string& unit) { return hz * (unit == "rpm" ? 60.0 : 1.0); }
std::string frequency_text(Real hz, const std::string& unit) {
  return fmt::format("{:.4g} {}", frequency_value(hz, unit), frequency_unit(unit));
}

// A right-aligned number; "-" when it does not exist. Values that would print as
// "-0.000" print as "0.000".
std::string cell(Real x, const char* format_spec, int width, int decimals) {
  if (!std::isfinite(x)) return fmt::format("{:>{}}", "-", width);
  if (std::abs(x) < 0.5 * std::pow(10.0, -decimals)) x = 0.0;
  return fmt::format(fmt::runtime(fmt::format("{{:>{}{}}}", width, format_spec)), x);
}

std::string node_name(const Model& model, Index node) { return printable(model.node_label(node)); }

std::string element_name(const Model& model, Index element) {
  return printable(linearised_element_name(model, element));
}

std::string operating_block(const std::string& title, const std::string& first, const std::vector<OperatingRow>& rows) {
  struct Column {
    const char* name;
    const char* head;
    Real scale;
    const char* format;
  };
  static const Column columns[] = {{"eccentricity_ratio", "eps [-]", 1, ".4f"},
                                   {"attitude_angle_deg", "attitude [deg]", 1, ".2f"},
                                   {"min_film_thickness_m", "h_min [um]", 1e6, ".3f"},
                                   {"min_film_angle_deg", "at [deg]", 1, ".1f"},
                                   {"specific_load_pa", "W/(LD) [MPa]", 1e-6, ".4g"},
                                   {"sommerfeld_number", "Sommerfeld [-]", 1, ".4g"},
                                   {"friction_torque_nm", "torque [N m]", 1, ".4g"},
                                   {"power_loss_w", "loss [W]", 1, ".4g"},
                                   {"peak_pressure_pa", "p_max [MPa]", 1e-6, ".4g"},
                                   {"max_element_load_n", "Q_max [N]", 1, ".4g"},
                                   {"loaded_elements", "loaded", 1, ".0f"},
                                   {"max_contact_stress_pa", "p_Hertz [MPa]", 1e-6, ".4g"}};
  std::vector<const Column*> used;
  for (const Column& c : columns)
    for (const OperatingRow& r : rows)
      if (std::find(r.names->begin(), r.names->end(), c.name) != r.names->end()) {
        used.push_back(&c);
        break;
      }
  if (used.empty()) return {};
  std::string out = fmt::format("\n{}\n{:>30}", title, first);
  for (const Column* c : used) out += fmt::format(" {:>14}", c->head);
  out += '\n';
  for (const OperatingRow& r : rows) {
    out += fmt::format("{:>30}", r.label);
    for (const Column* c : used) {
      std::string text = "-";
      const auto it = std::find(r.names->begin(), r.names->end(), c->name);
      if (it != r.names->end()) {
        const Real v = (*r.values)[static_cast<std::size_t>(it - r.names->begin())];
        if (std::isfinite(v)) text = fmt::format(fmt::runtime("{:" + std::string(c->format) + "}"), v * c->scale);
      }
      out += fmt::format(" {:>14}", text);
    }
    out += '\n';
  }
  return out;
}

std::string force_name(const Model& model, Index force) {
  const std::string& label = model.forces[static_cast<std::size_t>(force)].label();
  return label.empty() ? fmt::format("force {}", force + 1) : printable(label);
}

// The supports' state at an analysis' one speed (its first point): one row per support.
std::string operating_at_one_speed(const std::vector<OperatingSeries>& series, const Model& model) {
  std::vector<OperatingRow> rows;
  for (const OperatingSeries& s : series)
    if (!s.values.empty()) rows.push_back({force_name(model, s.force), &s.quantities, &s.values.front()});
  return operating_block("Bearing operating data at the equilibrium", "", rows);
}

}  // namespace feran::detail

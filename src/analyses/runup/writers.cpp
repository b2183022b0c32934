// The run-up's writers: its CSV (header and rows, streamed or from the kept samples),
// JSON and terminal report (analyses/runup/analysis.hpp), in the writers' shared
// vocabulary (result_text.hpp).
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/transient/modal_basis.hpp>
#include <feran/core/text.hpp>

#include "../../io/csv_text.hpp"
#include "../../io/json_text.hpp"
#include "../../io/operating_text.hpp"
#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

std::string runup_csv_header(const Model& model, const TransientOptions& options) {
  std::string header = "time_s,speed_hz";
  for (Index node : options.probes) {
    const std::string t = csv_node_tag(model, node);
    header += ',' + csv_column(t, "_magnitude_m");
    for (const char* d : dof_names) header += ',' + csv_column(t, std::string("_") + d);
  }
  for (Index e : options.springs)
    for (const char* d : direction_names) header += ',' + csv_column(csv_element_tag(model, e), std::string("_f") + d);
  header += operating_csv_header(operating_series(model), model);
  header += '\n';
  return header;
}

std::string runup_csv_row(const TransientSample& s) {
  std::string row = csv_number(s.t);
  row += ',';
  row += csv_number(rad_to_hz(s.speed));
  for (std::size_t p = 0; p < s.probes.size(); ++p) {
    row += ',';
    row += csv_number(s.magnitude[p]);
    for (Real q : s.probes[p]) {
      row += ',';
      row += csv_number(q);
    }
  }
  for (const auto& f : s.springs)
    for (Real c : f) {
      row += ',';
      row += csv_number(c);
    }
  std::vector<const std::vector<Real>*> rows;
  for (const std::vector<Real>& r : s.operating) rows.push_back(&r);
  append_operating_csv(row, rows);
  row += '\n';
  return row;
}

std::string RunupAnalysis::csv(const Outcome<RunupAnalysis>& o) {
  std::string out = runup_csv_header(o.model(), o.options);
  for (const TransientSample& s : o.result.samples) out += runup_csv_row(s);
  return out;
}

namespace {

// Per probe: its motion at every sample, its |r| envelope over speed and its peak.
Json probes_json(const TransientResult& result, const TransientOptions& options, const Model& model) {
  Json probes = Json::array();
  for (std::size_t p = 0; p < options.probes.size(); ++p) {
    const Node& n = model.nodes[static_cast<std::size_t>(options.probes[p])];
    Json jp = {{"node", n.number}, {"name", n.name}, {"x_m", n.x}};
    Json mag = Json::array();
    Json dofs = Json::object();
    for (const char* d : dof_names) dofs[d] = Json::array();
    for (const TransientSample& s : result.samples) {
      mag.push_back(detail::json_number(s.magnitude[p]));
      for (int d = 0; d < dofs_per_node; ++d)
        dofs[dof_names[d]].push_back(detail::json_number(s.probes[p][static_cast<std::size_t>(d)]));
    }
    jp["magnitude_m"] = mag;
    jp["dofs"] = dofs;
    const Envelope& e = result.envelopes[p];
    Json es = Json::array(), em = Json::array();
    for (std::size_t b = 0; b < e.speed.size(); ++b) {
      es.push_back(rad_to_hz(e.speed[b]));
      em.push_back(detail::json_number(e.magnitude[b]));
    }
    jp["envelope"] = {{"speed_hz", es}, {"magnitude_m", em}};
    jp["peak"] = {{"magnitude_m", e.peak}, {"time_s", e.peak_time}, {"speed_hz", rad_to_hz(e.peak_speed)}};
    probes.push_back(jp);
  }
  return probes;
}

// Per recorded spring: its force at every sample.
Json springs_json(const TransientResult& result, const TransientOptions& options, const Model& model) {
  Json springs = Json::array();
  for (std::size_t k = 0; k < options.springs.size(); ++k) {
    Json js = {{"label", model.elements[static_cast<std::size_t>(options.springs[k])].label()}};
    Json force = Json::object();
    for (int d = 0; d < dofs_per_node; ++d) {
      Json series = Json::array();
      for (const TransientSample& s : result.samples)
        series.push_back(detail::json_number(s.springs[k][static_cast<std::size_t>(d)]));
      force[direction_names[d]] = series;
    }
    js["force_n"] = force;
    springs.push_back(js);
  }
  return springs;
}

// The supports' state at the output times, and their largest excursion at any step.
Json supports_json(const TransientResult& result, const Model& model) {
  Json supports = detail::operating_json(result.operating, model);
  for (Json& js : supports) {
    js["largest_clearance_ratio"] = nullptr;
    js["largest_clearance_ratio_time_s"] = nullptr;
    js["largest_clearance_ratio_speed_hz"] = nullptr;
  }
  for (const ClearanceUse& u : result.clearance_use)
    for (std::size_t k = 0; k < result.operating.size(); ++k)
      if (result.operating[k].force == u.force) {
        supports[k]["clearance_m"] = u.clearance;
        supports[k]["largest_clearance_ratio"] = u.largest;
        supports[k]["largest_clearance_ratio_time_s"] = u.time;
        supports[k]["largest_clearance_ratio_speed_hz"] = rad_to_hz(u.speed);
      }
  return supports;
}

}  // namespace

std::string RunupAnalysis::json(const Outcome<RunupAnalysis>& o) {
  const TransientResult& result = o.result;
  const TransientOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  Json j = {{"program", "feran"},
            {"format_version", 1},
            {"analysis", "runup"},
            {"model", {{"path", source.model_path}, {"title", source.title}}},
            {"warnings", source.warnings}};
  j["integrator"] = options.integrator;
  j["complete"] = result.info.converged();
  j["message"] = result.info.message;
  j["warning"] = result.warning;
  j["duration_s"] = options.duration;
  j["t_end_s"] = result.t_end;
  j["statistics"] = {{"steps", result.steps},
                     {"rejected_steps", result.rejected},
                     {"factorizations", result.factorizations},
                     {"newton_iterations", result.newton_iterations},
                     {"modal_basis", result.basis_size}};
  Json profile = Json::array();
  for (const auto& [t, w] : options.profile.points()) profile.push_back({{"time_s", t}, {"speed_hz", rad_to_hz(w)}});
  j["profile"] = profile;
  j["driven"] = options.driven;
  Json time = Json::array(), speed = Json::array();
  for (const TransientSample& s : result.samples) {
    time.push_back(s.t);
    speed.push_back(rad_to_hz(s.speed));
  }
  j["time_s"] = time;
  j["speed_hz"] = speed;
  j["probes"] = probes_json(result, options, model);
  j["springs"] = springs_json(result, options, model);
  j["supports"] = supports_json(result, model);
  return json_text(j, 1);
}

std::string RunupAnalysis::terminal(const Outcome<RunupAnalysis>& o) {
  const TransientResult& result = o.result;
  const TransientOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  const double wall_seconds = result.wall_seconds;
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

}  // namespace feran

#include <feran/io/runup_writer.hpp>

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "csv_text.hpp"
#include "json_text.hpp"
#include "operating_text.hpp"

#include <feran/core/error.hpp>

namespace feran {

namespace {

using detail::csv_number;
using detail::direction_names;
using detail::dof_names;
using nlohmann::json;

}  // namespace

RunupCsvWriter::RunupCsvWriter(OutputFiles& files, int output, const Model& model, const TransientOptions& options)
    : files_(files), output_(output) {
  std::string header = "time_s,speed_hz";
  for (Index node : options.probes) {
    const std::string t = detail::csv_node_tag(model, node);
    header += ',' + detail::csv_column(t, "_magnitude_m");
    for (const char* d : dof_names) header += ',' + detail::csv_column(t, std::string("_") + d);
  }
  for (Index e : options.springs)
    for (const char* d : direction_names)
      header += ',' + detail::csv_column(detail::csv_element_tag(model, e), std::string("_f") + d);
  header += detail::operating_csv_header(operating_series(model), model);
  header += '\n';
  files_.append(output_, header);
}

void RunupCsvWriter::write(const TransientSample& s) {
  row_ = csv_number(s.t);
  row_ += ',';
  row_ += csv_number(rad_to_hz(s.speed));
  for (std::size_t p = 0; p < s.probes.size(); ++p) {
    row_ += ',';
    row_ += csv_number(s.magnitude[p]);
    for (Real q : s.probes[p]) {
      row_ += ',';
      row_ += csv_number(q);
    }
  }
  for (const auto& f : s.springs)
    for (Real c : f) {
      row_ += ',';
      row_ += csv_number(c);
    }
  std::vector<const std::vector<Real>*> rows;
  for (const std::vector<Real>& r : s.operating) rows.push_back(&r);
  detail::append_operating_csv(row_, rows);
  row_ += '\n';
  files_.append(output_, row_);
}

std::string runup_json(const TransientResult& result, const TransientOptions& options, const Model& model,
                       const ResultSource& source) {
  json j = {{"program", "feran"},
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
  json profile = json::array();
  for (const auto& [t, w] : options.profile.points()) profile.push_back({{"time_s", t}, {"speed_hz", rad_to_hz(w)}});
  j["profile"] = profile;
  j["driven"] = options.driven;
  json time = json::array(), speed = json::array();
  for (const TransientSample& s : result.samples) {
    time.push_back(s.t);
    speed.push_back(rad_to_hz(s.speed));
  }
  j["time_s"] = time;
  j["speed_hz"] = speed;
  json probes = json::array();
  for (std::size_t p = 0; p < options.probes.size(); ++p) {
    const Node& n = model.nodes[static_cast<std::size_t>(options.probes[p])];
    json jp = {{"node", n.number}, {"name", n.name}, {"x_m", n.x}};
    json mag = json::array();
    json dofs = json::object();
    for (const char* d : dof_names) dofs[d] = json::array();
    for (const TransientSample& s : result.samples) {
      mag.push_back(detail::json_number(s.magnitude[p]));
      for (int d = 0; d < dofs_per_node; ++d)
        dofs[dof_names[d]].push_back(detail::json_number(s.probes[p][static_cast<std::size_t>(d)]));
    }
    jp["magnitude_m"] = mag;
    jp["dofs"] = dofs;
    const Envelope& e = result.envelopes[p];
    json es = json::array(), em = json::array();
    for (std::size_t b = 0; b < e.speed.size(); ++b) {
      es.push_back(rad_to_hz(e.speed[b]));
      em.push_back(detail::json_number(e.magnitude[b]));
    }
    jp["envelope"] = {{"speed_hz", es}, {"magnitude_m", em}};
    jp["peak"] = {{"magnitude_m", e.peak}, {"time_s", e.peak_time}, {"speed_hz", rad_to_hz(e.peak_speed)}};
    probes.push_back(jp);
  }
  j["probes"] = probes;
  json springs = json::array();
  for (std::size_t k = 0; k < options.springs.size(); ++k) {
    json js = {{"label", model.elements[static_cast<std::size_t>(options.springs[k])].label()}};
    json force = json::object();
    for (int d = 0; d < dofs_per_node; ++d) {
      json series = json::array();
      for (const TransientSample& s : result.samples)
        series.push_back(detail::json_number(s.springs[k][static_cast<std::size_t>(d)]));
      force[direction_names[d]] = series;
    }
    js["force_n"] = force;
    springs.push_back(js);
  }
  j["springs"] = springs;
  // The supports' state at the output times, and their largest excursion at any step.
  json supports = detail::operating_json(result.operating, model);
  for (json& js : supports) {
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
  j["supports"] = supports;
  return detail::json_text(j, 1);
}

}  // namespace feran

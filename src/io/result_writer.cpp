#include <feran/io/result_writer.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/core/error.hpp>

namespace feran {

namespace {

using nlohmann::json;

// NaN and infinities have no JSON spelling: they become null.
json number(Real x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json numbers(const std::vector<Real>& xs) {
  json a = json::array();
  for (Real x : xs) a.push_back(number(x));
  return a;
}

json solver_json(const SolverInfo& info) {
  return {{"method", info.method},
          {"converged", info.converged},
          {"n_converged", info.n_converged},
          {"iterations", info.iterations},
          {"message", info.message}};
}

json header(const std::string& analysis, const ResultSource& source) {
  return {{"program", "feran"},
          {"format_version", 1},
          {"analysis", analysis},
          {"model", {{"path", source.model_path}, {"title", source.title}}}};
}

// CSV field: numbers in full precision, empty for NaN.
std::string csv_number(Real x) { return std::isfinite(x) ? fmt::format("{:.10g}", x) : ""; }

std::string csv_name(std::string label) {
  for (char& c : label)
    if (c == ' ') c = '_';
  return label;
}

}  // namespace

std::string modal_json(const ModalResult& result, const Model& model, const ResultSource& source,
                       bool shapes) {
  json j = header("modal", source);
  j["speed_hz"] = rad_to_hz(result.speed);
  j["speed_rpm"] = rad_to_hz(result.speed) * 60.0;
  j["solver"] = solver_json(result.info);
  if (shapes) {
    json nodes = json::array();
    for (const Node& n : model.nodes)
      nodes.push_back({{"number", n.number}, {"name", n.name}, {"x_m", n.x}, {"rotating", n.rotating}});
    j["nodes"] = nodes;
  }
  json modes = json::array();
  int index = 0;
  for (const Mode& m : result.modes) {
    json jm = {{"index", ++index},
               {"frequency_hz", number(m.frequency_hz)},
               {"damping_ratio", number(m.damping_ratio)},
               {"log_decrement", number(m.log_decrement)},
               {"eigenvalue", {{"real", m.eigenvalue.real()}, {"imag", m.eigenvalue.imag()}}},
               {"whirl", to_string(m.whirl)},
               {"directivity", number(m.directivity)},
               {"type", to_string(m.type)},
               {"rigid_body", m.rigid_body},
               {"oscillatory", m.oscillatory}};
    if (shapes && m.shape.size() > 0) {
      json shape;
      for (int d = 0; d < dofs_per_node; ++d) {
        json re = json::array(), im = json::array();
        for (Index node = 0; node < model.n_nodes(); ++node) {
          const Complex c = m.shape(global_dof(node, static_cast<Dof>(d)));
          re.push_back(c.real());
          im.push_back(c.imag());
        }
        shape[dof_name(static_cast<Dof>(d))] = {{"re", re}, {"im", im}};
      }
      jm["shape"] = shape;
    }
    modes.push_back(jm);
  }
  j["modes"] = modes;
  return j.dump(2) + "\n";
}

std::string modal_csv(const ModalResult& result) {
  std::ostringstream out;
  out << "mode,frequency_hz,damping_ratio,log_decrement,eigenvalue_real,eigenvalue_imag,whirl,"
         "directivity,type,rigid_body\n";
  int index = 0;
  for (const Mode& m : result.modes)
    out << ++index << ',' << csv_number(m.frequency_hz) << ',' << csv_number(m.damping_ratio) << ','
        << csv_number(m.log_decrement) << ',' << csv_number(m.eigenvalue.real()) << ','
        << csv_number(m.eigenvalue.imag()) << ',' << to_string(m.whirl) << ','
        << csv_number(m.directivity) << ',' << to_string(m.type) << ','
        << (m.rigid_body ? "true" : "false") << '\n';
  return out.str();
}

std::string campbell_json(const CampbellResult& result, const CampbellOptions& options,
                          const ResultSource& source) {
  json j = header("campbell", source);
  std::vector<Real> hz;
  for (Real s : result.speeds) hz.push_back(rad_to_hz(s));
  j["complete"] = result.info.converged && result.speeds.size() == options.speeds.size();
  j["speeds_hz"] = numbers(hz);
  j["orders"] = options.orders;
  j["solver"] = solver_json(result.info);
  j["n_solves"] = result.n_solves;
  json modes = json::array();
  for (const TrackedMode& m : result.modes) {
    json whirl_at = json::array();
    for (Whirl w : m.whirl_at) whirl_at.push_back(to_string(w));
    modes.push_back({{"label", m.label},
                     {"whirl", to_string(m.whirl)},
                     {"type", to_string(m.type)},
                     {"frequency_hz", numbers(m.frequency_hz)},
                     {"damping_ratio", numbers(m.damping_ratio)},
                     {"log_decrement", numbers(m.log_decrement)},
                     {"directivity", numbers(m.directivity)},
                     {"whirl_at", whirl_at},
                     {"correlation", numbers(m.correlation)}});
  }
  j["modes"] = modes;
  json critical = json::array();
  for (const CriticalSpeed& c : result.critical_speeds)
    critical.push_back({{"speed_hz", rad_to_hz(c.speed)},
                        {"speed_rpm", rad_to_hz(c.speed) * 60.0},
                        {"mode", result.modes[static_cast<std::size_t>(c.mode)].label},
                        {"order", c.order},
                        {"frequency_hz", c.frequency_hz},
                        {"whirl", to_string(c.whirl)}});
  j["critical_speeds"] = critical;
  if (result.stability_threshold) {
    const StabilityThreshold& t = *result.stability_threshold;
    j["stability_threshold_hz"] = rad_to_hz(t.speed);
    j["stability_threshold"] = {{"speed_hz", rad_to_hz(t.speed)},
                                {"speed_rpm", rad_to_hz(t.speed) * 60.0},
                                {"mode", result.modes[static_cast<std::size_t>(t.mode)].label},
                                {"frequency_hz", t.frequency_hz},
                                {"unstable_at_start", t.unstable_at_start}};
  } else {
    j["stability_threshold_hz"] = nullptr;
    j["stability_threshold"] = nullptr;
  }
  return j.dump(2) + "\n";
}

std::string campbell_csv(const CampbellResult& result) {
  std::ostringstream out;
  out << "speed_hz,speed_rpm";
  for (const TrackedMode& m : result.modes)
    out << ',' << csv_name(m.label) << "_frequency_hz," << csv_name(m.label) << "_damping_ratio";
  out << '\n';
  for (std::size_t i = 0; i < result.speeds.size(); ++i) {
    out << csv_number(rad_to_hz(result.speeds[i])) << ',' << csv_number(rad_to_hz(result.speeds[i]) * 60);
    for (const TrackedMode& m : result.modes)
      out << ',' << csv_number(m.frequency_hz[i]) << ',' << csv_number(m.damping_ratio[i]);
    out << '\n';
  }
  return out.str();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string temp = path + ".part";
  {
    std::ofstream f(temp, std::ios::binary | std::ios::trunc);
    if (!f) throw Error(fmt::format("cannot write '{}'", path));
    f << content;
    f.flush();
    if (!f) {
      std::remove(temp.c_str());
      throw Error(fmt::format("cannot write '{}'", path));
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw Error(fmt::format("cannot write '{}'", path));
  }
}

}  // namespace feran

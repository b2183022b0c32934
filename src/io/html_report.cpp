#include <feran/io/html_report.hpp>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/api684/analysis.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/modal/analysis.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/periodic/analysis.hpp>
#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/runup/waterfall.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/io/study_log.hpp>

#include "json_text.hpp"
#include "report_assets.hpp"
#include "verdicts.hpp"

namespace feran {

namespace {

using nlohmann::json;

// rᵀ·M·s over the model's elements, r and s given per (node, DOF) of the full model.
Real mass_form(const Model& model, const std::function<Real(Index, Dof)>& r, const std::function<Real(Index, Dof)>& s) {
  const OperatingPoint rest{};
  Real sum = 0;
  for (const Element& e : model.elements) {
    const LocalMatrices m = e.local_matrices(rest);
    if (m.M.size() == 0) continue;
    const Index n = static_cast<Index>(m.dofs.size());
    Vector a(n), b(n);
    for (Index i = 0; i < n; ++i) {
      const Index node = m.dofs[static_cast<std::size_t>(i)] / dofs_per_node;
      const Dof d = static_cast<Dof>(m.dofs[static_cast<std::size_t>(i)] % dofs_per_node);
      const bool rotating = model.nodes[static_cast<std::size_t>(node)].rotating;
      a(i) = rotating ? r(node, d) : 0.0;
      b(i) = rotating ? s(node, d) : 0.0;
    }
    sum += a.dot(m.M * b);
  }
  return sum;
}

// The rotor's mass, centre of mass and inertias from the mass matrix: m = rᵀMr for
// r a unit lateral translation; m·x_c from the rotation about the origin (v = x,
// r_z = 1); the transverse inertia about x_c from v = x − x_c, r_z = 1; the polar
// inertia from a unit twist r_x = 1 (exact for the consistent mass of every element).
json rotor_properties(const Model& model) {
  const auto x = [&](Index n) { return model.nodes[static_cast<std::size_t>(n)].x; };
  const auto translation = [](Index, Dof d) { return d == Dof::v ? 1.0 : 0.0; };
  const auto tilt_about = [&](Real xc) {
    return [&, xc](Index n, Dof d) { return d == Dof::v ? x(n) - xc : d == Dof::rz ? 1.0 : 0.0; };
  };
  const Real m = mass_form(model, translation, translation);
  const Real xc = m > 0 ? mass_form(model, translation, tilt_about(0.0)) / m : 0.0;
  const auto tilt = tilt_about(xc);
  const auto twist = [](Index, Dof d) { return d == Dof::rx ? 1.0 : 0.0; };
  return {{"mass_kg", m},
          {"centre_of_mass_x_m", xc},
          {"transverse_inertia_kg_m2", mass_form(model, tilt, tilt)},
          {"polar_inertia_kg_m2", mass_form(model, twist, twist)}};
}

// What the drawing and the model table need: nodes, shaft segments, rigid bodies
// (drawn as the solid disk of the same mass and inertias) and springs.
json model_summary(const ModelFile& file, Real speed) {
  const Model& model = file.model;
  json nodes = json::array();
  for (const Node& n : model.nodes)
    nodes.push_back({{"number", n.number}, {"name", n.name}, {"x_m", n.x}, {"rotating", n.rotating}});
  json shafts = json::array(), bodies = json::array(), springs = json::array();
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    if (const auto seg = el.shaft_segment()) {
      shafts.push_back({{"node_a", seg->node_a},
                        {"node_b", seg->node_b},
                        {"x_a_m", model.nodes[static_cast<std::size_t>(seg->node_a)].x},
                        {"x_b_m", model.nodes[static_cast<std::size_t>(seg->node_b)].x},
                        {"outer_diameter_m", seg->section.outer_diameter},
                        {"inner_diameter_m", seg->section.inner_diameter},
                        {"outer_diameter_b_m", seg->section_b.outer_diameter},
                        {"inner_diameter_b_m", seg->section_b.inner_diameter},
                        {"rotating", model.nodes[static_cast<std::size_t>(seg->node_a)].rotating},
                        {"label", el.label()}});
    } else if (const auto p = el.mass_properties()) {
      // A solid cylinder: J_P = m r²/2, J_A = m(3r² + w²)/12.
      const Real r = p->mass > 0 ? std::sqrt(2 * p->polar_inertia / p->mass) : 0.0;
      const Real w2 = p->mass > 0 ? 12 * p->transverse_inertia / p->mass - 3 * r * r : 0.0;
      bodies.push_back({{"label", el.label()},
                        {"node", p->node},
                        {"x_m", model.nodes[static_cast<std::size_t>(p->node)].x + p->offset},
                        {"mass_kg", p->mass},
                        {"transverse_inertia_kg_m2", p->transverse_inertia},
                        {"polar_inertia_kg_m2", p->polar_inertia},
                        {"rotating", p->rotating},
                        {"drawn_radius_m", r},
                        {"drawn_width_m", w2 > 0 ? std::sqrt(w2) : 0.0}});
    } else if (const auto t = el.transmission(speed)) {
      const auto k = [&](Dof d) { return t->K(static_cast<Index>(d), static_cast<Index>(d)); };
      const auto c = [&](Dof d) { return t->C(static_cast<Index>(d), static_cast<Index>(d)); };
      springs.push_back({{"label", el.label()},
                         {"kind", std::string(el.kind())},
                         {"node_a", t->node_a},
                         {"node_b", t->node_b ? json(*t->node_b) : json(nullptr)},
                         {"x_m", model.nodes[static_cast<std::size_t>(t->node_a)].x},
                         {"kyy_n_per_m", k(Dof::v)},
                         {"kzz_n_per_m", k(Dof::w)},
                         {"kyz_n_per_m", t->K(1, 2)},
                         {"kzy_n_per_m", t->K(2, 1)},
                         {"cyy_n_s_per_m", c(Dof::v)},
                         {"czz_n_s_per_m", c(Dof::w)}});
    }
  }
  // Journal and rolling bearings: their tangent about the static equilibrium at this
  // speed (none at rest for an oil film, or where no equilibrium is found).
  if (has_supports(model)) {
    const Model lin = linearised(model);
    for (auto e = static_cast<Index>(model.elements.size()); e < static_cast<Index>(lin.elements.size()); ++e) {
      const Element& el = lin.elements[static_cast<std::size_t>(e)];
      const Connection at = *el.connection();
      std::optional<Transmission> t;
      if (speed > 0 || !needs_speed(model)) {
        try {
          t = el.transmission(speed);
        } catch (const Error&) {  // no equilibrium at this speed: drawn without coefficients
        }
      }
      const auto k = [&](Index i, Index j) { return t ? detail::json_number(t->K(i, j)) : json(nullptr); };
      const auto c = [&](Index i) { return t ? detail::json_number(t->C(i, i)) : json(nullptr); };
      const auto v = static_cast<Index>(Dof::v), w = static_cast<Index>(Dof::w);
      springs.push_back({{"label", linearised_element_name(model, e)},
                         {"kind", std::string(model.forces[*linearised_support_force(model, e)].kind())},
                         {"node_a", at.node_a},
                         {"node_b", at.node_b ? json(*at.node_b) : json(nullptr)},
                         {"x_m", model.nodes[static_cast<std::size_t>(at.node_a)].x},
                         {"kyy_n_per_m", k(v, v)},
                         {"kzz_n_per_m", k(w, w)},
                         {"kyz_n_per_m", k(v, w)},
                         {"kzy_n_per_m", k(w, v)},
                         {"cyy_n_s_per_m", c(v)},
                         {"czz_n_s_per_m", c(w)}});
    }
  }
  return {{"title", file.title},
          {"nodes", nodes},
          {"shafts", shafts},
          {"bodies", bodies},
          {"springs", springs},
          {"springs_at_speed_rpm", rad_to_hz(speed) * 60},
          {"rotor", rotor_properties(model)},
          {"n_dofs", model.n_dofs()}};
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read '{}'", path.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A design study's output directory: its study, summary and evaluations.
json study_results(const std::string& directory) {
  namespace fs = std::filesystem;
  const fs::path dir(directory);
  if (!fs::is_directory(dir)) throw Error(fmt::format("study directory '{}' does not exist", directory));
  for (const char* name : {study_files::study, study_files::evaluations})
    if (!fs::exists(dir / name))
      throw Error(fmt::format("'{}' holds no study results: '{}' is missing (the output of feran study -o DIR)",
                              directory, name));
  json out;
  try {
    out["study"] = json::parse(read_text(dir / study_files::study));
    out["summary"] =
        fs::exists(dir / study_files::summary) ? json::parse(read_text(dir / study_files::summary)) : json(nullptr);
    json evaluations = json::array();
    std::istringstream lines(read_text(dir / study_files::evaluations));
    std::string line;
    while (std::getline(lines, line))
      if (!line.empty()) evaluations.push_back(json::parse(line));
    out["evaluations"] = evaluations;
  } catch (const json::parse_error& e) {
    throw Error(fmt::format("the study results in '{}' are not valid JSON: {}", directory, e.what()));
  }
  return out;
}

// Records a section's failure instead of the whole report's.
template <class F>
void section(json& data, const char* name, F&& make, const StopToken& stop = {}) {
  if (stop.requested()) {  // a report stopped on request: the sections after are left out
    data[name] = {{"error", "not computed: the report was stopped on request"}};
    return;
  }
  try {
    data[name] = make();
  } catch (const Error& e) {
    data[name] = {{"error", e.what()}};
  }
}

std::string timestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// JSON text placed in a <script> element: "</" would end the element.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

bool report_available() { return detail::report_assets_built(); }

std::vector<std::string> report_study_files(const ReportOptions& options) {
  if (options.study_directory.empty()) return {};
  std::vector<std::string> out;
  for (const char* name : {study_files::study, study_files::evaluations, study_files::summary})
    out.push_back((std::filesystem::path(options.study_directory) / name).string());
  return out;
}

namespace {

// Each resonance peak of a response's probes with its amplification factor and its
// margins from the operating range [@p low, @p high] (API 684).
json separation_json(const HarmonicResult& hr, Real low, Real high) {
  json peaks = json::array();
  for (std::size_t p = 0; p < hr.probes.size(); ++p) {
    for (const SeparationCheck& c : separation_checks(hr, p, low, high))
      peaks.push_back({{"probe", p},
                       {"speed_rpm", rad_to_hz(c.peak.speed) * 60},
                       {"amplitude_m", c.peak.amplitude},
                       {"amplification_factor", c.peak.resolved() ? json(c.peak.amplification_factor) : json(nullptr)},
                       {"actual_margin", c.actual_margin},
                       {"required_margin", c.required_margin ? json(*c.required_margin) : json(nullptr)},
                       {"passes", c.passes ? json(*c.passes) : json(nullptr)},
                       {"unstable", c.unstable}});
  }
  return peaks;
}

}  // namespace

namespace {

// The report's sections, one step each, over the data embedded in the page.
class ReportData {
 public:
  ReportData(const ModelFile& file, const ReportOptions& options)
      : file_(file),
        options_(options),
        unowned_(std::shared_ptr<const ModelFile>(), &file),
        // The operating range, when the model or the request gives one.
        low_(options.api684_request.min_speed ? options.api684_request.min_speed : file.spec.api684.min_speed),
        high_(options.api684_request.max_speed ? options.api684_request.max_speed : file.spec.api684.max_speed) {}

  json build(std::string* summary) {
    inputs();
    campbell();
    modes();
    if (file_.model.count_forces(is_unbalance) > 0 || file_.model.count_forces(is_harmonic_force) > 0 ||
        !options_.response.forces.empty())
      section(
          data_, "response", [&] { return response(); }, options_.stop);
    if (options_.static_analysis)
      section(
          data_, "static", [&] { return static_deflection(); }, options_.stop);
    if (options_.api684 && low_ && high_)
      section(
          data_, "api684",
          [&] {
            return json::parse(Api684Analysis::json(run_analysis<Api684Analysis>(
                unowned_, options_.api684_request, file_key_name<Api684Analysis>(), context(true))));
          },
          options_.stop);
    const RunupSpec& r = file_.spec.runup;
    if (options_.runup && (r.speed || r.to || !r.table.empty()))
      section(
          data_, "runup", [&] { return runup(); }, options_.stop);
    const OrbitsSpec &o = file_.spec.orbits, &q = options_.orbits_request;
    if (options_.orbits && (((o.from || q.from) && (o.to || q.to)) || o.parameter || q.parameter))
      section(
          data_, "orbits",
          [&] {
            return json::parse(OrbitsAnalysis::json(
                run_analysis<OrbitsAnalysis>(unowned_, q, file_key_name<OrbitsAnalysis>(), context())));
          },
          options_.stop);
    if (!options_.study_directory.empty()) data_["study"] = study_results(options_.study_directory);
    finish(summary);
    return std::move(data_);
  }

 private:
  // The requested threads for the analyses whose points run side by side.
  RunContext context(bool parallel = false) const {
    RunContext c{.stop = options_.stop};
    if (parallel) c.threads = options_.n_threads;
    return c;
  }
  void inputs();
  void campbell();
  void modes();
  json response();
  json static_deflection();
  json runup();
  void finish(std::string* summary);

  const ModelFile& file_;
  const ReportOptions& options_;
  const std::shared_ptr<const ModelFile> unowned_;
  const std::optional<Real> low_, high_;
  json data_;
  std::vector<Real> campbell_speeds_;  // the Campbell diagram's speeds [rad/s]
  std::vector<Real> mode_speeds_;      // the speeds of the mode shapes [rad/s]
};

void ReportData::inputs() {
  data_["inputs"] = {{"model_path", file_.path},
                     {"command", options_.command},
                     {"version", options_.version},
                     {"created", timestamp()},
                     {"model_text", write_toml(file_.spec)}};
  data_["title"] = options_.title.empty()
                       ? (file_.title.empty() ? std::filesystem::path(file_.path).filename().string() : file_.title)
                       : options_.title;
  data_["speed_unit"] = options_.speed_unit;
  data_["operating"] =
      low_ && high_ ? json{{"min_rpm", rad_to_hz(*low_) * 60}, {"max_rpm", rad_to_hz(*high_) * 60}} : json(nullptr);
  data_["model"] = model_summary(file_, high_.value_or(0.0));
}

// The Campbell diagram and damping, to 1.5 × the maximum operating speed unless a
// table gives its last speed.
void ReportData::campbell() {
  CampbellSpec request = options_.campbell;
  if (!request.stop && !file_.spec.campbell.stop && high_) request.stop = 1.5 * *high_;
  const Outcome<CampbellAnalysis> o =
      run_analysis<CampbellAnalysis>(unowned_, request, file_key_name<CampbellAnalysis>(), context(true));
  campbell_speeds_ = o.options.speeds;
  data_["campbell"] = json::parse(CampbellAnalysis::json(o));
}

// Mode shapes at the chosen speeds: by default at rest, unless an oil film carries the
// rotor only while it turns (then the lowest operating speed, else the Campbell
// diagram's first speed above 0), and at the maximum operating speed (else the
// diagram's last).
void ReportData::modes() {
  mode_speeds_ = options_.mode_speeds;
  if (mode_speeds_.empty()) {
    Real first = 0.0;
    if (needs_speed(file_.model)) {
      first = low_.value_or(0.0);
      for (const Real s : campbell_speeds_)
        if (!(first > 0) && s > 0) first = s;
    }
    mode_speeds_ = {first};
    const Real last = high_.value_or(campbell_speeds_.back());
    if (last != first) mode_speeds_.push_back(last);
  }
  const ResultSource source{file_.path, file_.title};
  json modes = json::array();
  for (const Real s : mode_speeds_) {
    ModalOptions mo;
    mo.oscillatory_only = true;
    mo.n_modes = options_.mode_count;
    section(
        modes.emplace_back(), "result",
        [&] {
          // The modal analysis's own JSON, of oscillatory modes with their shapes.
          const Outcome<ModalAnalysis> o{unowned_, {s, mo}, run_modal(file_.model, s, mo, file_.assembler), source};
          return json::parse(ModalAnalysis::json(o));
        },
        options_.stop);
  }
  data_["modes"] = modes;
}

// The unbalance response over the Campbell diagram's speeds, with the peaks judged
// against the operating range (API 684), and the deflected shape at one speed.
json ReportData::response() {
  ResponseSpec request = options_.response;
  if (!request.stations) request.stations = "summary";
  if (!request.stop && !file_.spec.response.stop) request.stop = campbell_speeds_.back();
  const Outcome<ResponseAnalysis> response =
      run_analysis<ResponseAnalysis>(unowned_, request, file_key_name<ResponseAnalysis>(), context(true));
  const HarmonicResult& hr = response.result;
  json j = json::parse(ResponseAnalysis::json(response));
  if (low_ && high_) j["peaks"] = separation_json(hr, *low_, *high_);
  // The deflected shape at one speed: every node's orbit, from a response there.
  Real at = options_.deflection_speed.value_or(0.0);
  if (!options_.deflection_speed) {
    Real best = -1;
    for (const auto& p : hr.probes)
      for (std::size_t k = 0; k < p.orbit.size(); ++k)
        if (p.orbit[k].major > best) best = p.orbit[k].major, at = hr.speeds[k];
  }
  ResponseSpec shape = options_.response;
  shape.speed = at;
  shape.start.reset();
  shape.stop.reset();
  shape.points.reset();
  shape.probes.clear();
  for (const Node& n : file_.model.nodes) shape.probes.emplace_back(std::int64_t{n.number});
  shape.stations = "none";
  j["deflected_shape"] = json::parse(ResponseAnalysis::json(
      run_analysis<ResponseAnalysis>(unowned_, shape, file_key_name<ResponseAnalysis>(), context())));
  return j;
}

// A rotor on oil films rests on them only while it turns: without a speed of its own,
// the static analysis runs at the maximum operating speed (else the first speed above
// 0 the mode shapes use).
json ReportData::static_deflection() {
  StaticSpec request;
  if (!file_.spec.static_.speed && needs_speed(file_.model)) request.speed = high_ ? *high_ : mode_speeds_.front();
  return json::parse(StaticAnalysis::json(
      run_analysis<StaticAnalysis>(unowned_, request, file_key_name<StaticAnalysis>(), context())));
}

// The model's run-up, with the waterfall of its first probe's v as feran.plot draws it.
json ReportData::runup() {
  const Outcome<RunupAnalysis> runup =
      run_analysis<RunupAnalysis>(unowned_, {}, file_key_name<RunupAnalysis>(), context());
  json j = json::parse(RunupAnalysis::json(runup));
  if (runup.result.samples.size() >= 8 && !runup.options.probes.empty()) {
    const Waterfall w = waterfall(runup.result, 0, Dof::v);
    json rows = json::array();
    for (Index i = 0; i < w.amplitude.rows(); ++i)
      rows.push_back(std::vector<Real>(w.amplitude.row(i).begin(), w.amplitude.row(i).end()));
    std::vector<Real> speeds_hz;
    for (const Real speed : w.speeds) speeds_hz.push_back(rad_to_hz(speed));
    j["waterfall"] = {
        {"probe", 0}, {"dof", "v"}, {"speeds_hz", speeds_hz}, {"frequencies_hz", w.frequencies}, {"amplitude_m", rows}};
  }
  return j;
}

void ReportData::finish(std::string* summary) {
  // The sections computed, in the report's order: the script draws each with its
  // module (src/analyses/<name>/report.js, src/study/report.js).
  json sections = json::array();
  for (const char* key : {"campbell", "modes", "response", "static", "api684", "runup", "orbits", "study"})
    if (data_.contains(key)) sections.push_back(key);
  data_["sections"] = sections;
  // Stopped on request: what was computed is shown, marked incomplete (an analysis
  // cut short keeps its results up to there; the sections after it are left out).
  data_["complete"] = !options_.stop.requested();
  // The verdicts the report opens with, read off the sections above.
  const std::vector<detail::Verdict> verdicts = detail::report_verdicts(data_, options_.speed_unit);
  data_["verdicts"] = detail::verdicts_json(verdicts);
  if (summary) *summary = detail::verdicts_text(verdicts);
}

}  // namespace

std::string html_report(const ModelFile& file, const ReportOptions& options, std::string* summary) {
  if (!report_available())
    throw Error(
        "this feran was built without plotly.js, which the report inlines: run scripts/setup.sh (it "
        "installs the front-end packages with npm) and build again");
  if (options.speed_unit != "rpm" && options.speed_unit != "Hz")
    throw Error(fmt::format("the report's speed unit must be \"rpm\" or \"Hz\", got \"{}\"", options.speed_unit));
  const json data = ReportData(file, options).build(summary);
  const std::string title = html_escape(data["title"].get<std::string>());
  std::string html;
  html.reserve(detail::plotly_js().size() + (1 << 20));
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"generator\" content=\"feran " + html_escape(options.version) + "\">\n";
  html += "<title>" + title + " — feran report</title>\n<style>\n";
  html += detail::report_css();
  html += "\n</style>\n<script>\n";
  html += detail::plotly_js();
  html +=
      "\n</script>\n</head>\n<body>\n<div id=\"report\"><noscript>This report draws its figures with "
      "JavaScript.</noscript></div>\n";
  html += "<script id=\"feran-data\" type=\"application/json\">\n";
  html += script_safe(data.dump(-1, ' ', false, json::error_handler_t::replace));
  html += "\n</script>\n<script>\n";
  html += detail::report_js();
  html += "\n</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace feran

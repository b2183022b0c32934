// The modal analysis's room: its options ([modal]), their defaults and checks, its
// JSON, CSV and terminal writers and its study quantities (analyses/modal/analysis.hpp).
#include <feran/analyses/modal/analysis.hpp>

#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/io/option_text.hpp>
#include <feran/spec/fields.hpp>
#include <feran/study/design_analyses.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace spec {

template <>
const FieldTable<ModalSpec>& fields_of<ModalSpec>() {
  using S = ModalSpec;
  using K = FieldKind;
  static const FieldTable<S> table = {
      {.key = "speed",
       .kind = K::quantity,
       .member = &S::speed,
       .doc = "rotor speed of the modal analysis",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::non_negative},
       .unit = "Hz",
       .short_name = "s"},
      {.key = "modes",
       .kind = K::integer,
       .member = &S::modes,
       .doc = "number of modes, the lowest first",
       .bound = {Bound::Kind::at_least, 1},
       .default_text = "all (dense) or 12 (sparse)",
       .short_name = "n"},
      {.key = "solver",
       .kind = K::choice,
       .member = &S::solver,
       .doc = "eigen solver: `\"auto\"` (dense for all modes up to 400 DOF; with `modes`, for each decoupled block "
              "the one a cost model expects to be faster), `\"dense\"` (LAPACK QR) or `\"sparse\"` (the lowest "
              "modes by shift-invert Arnoldi)",
       .choices = eigen_solver_names},
      {.key = "shapes", .kind = K::flag, .member = &S::shapes, .doc = "whether the JSON holds the mode shapes"},
  };
  return table;
}

}  // namespace spec

const ModalSpec& ModalAnalysis::defaults() {
  static const ModalSpec d{.speed = 0.0, .modes = std::nullopt, .solver = "auto", .shapes = false};
  return d;
}

ModalSettings ModalAnalysis::settings(const Model&, const ModalSpec&, const ModalSpec& resolved, const OptionName&) {
  ModalSettings s;
  s.speed = *resolved.speed;
  s.options.n_modes = resolved.modes.value_or(0);
  s.options.solver = parse_solver_name(*resolved.solver, "solver");
  s.options.shapes = *resolved.shapes;
  return s;
}

ModalResult ModalAnalysis::run(const Model& model, const ModalSettings& options, const RunContext& context) {
  return run_modal(model, options.speed, options.options, context.assembler);
}

std::vector<std::string> ModalAnalysis::warnings(const Model& model, const ModalSettings& options,
                                                 const ModalResult& result) {
  // Frequency tables are read at the modes' frequencies.
  std::vector<Real> frequencies;
  for (const Mode& m : result.modes) frequencies.push_back(m.frequency_hz);
  const auto span = frequency_span(frequencies);
  return range_warnings(model, options.speed, options.speed, span);
}

std::string ModalAnalysis::json(const Outcome<ModalAnalysis>& o) {
  const ModalResult& result = o.result;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  const bool shapes = o.options.options.shapes;
  Json j = header("modal", source);
  j["speed_hz"] = rad_to_hz(result.speed);
  j["speed_rpm"] = rad_to_hz(result.speed) * 60.0;
  j["solver"] = solver_json(result.info);
  j["solver"]["complex_form"] = result.complex_form;
  if (result.frequency_dependent) j["solver"]["frequency_iterations"] = result.frequency_iterations;
  if (shapes) {
    Json nodes = Json::array();
    for (const Node& n : model.nodes)
      nodes.push_back({{"number", n.number}, {"name", n.name}, {"x_m", n.x}, {"rotating", n.rotating}});
    j["nodes"] = nodes;
  }
  Json modes = Json::array();
  int index = 0;
  for (const Mode& m : result.modes) {
    Json jm = {{"index", ++index},
               {"frequency_hz", json_number(m.frequency_hz)},
               {"damping_ratio", json_number(m.damping_ratio)},
               {"log_decrement", json_number(m.log_decrement)},
               {"eigenvalue", {{"real", m.eigenvalue.real()}, {"imag", m.eigenvalue.imag()}}},
               {"whirl", to_string(m.whirl)},
               {"directivity", json_number(m.directivity)},
               {"type", to_string(m.type)},
               {"shape", to_string(m.shape_kind)},
               {"bending", json_number(m.bending)},
               {"rigid_body", m.rigid_body},
               {"oscillatory", m.oscillatory}};
    if (shapes && m.shape.size() > 0) {
      Json shape;
      for (int d = 0; d < dofs_per_node; ++d) {
        Json re = Json::array(), im = Json::array();
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
  j["supports"] = detail::operating_json(result.operating, model, true);
  return detail::json_text(j, 2);
}

std::string ModalAnalysis::csv(const Outcome<ModalAnalysis>& o) {
  const ModalResult& result = o.result;
  std::ostringstream out;
  out << "mode,frequency_hz,damping_ratio,log_decrement,eigenvalue_real,eigenvalue_imag,whirl,"
         "directivity,type,rigid_body,shape,bending\n";
  int index = 0;
  for (const Mode& m : result.modes)
    out << ++index << ',' << csv_number(m.frequency_hz) << ',' << csv_number(m.damping_ratio) << ','
        << csv_number(m.log_decrement) << ',' << csv_number(m.eigenvalue.real()) << ','
        << csv_number(m.eigenvalue.imag()) << ',' << to_string(m.whirl) << ',' << csv_number(m.directivity) << ','
        << to_string(m.type) << ',' << (m.rigid_body ? "true" : "false") << ',' << to_string(m.shape_kind) << ','
        << csv_number(m.bending) << '\n';
  return out.str();
}

std::string ModalAnalysis::terminal(const Outcome<ModalAnalysis>& o) {
  const ModalResult& result = o.result;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  std::string out = source_line("modal", source);
  out += fmt::format("speed {}, {} modes, solver {}\n\n", speed_text(result.speed, source.speed_unit),
                     result.modes.size(), to_string(result.info.method));
  const std::string& unit = source.speed_unit;
  out += fmt::format("{:>4}  {:>14}  {:>12}  {:>10}  {:<9} {:>11}  {:<10} {:<12} {}\n", "mode",
                     fmt::format("frequency [{}]", frequency_unit(unit)), "damping [%]", "log. decr.", "whirl",
                     "directivity", "type", "shape", "note");
  int index = 0;
  for (const Mode& m : result.modes) {
    const char* note = m.rigid_body ? "rigid body" : (!m.oscillatory ? "non-oscillatory" : "");
    out += fmt::format(
        "{:>4}  {}  {}  {}  {:<9} {}  {:<10} {:<12} {}\n", ++index,
        cell(frequency_value(m.frequency_hz, unit), unit == "rpm" ? ".2f" : ".4f", 14, unit == "rpm" ? 2 : 4),
        cell(100.0 * m.damping_ratio, ".3f", 12, 3), cell(m.log_decrement, ".4f", 10, 4), to_string(m.whirl),
        cell(m.directivity, ".3f", 11, 3), to_string(m.type),
        m.shape_kind == ModeShape::none ? "-" : to_string(m.shape_kind), note);
  }
  out += operating_at_one_speed(result.operating, model);
  if (!result.info.converged()) out += fmt::format("\nwarning: {}\n", result.info.message);
  return out;
}

// ---- study quantities ----------------------------------------------------------------

namespace {

// The n-th oscillatory lateral mode of the quantity's whirl at its speed (default the
// design's [modal] speed): one of its numbers.
template <Real Mode::*member>
Real mode_value(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  ModalSpec request;
  request.speed = q.speed;
  const ModalSettings settings =
      analysis_options<ModalAnalysis>(a.spec(), a.model(), request, file_key_name<ModalAnalysis>());
  const ModalResult result = ModalAnalysis::run(a.model(), settings, RunContext{a.stop(), {}});
  if (!result.info.converged()) throw Error(fmt::format("the modal analysis failed: {}", result.info.message));
  int seen = 0;
  for (const auto& m : result.modes)
    if (m.type == ModeType::lateral && m.oscillatory && selected(m.whirl, q.whirl) && ++seen == q.n) return m.*member;
  throw Error(fmt::format("no {} {}lateral mode at {} (found {})", ordinal(q.n), whirl_word(q.whirl),
                          rpm(settings.speed), seen));
}

}  // namespace

const std::vector<QuantityRow>& ModalAnalysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "natural_frequency",
       .doc = "the n-th natural frequency of a whirl at a speed",
       .analysis = name,
       .unit = Quantity::frequency,
       .evaluate = mode_value<&Mode::frequency_hz>},
      {.name = "damping_ratio",
       .doc = "the damping ratio of that mode",
       .analysis = name,
       .evaluate = mode_value<&Mode::damping_ratio>,
       .any_whirl = true},
      {.name = "log_decrement",
       .doc = "the logarithmic decrement of that mode",
       .analysis = name,
       .evaluate = mode_value<&Mode::log_decrement>,
       .any_whirl = true},
  };
  return rows;
}

}  // namespace feran

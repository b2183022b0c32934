// The static analysis's room: its options ([static]), their defaults and checks, and
// its JSON, CSV and terminal writers (analyses/static/analysis.hpp).
#include <feran/analyses/static/analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/spec/fields.hpp>
#include <feran/study/design_analyses.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace spec {

namespace {
constexpr std::string_view gravity_directions[] = {"+x", "-x", "+y", "-y", "+z", "-z", "none"};
}  // namespace

template <>
const FieldTable<StaticSpec>& fields_of<StaticSpec>() {
  using S = StaticSpec;
  using K = FieldKind;
  static const FieldTable<S> table = {
      {.key = "gravity",
       .kind = K::choice,
       .member = &S::gravity,
       .doc = "the direction in which gravity pulls, or `\"none\"` (explicitly no gravity)",
       .choices = gravity_directions,
       .group = "gravity"},
      {.key = "g",
       .kind = K::quantity,
       .member = &S::g,
       .doc = "magnitude of the gravitational acceleration; only with a direction (an error with `\"none\"` or without "
              "`gravity`)",
       .quantity = Quantity::acceleration,
       .bound = {Bound::Kind::positive},
       .unit = "m/s^2",
       .follows = "gravity"},
      {.key = "speed",
       .kind = K::quantity,
       .member = &S::speed,
       .doc = "rotor speed at which speed-dependent coefficients (section 5) are evaluated",
       .quantity = Quantity::speed,
       .bound = {Bound::Kind::non_negative},
       .unit = "Hz",
       .short_name = "s"},
      {.key = "loads", .kind = K::flag, .member = &S::loads, .doc = "whether the model's [[static_loads]] act"},
      {.key = "stability",
       .kind = K::flag,
       .member = &S::stability,
       .doc = "whether to judge if the rotor stays at the equilibrium when disturbed, from the motion linearised "
              "about it (false leaves it unknown)"},
  };
  return table;
}

}  // namespace spec

const StaticSpec& StaticAnalysis::defaults() {
  static const StaticSpec d{.gravity = "-y", .g = defaults::gravity, .speed = 0.0, .loads = true, .stability = true};
  return d;
}

StaticOptions StaticAnalysis::settings(const Model&, const StaticSpec& asked, const StaticSpec& resolved,
                                       const OptionName& named) {
  if (asked.g && resolved.gravity == "none")
    throw Error(fmt::format("{0} cannot be given with {1} none; give a direction such as {1} -z, or leave {0} out",
                            named("g"), named("gravity")));
  StaticOptions options;
  const std::string& direction = *resolved.gravity;
  if (direction != "none") {
    const auto axis = static_cast<Index>(direction.back() - 'x');
    options.gravity(axis) = direction.front() == '-' ? -*resolved.g : *resolved.g;
  }
  options.speed = *resolved.speed;
  options.loads = *resolved.loads;
  options.stability = *resolved.stability;
  return options;
}

StaticResult StaticAnalysis::run(const Model& model, const StaticOptions& options, const RunContext&) {
  return run_static(model, options);
}

std::vector<std::string> StaticAnalysis::warnings(const Model& model, const StaticOptions& options,
                                                  const StaticResult&) {
  return range_warnings(model, options.speed, options.speed);
}

StaticOptions static_options(const ModelSpec& spec, const Model& model) {
  return analysis_options<StaticAnalysis>(spec, model, {}, file_key_name<StaticAnalysis>());
}

StaticOptions static_options(const ModelFile& file) { return static_options(file.spec, file.model); }

std::string StaticAnalysis::json(const Outcome<StaticAnalysis>& o) {
  const StaticResult& result = o.result;
  const StaticOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  Json j = header("static", source);
  j["gravity_m_s2"] = {options.gravity(0), options.gravity(1), options.gravity(2)};
  j["speed_hz"] = rad_to_hz(options.speed);
  j["solver"] = solver_json(result.info);
  j["stability"] = stability_point_json(result.stability);
  Json nodes = Json::array();
  for (Index node = 0; node < model.n_nodes(); ++node) {
    Json jn = node_json(model, node);
    for (int d = 0; d < dofs_per_node; ++d) jn[dof_names[d]] = result.q(dofs_per_node * node + d);
    nodes.push_back(jn);
  }
  j["displacements"] = nodes;
  auto components = [](const NodeValues& v, const std::array<bool, dofs_per_node>& mask) {
    Json out = Json::object();
    for (int d = 0; d < dofs_per_node; ++d)
      if (mask[static_cast<std::size_t>(d)]) out[direction_names[d]] = v[static_cast<std::size_t>(d)];
    return out;
  };
  Json springs = Json::array();
  for (const auto& [e, f] : result.springs) {
    const Transmission link = *model.elements[static_cast<std::size_t>(e)].transmission(0.0);
    Json js = {{"label", element_label(model, e)},
               {"node", model.nodes[static_cast<std::size_t>(link.node_a)].number},
               {"force", components(f, all_dofs)}};
    js["to"] = link.node_b ? Json(model.nodes[static_cast<std::size_t>(*link.node_b)].number) : Json("ground");
    springs.push_back(js);
  }
  j["springs"] = springs;
  Json supports = Json::array();
  for (const auto& [i, f] : result.supports) {
    const Force& force = model.forces[static_cast<std::size_t>(i)];
    const std::vector<Index> at = force.nodes();
    Json js = {{"label", force_label(model, i)},
               {"kind", force.kind()},
               {"node", model.nodes[static_cast<std::size_t>(at.front())].number},
               {"force", {{"y", f[static_cast<std::size_t>(Dof::v)]}, {"z", f[static_cast<std::size_t>(Dof::w)]}}}};
    js["to"] = at.size() > 1 ? Json(model.nodes[static_cast<std::size_t>(at[1])].number) : Json("ground");
    Json operating = Json::object();
    for (const OperatingValue& v : result.support_data[supports.size()]) operating[v.name] = json_number(v.value);
    js["operating"] = operating;
    supports.push_back(js);
  }
  j["supports"] = supports;
  Json reactions = Json::array();
  for (const auto& [node, f] : result.reactions) {
    std::array<bool, dofs_per_node> mask{};
    for (const FixedDofs& fd : model.fixed)
      if (fd.node == node)
        for (int d = 0; d < dofs_per_node; ++d)
          mask[static_cast<std::size_t>(d)] |= fd.dofs[static_cast<std::size_t>(d)];
    Json jr = node_json(model, node);
    jr["force"] = components(f, mask);
    reactions.push_back(jr);
  }
  j["reactions"] = reactions;
  Json stations = Json::array();
  for (std::size_t i = 0; i < result.stations.size(); ++i) {
    const SectionForces& f = result.section_forces[i];
    const SectionStress& s = result.stresses[i];
    Json js = station_json(model, result.stations[i]);
    js["forces"] = {{"N", f.N.real()}, {"Vy", f.Vy.real()}, {"Vz", f.Vz.real()},
                    {"T", f.T.real()}, {"My", f.My.real()}, {"Mz", f.Mz.real()}};
    js["stress_pa"] = {{"axial", s.axial},
                       {"bending", s.bending},
                       {"torsion", s.torsion},
                       {"shear", s.shear},
                       {"von_mises", s.von_mises}};
    stations.push_back(js);
  }
  j["stations"] = stations;
  j["total_load"] = components(result.total_load, all_dofs);
  return detail::json_text(j, 2);
}

std::string StaticAnalysis::csv(const Outcome<StaticAnalysis>& o) {
  const StaticResult& result = o.result;
  const Model& model = o.model();
  std::ostringstream out;
  out << "element,end,node,x_m,u_m,v_m,w_m,rx_rad,ry_rad,rz_rad,N_n,Vy_n,Vz_n,T_nm,My_nm,Mz_nm,"
         "axial_pa,bending_pa,torsion_pa,shear_pa,von_mises_pa\n";
  for (std::size_t i = 0; i < result.stations.size(); ++i) {
    const ShaftStation& st = result.stations[i];
    const SectionForces& f = result.section_forces[i];
    const SectionStress& s = result.stresses[i];
    out << st.element + 1 << ',' << (st.end == 0 ? "start" : "end") << ','
        << model.nodes[static_cast<std::size_t>(st.node)].number << ',' << csv_number(st.x);
    for (int d = 0; d < dofs_per_node; ++d) out << ',' << csv_number(result.q(dofs_per_node * st.node + d));
    for (Complex c : {f.N, f.Vy, f.Vz, f.T, f.My, f.Mz}) out << ',' << csv_number(c.real());
    out << ',' << csv_number(s.axial) << ',' << csv_number(s.bending) << ',' << csv_number(s.torsion) << ','
        << csv_number(s.shear) << ',' << csv_number(s.von_mises) << '\n';
  }
  return out.str();
}

namespace {

// The supports' state at the equilibrium of a static analysis: one row per support.
std::string operating_table(const StaticResult& result, const Model& model) {
  std::vector<std::vector<std::string>> names(result.support_data.size());
  std::vector<std::vector<Real>> values(result.support_data.size());
  std::vector<OperatingRow> rows;
  for (std::size_t i = 0; i < result.supports.size(); ++i) {
    for (const OperatingValue& o : result.support_data[i]) names[i].push_back(o.name), values[i].push_back(o.value);
    rows.push_back({force_name(model, result.supports[i].first), &names[i], &values[i]});
  }
  return operating_block("Bearing operating data at the equilibrium", "", rows);
}

}  // namespace

std::string StaticAnalysis::terminal(const Outcome<StaticAnalysis>& o) {
  const StaticResult& result = o.result;
  const StaticOptions& options = o.options;
  const Model& model = o.model();
  const ResultSource& source = o.source;
  std::string out = source_line("static", source);
  out += fmt::format("gravity ({:.4g}, {:.4g}, {:.4g}) m/s^2, {} static load(s), coefficients at {}\n\n",
                     options.gravity(0), options.gravity(1), options.gravity(2),
                     options.loads ? model.count_forces([](const Force& f) { return f.has_static(); }) : 0,
                     speed_text(options.speed, source.speed_unit));
  if (result.stability.known && result.stability.unstable)
    out +=
        fmt::format("warning: the rotor does not stay at this equilibrium: {}\n\n", stability_phrase(result.stability));
  else
    out += fmt::format("stability of the equilibrium: {}\n\n", stability_phrase(result.stability));
  out += "Displacements [mm, mrad]\n";
  out += fmt::format("{:>20} {:>9} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "node", "x [mm]", "u", "v", "w", "rx",
                     "ry", "rz");
  for (Index node = 0; node < model.n_nodes(); ++node) {
    out += fmt::format("{:>20} {:>9.2f}", node_name(model, node), 1e3 * model.nodes[static_cast<std::size_t>(node)].x);
    for (int d = 0; d < dofs_per_node; ++d) out += " " + cell(1e3 * result.q(dofs_per_node * node + d), ".5f", 10, 5);
    out += '\n';
  }
  auto forces = [&](const NodeValues& f) {
    std::string s;
    for (int d = 0; d < dofs_per_node; ++d) s += " " + cell(f[static_cast<std::size_t>(d)], ".4g", 10, 12);
    return s;
  };
  const std::string head = fmt::format("{:>10} {:>10} {:>10} {:>10} {:>10} {:>10}", "Fx [N]", "Fy [N]", "Fz [N]",
                                       "Mx [Nm]", "My [Nm]", "Mz [Nm]");
  if (!result.springs.empty()) {
    out += fmt::format("\nForces on the spring-dampers' second node or ground\n{:>30}{}\n", "", head);
    for (const auto& [e, f] : result.springs) out += fmt::format("{:>30}{}\n", element_name(model, e), forces(f));
  }
  if (!result.supports.empty()) {
    out += fmt::format("\nForces the bearings transmit to their housing or ground\n{:>30}{}\n", "", head);
    for (const auto& [i, f] : result.supports) out += fmt::format("{:>30}{}\n", force_name(model, i), forces(f));
    out += operating_table(result, model);
  }
  if (!result.reactions.empty()) {
    out += fmt::format("\nForces on the supports (fixed DOFs)\n{:>30}{}\n", "", head);
    for (const auto& [node, f] : result.reactions)
      out += fmt::format("{:>30}{}\n", "node " + node_name(model, node), forces(f));
  }
  out += fmt::format("{:>30}{}\n", "total applied load", forces(result.total_load));
  if (!result.stations.empty()) {
    std::size_t worst = 0;
    for (std::size_t i = 0; i < result.stresses.size(); ++i)
      if (result.stresses[i].von_mises > result.stresses[worst].von_mises) worst = i;
    out += "\nShaft section forces and stresses (element ends)\n";
    out += fmt::format("{:>9} {:>10} {:>10} {:>10} {:>10} {:>12} {:>12}\n", "x [mm]", "N [N]", "|V| [N]", "T [Nm]",
                       "|M| [Nm]", "bending[MPa]", "eq. [MPa]");
    for (std::size_t i = 0; i < result.stations.size(); ++i) {
      const SectionForces& f = result.section_forces[i];
      out += fmt::format("{:>9.2f} {} {} {} {} {} {}{}\n", 1e3 * result.stations[i].x, cell(f.N.real(), ".4g", 10, 12),
                         cell(std::hypot(f.Vy.real(), f.Vz.real()), ".4g", 10, 12), cell(f.T.real(), ".4g", 10, 12),
                         cell(std::hypot(f.My.real(), f.Mz.real()), ".4g", 10, 12),
                         cell(1e-6 * result.stresses[i].bending, ".4f", 12, 4),
                         cell(1e-6 * result.stresses[i].von_mises, ".4f", 12, 4), i == worst ? "  <- largest" : "");
    }
  }
  return out;
}

// ---- study quantities ----------------------------------------------------------------

namespace {

// The design's static result; none at an equilibrium the rotor does not stay at.
const StaticResult& stable_result(DesignAnalyses& a) {
  const StaticResult& r = a.result<StaticAnalysis>();
  if (r.stability.known && r.stability.unstable)
    throw Error(fmt::format("the rotor does not stay at its static equilibrium: {}", stability_phrase(r.stability)));
  return r;
}

Real lateral(const StaticResult& r, Index node) {
  return std::hypot(r.q(dofs_per_node * node + static_cast<Index>(Dof::v)),
                    r.q(dofs_per_node * node + static_cast<Index>(Dof::w)));
}

Real static_deflection(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const StaticResult& r = stable_result(a);
  if (q.probe) return lateral(r, node_index(a.model(), *q.probe));
  Real largest = 0;
  for (Index node = 0; node < a.model().n_nodes(); ++node) largest = std::max(largest, lateral(r, node));
  return largest;
}

Real static_stress(DesignAnalyses& a, const QuantitySpec&, std::string&) {
  const StaticResult& r = stable_result(a);
  if (r.stresses.empty()) throw Error("the model has no shaft element");
  Real largest = 0;
  for (const SectionStress& s : r.stresses) largest = std::max(largest, s.von_mises);
  return largest;
}

Real static_spring_force(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const StaticResult& r = stable_result(a);
  const Index only = q.spring ? spring_element(a.model(), *q.spring) : -1;
  Real largest = 0;
  for (const auto& [e, f] : r.springs)
    if (only < 0 || e == only)
      largest = std::max(largest, std::hypot(f[static_cast<std::size_t>(Dof::v)], f[static_cast<std::size_t>(Dof::w)]));
  return largest;
}

template <bool smallest>
Real static_bearing_value(DesignAnalyses& a, const QuantitySpec& q, std::string&) {
  const StaticResult& r = stable_result(a);
  std::vector<BearingValues> bearings;
  for (std::size_t i = 0; i < r.supports.size(); ++i) {
    BearingValues& b = bearings.emplace_back();
    b.label = a.model().forces[static_cast<std::size_t>(r.supports[i].first)].label();
    for (const OperatingValue& v : r.support_data[i]) {
      b.quantities.push_back(v.name);
      if (v.name == q.value) b.values.push_back(v.value);
    }
  }
  return extreme_bearing_value(q, smallest, bearings, " at the equilibrium");
}

}  // namespace

const std::vector<QuantityRow>& StaticAnalysis::quantities() {
  static const std::vector<QuantityRow> rows = {
      {.name = "static_deflection",
       .doc = "lateral static deflection √(v² + w²) at a probe, else the largest of every node",
       .analysis = name,
       .unit = Quantity::length,
       .evaluate = static_deflection},
      {.name = "static_stress",
       .doc = "largest equivalent (von Mises) static shaft stress",
       .analysis = name,
       .unit = Quantity::pressure,
       .evaluate = static_stress},
      {.name = "static_spring_force",
       .doc = "lateral static force of a spring (or the largest of all)",
       .analysis = name,
       .unit = Quantity::force,
       .evaluate = static_spring_force},
      {.name = "min_static_bearing_value",
       .doc = "smallest value of a bearing's operating quantity at the static equilibrium (of all bearings, or of "
              "the one named)",
       .analysis = name,
       .evaluate = static_bearing_value<true>,
       .bearing_value = true},
      {.name = "max_static_bearing_value",
       .doc = "largest value of it",
       .analysis = name,
       .evaluate = static_bearing_value<false>,
       .bearing_value = true},
  };
  return rows;
}

}  // namespace feran

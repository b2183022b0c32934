// The periodic orbits' writers: the JSON, the CSV and the terminal report
// (analyses/periodic/analysis.hpp; the formats in docs/output-format.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/periodic/analysis.hpp>
#include <feran/core/units.hpp>

#include "../../io/result_text.hpp"

namespace feran {

using Json = nlohmann::json;
using namespace detail;  // NOLINT(google-build-using-namespace): the writers' shared vocabulary (result_text.hpp)

namespace {

// The fastest growth of a state's disturbances [1/s]: the largest real part of its
// exponents, the orbit's phase exponent left out.
Real growth_rate(const SteadyState& s) {
  Real g = -std::numeric_limits<Real>::infinity();
  for (Index j = 0; j < s.floquet.exponents.size(); ++j)
    if (j != s.floquet.trivial) g = std::max(g, s.floquet.exponents(j).real());
  return g;
}

Json probes_json(const std::vector<ProbeOrbit>& probes) {
  Json out = Json::array();
  for (const ProbeOrbit& p : probes)
    out.push_back({{"mean_v_m", p.mean_v},
                   {"mean_w_m", p.mean_w},
                   {"amplitude_m", p.amplitude},
                   {"largest_m", p.largest},
                   {"v_m", std::vector<Real>(p.v.begin(), p.v.end())},
                   {"w_m", std::vector<Real>(p.w.begin(), p.w.end())}});
  return out;
}

Json state_json(const SteadyState& s, const std::vector<ProbeOrbit>& probes) {
  return {{"parameter", s.parameter},
          {"speed_hz", rad_to_hz(s.speed)},
          {"frequency_hz", rad_to_hz(s.frequency)},
          {"stable", s.stable},
          {"largest_multiplier", json_number(s.floquet.largest)},
          {"growth_rate_per_s", json_number(growth_rate(s))},
          {"truncation", s.truncation},
          {"residual", s.residual},
          {"probes", probes_json(probes)}};
}

Json branch_json(const OrbitsBranch& b) {
  Json j = {{"name", b.name},
            {"kind", branch_kind_name(b.branch.kind)},
            {"ended_by", b.branch.ended_by},
            {"clipped", b.branch.clipped},
            {"criticality", b.branch.criticality.empty() ? Json(nullptr) : Json(b.branch.criticality)},
            {"harmonics", b.branch.fourier.harmonics}};
  Json points = Json::array();
  for (std::size_t k = 0; k < b.branch.orbits.size(); ++k)
    points.push_back(state_json(b.branch.orbits[k], b.probes[k]));
  j["points"] = points;
  Json bifurcations = Json::array();
  for (std::size_t k = 0; k < b.branch.bifurcations.size(); ++k) {
    const Bifurcation& f = b.branch.bifurcations[k];
    Json jf = state_json(f.at, b.bifurcation[k]);
    jf["kind"] = bifurcation_name(f.kind);
    jf["critical_frequency_hz"] = rad_to_hz(critical_frequency(f));
    jf["after"] = f.after;
    bifurcations.push_back(jf);
  }
  j["bifurcations"] = bifurcations;
  return j;
}

}  // namespace

std::string OrbitsAnalysis::json(const Outcome<OrbitsAnalysis>& o) {
  const OrbitsOptions& options = o.options;
  const OrbitsResult& result = o.result;
  Json j = header("orbits", o.source);
  const bool speed = !options.build;
  j["parameter"] = {{"path", speed ? Json("speed") : Json(options.parameter)},
                    {"from", options.from},
                    {"to", options.to},
                    {"unit", speed                        ? std::string("rad/s")
                             : options.parameter_quantity ? std::string(si_unit(*options.parameter_quantity))
                                                          : std::string()}};
  j["speed_hz"] = speed ? Json(nullptr) : Json(rad_to_hz(options.speed));
  j["branch"] = result.branch;
  j["harmonics"] = options.fourier.harmonics;
  j["samples"] = options.fourier.samples;
  j["modes"] = options.modes;
  j["dofs"] = result.dofs;
  j["coordinates"] = result.coordinates;
  Json probes = Json::array();
  for (const Index node : options.probes) probes.push_back(node_json(o.model(), node));
  j["probes"] = probes;
  j["solver"] = solver_json(result.info);
  j["start_at"] = options.start_at ? Json(*options.start_at) : Json(nullptr);
  if (const auto& r = result.settled)
    j["run"] = {{"parameter", r->start.parameter},
                {"speed_hz", rad_to_hz(r->start.speed)},
                {"kind", branch_kind_name(r->kind)},
                {"settled_after_s", r->time},
                {"frequency_hz", rad_to_hz(r->start.frequency)},
                {"mismatch", r->mismatch}};
  else
    j["run"] = nullptr;
  Json branches = Json::array();
  for (const OrbitsBranch& b : result.branches) branches.push_back(branch_json(b));
  j["branches"] = branches;
  return json_text(j, 2);
}

std::string OrbitsAnalysis::csv(const Outcome<OrbitsAnalysis>& o) {
  const Model& model = o.model();
  std::ostringstream out;
  out << "branch,kind,point,parameter,speed_hz,frequency_hz,stable,largest_multiplier,growth_rate_per_s,truncation";
  for (const Index node : o.options.probes) {
    const std::string tag = csv_node_tag(model, node);
    for (const char* what : {"_amplitude_m", "_largest_m", "_mean_v_m", "_mean_w_m"})
      out << ',' << csv_column(tag, what);
  }
  out << '\n';
  const auto row = [&](const std::string& branch, const std::string& kind, const std::string& point,
                       const SteadyState& s, const std::vector<ProbeOrbit>& probes) {
    out << csv_field(branch) << ',' << kind << ',' << point << ',' << csv_number(s.parameter) << ','
        << csv_number(rad_to_hz(s.speed)) << ',' << csv_number(rad_to_hz(s.frequency)) << ',' << (s.stable ? 1 : 0)
        << ',' << csv_number(s.floquet.largest) << ',' << csv_number(growth_rate(s)) << ',' << csv_number(s.truncation);
    for (const ProbeOrbit& p : probes)
      out << ',' << csv_number(p.amplitude) << ',' << csv_number(p.largest) << ',' << csv_number(p.mean_v) << ','
          << csv_number(p.mean_w);
    out << '\n';
  };
  for (const OrbitsBranch& b : o.result.branches)
    for (std::size_t k = 0; k < b.branch.orbits.size(); ++k)
      row(b.name, "orbit", fmt::format("{}", k), b.branch.orbits[k], b.probes[k]);
  for (const OrbitsBranch& b : o.result.branches)
    for (std::size_t k = 0; k < b.branch.bifurcations.size(); ++k)
      row(b.name, bifurcation_name(b.branch.bifurcations[k].kind), "", b.branch.bifurcations[k].at, b.bifurcation[k]);
  return out.str();
}

namespace {

// The branch's parameter as the terminal shows it.
std::string parameter_text(const OrbitsOptions& o, Real p, const std::string& unit) {
  if (!o.build) return speed_short(p, unit);
  return o.parameter_quantity ? format_quantity(p, *o.parameter_quantity, o.parameter_unit) : fmt::format("{:.6g}", p);
}

// The stretches of a branch where its states are stable or unstable.
std::string stretches(const OrbitsBranch& b, const OrbitsOptions& o, const std::string& unit) {
  std::string out;
  const std::vector<SteadyState>& s = b.branch.orbits;
  std::size_t start = 0;
  for (std::size_t k = 1; k <= s.size(); ++k) {
    if (k < s.size() && s[k].stable == s[start].stable) continue;
    out += fmt::format("  {:<8} from {} to {}\n", s[start].stable ? "stable" : "UNSTABLE",
                       parameter_text(o, s[start].parameter, unit), parameter_text(o, s[k - 1].parameter, unit));
    start = k;
  }
  return out;
}

std::string branch_text(const OrbitsBranch& b, const OrbitsOptions& o, const Model& model, const std::string& unit) {
  const OrbitBranch& br = b.branch;
  std::string out = fmt::format("\n{}: {} steady states{}", b.name, br.orbits.size(),
                                br.criticality.empty() ? "" : ", " + br.criticality);
  out += br.clipped ? ", to the range's end\n" : fmt::format(", ended: {}\n", br.ended_by);
  out += stretches(b, o, unit);
  for (const Bifurcation& f : br.bifurcations)
    out += fmt::format("  {} at {}{}\n", bifurcation_name(f.kind),
                       o.build ? parameter_text(o, f.at.parameter, unit) : speed_text(f.at.parameter, unit),
                       critical_frequency(f) > 0 ? fmt::format(", growing motion at {}",
                                                               frequency_text(rad_to_hz(critical_frequency(f)), unit))
                                                 : std::string());
  const bool speed = !o.build;
  out += fmt::format("  {:>16} {:>12} {:>8} {:>11}", speed ? speed_header(unit) : "parameter",
                     "freq. [" + frequency_unit(unit) + "]", "stable", "largest|mu|");
  for (const Index node : o.probes) out += fmt::format(" {:>14}", csv_node_tag(model, node).substr(0, 9) + " [um]");
  out += '\n';
  const std::size_t n = br.orbits.size(), every = std::max<std::size_t>(1, (n + 19) / 20);
  for (std::size_t k = 0; k < n; ++k) {
    if (k % every != 0 && k + 1 != n) continue;
    const SteadyState& s = br.orbits[k];
    out += fmt::format("  {:>16} {} {:>8} {}",
                       speed ? speed_number(s.parameter, unit) : parameter_text(o, s.parameter, unit),
                       cell(frequency_value(rad_to_hz(s.frequency), unit), ".5g", 12, 5), s.stable ? "yes" : "NO",
                       cell(s.floquet.largest, ".6f", 11, 6));
    for (const ProbeOrbit& p : b.probes[k]) out += " " + cell(1e6 * p.amplitude, ".4g", 14, 4);
    out += '\n';
  }
  return out;
}

}  // namespace

std::string OrbitsAnalysis::terminal(const Outcome<OrbitsAnalysis>& o) {
  const OrbitsOptions& options = o.options;
  const OrbitsResult& result = o.result;
  const std::string& unit = o.source.speed_unit;
  std::string out = source_line("orbits", o.source);
  out += fmt::format("{} branches, {} harmonics on {} samples, {} DOFs condensed to {} coordinates\n", result.branch,
                     options.fourier.harmonics, options.fourier.samples, result.dofs, result.coordinates);
  if (options.build)
    out += fmt::format("parameter {} from {} to {} at {}\n", options.parameter,
                       parameter_text(options, options.from, unit), parameter_text(options, options.to, unit),
                       speed_text(options.speed, unit));
  else
    out += fmt::format("speeds from {} to {}\n", speed_text(options.from, unit), speed_text(options.to, unit));
  if (const auto& r = result.settled)
    out += fmt::format(
        "a run at {} settled after {:.4g} s on a {} orbit at {} (one period repeats it within {:.2g}): the branch "
        "goes through it\n",
        options.build ? parameter_text(options, r->start.parameter, unit) : speed_text(r->start.speed, unit), r->time,
        r->kind == OrbitBranch::Kind::forced ? "forced" : "self-excited",
        frequency_text(rad_to_hz(r->start.frequency), unit), r->mismatch);
  out += "amplitude: the largest distance of the orbit from its centre at each probe\n";
  for (const OrbitsBranch& b : result.branches) out += branch_text(b, options, o.model(), unit);
  return out;
}

}  // namespace feran

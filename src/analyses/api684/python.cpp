// The API 617 / API 684 analyses' Python result: the cases' unbalance responses with
// their amplification factors and separation margins, the undamped critical speed map
// and the level I stability sweep (analysis_binding.hpp binds feran.api684 and what
// every result has).
#include <atomic>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include <feran/analyses/api684/analysis.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

using PyApi684Result = Outcome<Api684Analysis>;

py::object optional_value(const std::optional<Real>& x) { return x ? py::cast(*x) : py::none(); }

std::string element_label(const Model& model, Index e) { return linearised_element_name(model, e); }

py::dict case_dict(const Api684Case& c, const Model& model) {
  py::dict d;
  d["name"] = c.name;
  d["passes"] = c.passes;
  d["mode_frequency_hz"] = c.mode ? py::cast(c.mode->frequency_hz) : py::none();
  d["mode_log_decrement"] = c.mode ? py::cast(c.mode->log_decrement) : py::none();
  py::list unbalances;
  for (const PlacedUnbalance& u : c.unbalances) {
    py::dict du;
    du["node"] = node_name(model, u.node);
    du["amount"] = u.amount;
    du["phase"] = u.phase;
    du["journal_mass"] = u.mass;
    du["basis"] = u.basis;
    unbalances.append(du);
  }
  d["unbalances"] = unbalances;
  d["speeds"] = array_1d(c.response.speeds.size(), [&](std::size_t k) { return c.response.speeds[k]; });
  d["probes"] =
      string_list(c.response.probes.size(), [&](std::size_t p) { return node_name(model, c.response.probes[p].node); });
  d["amplitude"] = array_2d(c.response.probes.size(), c.response.speeds.size(), [&](std::size_t p, std::size_t k) {
    return k < c.response.probes[p].orbit.size() ? c.response.probes[p].orbit[k].major : std::nan("");
  });
  py::list peaks;
  for (std::size_t p = 0; p < c.checks.size(); ++p)
    for (const SeparationCheck& k : c.checks[p]) {
      py::dict dk;
      dk["probe"] = node_name(model, c.response.probes[p].node);
      dk["speed"] = k.peak.speed;
      dk["amplitude"] = k.peak.amplitude;
      dk["lower_half_power"] = optional_value(k.peak.lower_half_power);
      dk["upper_half_power"] = optional_value(k.peak.upper_half_power);
      dk["amplification_factor"] = k.peak.resolved() ? py::cast(k.peak.amplification_factor) : py::none();
      dk["actual_margin"] = k.actual_margin;
      dk["required_margin"] = optional_value(k.required_margin);
      dk["passes"] = k.passes ? py::cast(*k.passes) : py::none();
      dk["unstable"] = k.unstable;
      peaks.append(dk);
    }
  d["peaks"] = peaks;
  return d;
}

py::object map_dict(const std::optional<CriticalSpeedMapResult>& map, const Model& model) {
  if (!map) return py::none();
  py::dict d;
  d["stiffness"] = array_1d(map->stiffness.size(), [&](std::size_t i) { return map->stiffness[i]; });
  const std::size_t nc = map->criticals.empty() ? 0 : map->criticals.front().size();
  d["criticals"] =
      array_2d(map->stiffness.size(), nc, [&](std::size_t i, std::size_t n) { return map->criticals[i][n]; });
  py::list curves;
  for (const BearingCurve& c : map->curves) {
    py::dict dc;
    dc["bearing"] = element_label(model, c.element);
    dc["direction"] = c.direction;
    dc["speeds"] = array_1d(c.speeds.size(), [&](std::size_t i) { return c.speeds[i]; });
    dc["stiffness"] = array_1d(c.stiffness.size(), [&](std::size_t i) { return c.stiffness[i]; });
    curves.append(dc);
  }
  d["curves"] = curves;
  py::list crossings;
  for (const MapIntersection& x : map->intersections) {
    py::dict dx;
    dx["bearing"] = element_label(model, x.element);
    dx["direction"] = x.direction;
    dx["critical"] = x.critical;
    dx["speed"] = x.speed;
    dx["stiffness"] = x.stiffness;
    crossings.append(dx);
  }
  d["intersections"] = crossings;
  return d;
}

py::object stability_dict(const std::optional<StabilitySweepResult>& s, const Model& model) {
  if (!s) return py::none();
  py::dict d;
  d["node"] = node_name(model, s->node);
  d["speed"] = s->speed;
  d["q"] = array_1d(s->q.size(), [&](std::size_t i) { return s->q[i]; });
  d["log_decrement"] = array_1d(s->log_decrement.size(), [&](std::size_t i) { return s->log_decrement[i]; });
  d["frequency_hz"] = array_1d(s->frequency_hz.size(), [&](std::size_t i) { return s->frequency_hz[i]; });
  d["q_zero"] = optional_value(s->q_zero);
  d["anticipated"] = optional_value(s->anticipated);
  d["log_decrement_at_anticipated"] = optional_value(s->log_decrement_at_anticipated);
  d["screening_passes"] = s->screening_passes ? py::cast(*s->screening_passes) : py::none();
  return d;
}

}  // namespace

template <>
void bind_result<Api684Analysis>(py::class_<Outcome<Api684Analysis>>& result) {
  result
      .def_property_readonly(
          "min_speed", [](const PyApi684Result& r) { return r.result.low; }, "[rad/s]")
      .def_property_readonly(
          "max_speed", [](const PyApi684Result& r) { return r.result.high; }, "[rad/s]")
      .def_property_readonly(
          "journal_loads",
          [](const PyApi684Result& r) {
            py::list out;
            for (const JournalLoad& j : r.result.journals) {
              py::dict d;
              d["bearing"] = element_label(r.model(), j.element);
              d["node"] = node_name(r.model(), j.node);
              d["force"] = j.force;
              d["mass"] = j.mass;
              out.append(d);
            }
            return out;
          },
          "per bearing: its static lateral load 'force' [N] and 'mass' = force/g [kg], the W of 4W/N")
      .def_property_readonly(
          "undamped_criticals",
          [](const PyApi684Result& r) {
            return array_1d(r.result.undamped.size(), [&](std::size_t i) { return r.result.undamped[i].speed; });
          },
          "forward undamped critical speeds with the bearings as given [rad/s]")
      .def_property_readonly(
          "cases",
          [](const PyApi684Result& r) {
            py::list out;
            for (const Api684Case& c : r.result.cases) out.append(case_dict(c, r.model()));
            return out;
          },
          "per unbalance case: name, passes, unbalances, speeds [rad/s], probes, amplitude\n"
          "(probes × speeds, orbit semi-major axis [m]) and peaks (speed, amplification_factor,\n"
          "actual_margin, required_margin, passes, …)")
      .def_property_readonly(
          "passes",
          [](const PyApi684Result& r) {
            for (const Api684Case& c : r.result.cases)
              if (!c.passes) return false;
            return true;
          },
          "every judged resonance peak keeps the separation margin API 617 requires")
      .def_property_readonly(
          "operating_stability",
          [](const PyApi684Result& r) {
            const OperatingStability& v = r.result.stability_verdict;
            py::dict d;
            d["passes"] = v.passes;
            d["reason"] = v.reason;
            d["speeds"] = array_1d(v.points.size(), [&](std::size_t i) { return v.points[i].speed; });
            d["unstable"] = array_1d(v.points.size(), [&](std::size_t i) {
              return v.points[i].known ? (v.points[i].unstable ? 1.0 : 0.0) : NAN;
            });
            d["growth_rate"] = array_1d(v.points.size(), [&](std::size_t i) { return v.points[i].growth_rate; });
            return d;
          },
          "the stability verdict over the operating range: passes, reason, speeds [rad/s], unstable\n"
          "(1/0, NaN unknown) and growth_rate [1/s] at 11 speeds from the minimum to the maximum\n"
          "continuous speed")
      .def_property_readonly(
          "map", [](const PyApi684Result& r) { return map_dict(r.result.map, r.model()); },
          "the undamped critical speed map: stiffness [N/m], criticals (stiffness × n)\n"
          "[rad/s], curves and intersections; None without it")
      .def_property_readonly(
          "stability", [](const PyApi684Result& r) { return stability_dict(r.result.stability, r.model()); },
          "level I stability: q [N/m], log_decrement, q_zero, anticipated,\n"
          "screening_passes; None without it");
}

}  // namespace feran::python

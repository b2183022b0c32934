// The API 617 / API 684 lateral analyses: unbalance responses to the analytical
// unbalance with amplification factors and separation margins, the undamped critical
// speed map and the level I stability sweep, as feran api684 computes them.
#include <atomic>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

#include "bindings.hpp"

namespace feran::python {

namespace {

struct PyApi684Result {
  ResultContext context;
  Api684Options options;
  Api684Result result;
  const Model& model() const { return context.file->model; }
};

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

std::optional<double> optional_stiffness(const py::object& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(value)) return parse_quantity(value.cast<std::string>(), Quantity::stiffness);
  try {
    return value.cast<double>();
  } catch (const py::cast_error&) {
    throw Error(std::string(name) + ": give a stiffness as a number in N/m or as text with its unit ('2 MN/m')");
  }
}

}  // namespace

void bind_api684(py::module_& m) {
  py::class_<PyApi684Result>(m, "Api684Result", "The API 617 / API 684 lateral analyses (feran api684)")
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
          "screening_passes; None without it")
      .def_property_readonly("warnings", [](const PyApi684Result& r) { return r.context.source.warnings; })
      .def(
          "to_json", [](const PyApi684Result& r) { return api684_json(r.result, r.model(), r.context.source); },
          "The JSON text that feran api684 --json writes (docs/output-format.md)")
      .def("report", [](const PyApi684Result& r) { return api684_report(r.result, r.model(), r.context.source); });

  m.def(
      "api684",
      [](const PyModel& model, const py::object& min_speed, const py::object& max_speed, const py::object& stop,
         std::optional<int> points, std::optional<int> modes, std::optional<std::string> unbalance,
         std::optional<double> unbalance_multiple, const py::object& probes, const py::object& bearings, bool map,
         const py::object& map_low, const py::object& map_high, std::optional<int> map_points, bool stability,
         const py::object& stability_node, const py::object& anticipated_q, int threads) {
        auto file = std::make_shared<const ModelFile>(model.built());
        Api684Request request;
        request.min_speed = optional_speed(min_speed, "min_speed");
        request.max_speed = optional_speed(max_speed, "max_speed");
        request.stop = optional_speed(stop, "stop");
        request.points = points;
        request.modes = modes;
        if (unbalance) {
          if (*unbalance != "4W/N" && *unbalance != "model")
            throw Error("unbalance: must be '4W/N' or 'model', got '" + *unbalance + "'");
          request.model_unbalance = *unbalance == "model";
        }
        request.unbalance_multiple = unbalance_multiple;
        request.probes = node_arguments(file->model, probes, "probes");
        for (const std::string& b : text_arguments(bearings, "bearings"))
          request.bearings.push_back(bearing_element(file->model, b));
        request.map = map;
        request.map_low = optional_stiffness(map_low, "map_low");
        request.map_high = optional_stiffness(map_high, "map_high");
        request.map_points = map_points;
        request.stability = stability;
        const auto nodes = node_arguments(file->model, stability_node, "stability_node");
        if (nodes.size() > 1) throw Error("stability_node: give one node");
        if (!nodes.empty()) request.stability_node = nodes.front();
        request.anticipated_q = optional_stiffness(anticipated_q, "anticipated_q");
        request.n_threads = threads;
        PyApi684Result out{{}, api684_settings(file->model, file->spec, request), {}};
        out.context = result_context(file, out.options.speeds.front(), out.options.speeds.back());
        std::atomic<bool> flag{false};
        out.options.stop = StopToken(flag);
        bool interrupted = false;
        run_watched([&] { out.result = run_api684(file->model, out.options); }, flag, interrupted);
        if (interrupted) raise_interrupted(py::cast(std::move(out)));
        return out;
      },
      py::arg("model"), py::kw_only(), py::arg("min_speed") = py::none(), py::arg("max_speed") = py::none(),
      py::arg("stop") = py::none(), py::arg("points") = py::none(), py::arg("modes") = py::none(),
      py::arg("unbalance") = py::none(), py::arg("unbalance_multiple") = py::none(), py::arg("probes") = py::none(),
      py::arg("bearings") = py::none(), py::arg("map") = true, py::arg("map_low") = py::none(),
      py::arg("map_high") = py::none(), py::arg("map_points") = py::none(), py::arg("stability") = true,
      py::arg("stability_node") = py::none(), py::arg("anticipated_q") = py::none(), py::arg("threads") = 0,
      "The API 617 / API 684 lateral analyses, as feran api684: min_speed and max_speed (the\n"
      "operating range; '9000 rpm' or rad/s), unbalance '4W/N' (default) or 'model', the map's\n"
      "stiffness range, the level I stability node and anticipated_q ('2 MN/m' or N/m).\n"
      "Unset options come from the model's [api684] table (docs/model-format.md).");
}

}  // namespace feran::python

// Run-ups: time integration along a speed profile, the samples as numpy arrays
// (probe × sample × DOF), the |r| envelopes over speed and the integrator's work.
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <feran/analyses/settings.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/runup_writer.hpp>

#include "bindings.hpp"

namespace feran::python {

namespace {

struct PyRunupResult {
  ResultContext context;
  TransientOptions options;
  TransientResult result;
  const Model& model() const { return context.file->model; }
  std::size_t samples() const { return result.samples.size(); }
};

std::vector<std::pair<Real, Real>> table_argument(const py::handle& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value)) return parse_speed_table_text(value.cast<std::string>(), "table");
  std::vector<std::pair<Real, Real>> out;
  for (const py::handle& point : py::iter(value)) {
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    if (py::len(pair) != 2) throw Error("table: each point is (time, speed), e.g. [(0, '0 Hz'), ('5 s', '80 Hz')]");
    const py::object t = pair[0];
    const double time =
        py::isinstance<py::str>(t) ? parse_quantity(t.cast<std::string>(), Quantity::time) : t.cast<double>();
    out.emplace_back(time, speed_argument(pair[1], "table"));
  }
  return out;
}

}  // namespace

void bind_runup(py::module_& m) {
  py::class_<PyRunupResult>(m, "RunupResult", "A run-up: samples over time, envelopes over speed")
      .def_property_readonly(
          "time",
          [](const PyRunupResult& r) {
            return array_1d(r.samples(), [&](std::size_t k) { return r.result.samples[k].t; });
          },
          "sample times [s]")
      .def_property_readonly(
          "speed",
          [](const PyRunupResult& r) {
            return array_1d(r.samples(), [&](std::size_t k) { return r.result.samples[k].speed; });
          },
          "rotor speed at each sample [rad/s]")
      .def_property_readonly(
          "bearings", [](const PyRunupResult& r) { return bearing_labels(r.result.operating, r.model()); },
          "the bearings (journal and rolling) by their names")
      .def_property_readonly(
          "bearing_data", [](const PyRunupResult& r) { return bearing_data(r.result.operating); },
          "per bearing (as bearings), its operating state in the motion at each sample: a dict of numpy\n"
          "arrays over the samples, named with their units as in static's bearing_data")
      .def_property_readonly(
          "bearing_clearance_ratio",
          [](const PyRunupResult& r) {
            py::list out;
            for (const ClearanceUse& u : r.result.clearance_use) {
              py::dict d;
              d["bearing"] = r.model().forces[static_cast<std::size_t>(u.force)].label();
              d["clearance_m"] = u.clearance;
              d["largest"] = u.largest;
              d["time"] = u.time;
              d["speed"] = u.speed;
              d["speed_hz"] = rad_to_hz(u.speed);
              d["speed_rpm"] = 60.0 * rad_to_hz(u.speed);
              out.append(d);
            }
            return out;
          },
          "per bearing with a clearance: the largest excursion of its journal relative to its housing over\n"
          "the run (every step), as a fraction of the clearance (largest), with when (time [s]) and at\n"
          "which speed [rad/s]")
      .def_property_readonly("probes",
                             [](const PyRunupResult& r) {
                               return string_list(r.options.probes.size(), [&](std::size_t i) {
                                 return node_name(r.model(), r.options.probes[i]);
                               });
                             })
      .def_property_readonly(
          "displacement",
          [](const PyRunupResult& r) {
            return array_3d(
                r.options.probes.size(), r.samples(), dofs_per_node,
                [&](std::size_t i, std::size_t k, std::size_t d) { return r.result.samples[k].probes[i][d]; });
          },
          "u, v, w, rx, ry, rz of each probe [m, rad], shape (probes, samples, 6)")
      .def_property_readonly(
          "magnitude",
          [](const PyRunupResult& r) {
            return array_2d(r.options.probes.size(), r.samples(),
                            [&](std::size_t i, std::size_t k) { return r.result.samples[k].magnitude[i]; });
          },
          "|r| = sqrt(v² + w²) of each probe [m], shape (probes, samples)")
      .def_property_readonly("springs",
                             [](const PyRunupResult& r) {
                               return string_list(r.options.springs.size(), [&](std::size_t i) {
                                 return r.model().elements[static_cast<std::size_t>(r.options.springs[i])].label();
                               });
                             })
      .def_property_readonly(
          "spring_force",
          [](const PyRunupResult& r) {
            return array_3d(
                r.options.springs.size(), r.samples(), dofs_per_node,
                [&](std::size_t i, std::size_t k, std::size_t d) { return r.result.samples[k].springs[i][d]; });
          },
          "force of each recorded spring-damper [N, N m], shape (springs, samples, 6)")
      .def_property_readonly(
          "envelope_speed",
          [](const PyRunupResult& r) {
            const std::size_t bins = r.result.envelopes.empty() ? 0 : r.result.envelopes[0].speed.size();
            return array_1d(bins, [&](std::size_t b) { return r.result.envelopes[0].speed[b]; });
          },
          "centres of the speed bins of the envelopes [rad/s]")
      .def_property_readonly(
          "envelope",
          [](const PyRunupResult& r) {
            const std::size_t bins = r.result.envelopes.empty() ? 0 : r.result.envelopes[0].magnitude.size();
            return array_2d(r.result.envelopes.size(), bins,
                            [&](std::size_t i, std::size_t b) { return r.result.envelopes[i].magnitude[b]; });
          },
          "largest |r| of each probe in each speed bin, from every step [m], NaN where never visited")
      .def_property_readonly(
          "peaks",
          [](const PyRunupResult& r) {
            py::list out;
            for (std::size_t i = 0; i < r.result.envelopes.size(); ++i) {
              const Envelope& e = r.result.envelopes[i];
              py::dict d;
              d["probe"] = node_name(r.model(), r.options.probes[i]);
              d["peak"] = e.peak;
              d["time"] = e.peak_time;
              d["speed"] = e.peak_speed;
              d["speed_hz"] = rad_to_hz(e.peak_speed);
              out.append(d);
            }
            return out;
          },
          "per probe: the largest |r| of the run [m], when [s] and at what speed [rad/s]")
      .def_property_readonly("t_end", [](const PyRunupResult& r) { return r.result.t_end; })
      .def_property_readonly("steps", [](const PyRunupResult& r) { return r.result.steps; })
      .def_property_readonly("rejected", [](const PyRunupResult& r) { return r.result.rejected; })
      .def_property_readonly("integrator", [](const PyRunupResult& r) { return r.options.integrator; })
      .def_property_readonly(
          "complete", [](const PyRunupResult& r) { return r.result.info.converged(); },
          "False when the run stopped early (failure, blow-up, interrupt); samples so far kept")
      .def_property_readonly("message", [](const PyRunupResult& r) { return r.result.info.message; })
      .def_property_readonly("warning", [](const PyRunupResult& r) { return r.result.warning; })
      .def_property_readonly("warnings", [](const PyRunupResult& r) { return r.context.source.warnings; })
      .def(
          "to_json",
          [](const PyRunupResult& r) { return runup_json(r.result, r.options, r.model(), r.context.source); },
          "The JSON text that feran runup --json writes (docs/output-format.md)")
      .def("report",
           [](const PyRunupResult& r) { return runup_report(r.result, r.options, r.model(), r.context.source); });

  m.def(
      "runup",
      [](const PyModel& model, const py::object& speed, const py::object& from, const py::object& to,
         const py::object& ramp_time, const py::object& table, const py::object& duration,
         std::optional<std::string> integrator, const py::object& dt, std::optional<double> rtol,
         std::optional<double> atol, const py::object& output_interval, const py::object& probes,
         const py::object& springs, std::optional<double> newton_tol, std::optional<int> newton_max_iter,
         bool allow_unstable, const std::string& jacobian, std::optional<int> jacobian_interval,
         const py::object& blowup, std::optional<int> modes, bool static_loads, bool gravity,
         std::optional<std::string> start, std::optional<bool> drive) {
        auto file = std::make_shared<const ModelFile>(model.built());
        const Model& built = file->model;
        RunupRequest request;
        request.speed = optional_speed(speed, "speed");
        request.from = optional_speed(from, "from");
        request.to = optional_speed(to, "to");
        request.ramp_time = optional_time(ramp_time, "ramp_time");
        request.table = table_argument(table);
        request.duration = optional_time(duration, "duration");
        request.integrator = std::move(integrator);
        request.dt = optional_time(dt, "dt");
        request.rel_tol = rtol;
        request.abs_tol = atol;
        request.output_interval = optional_time(output_interval, "output_interval");
        request.probes = node_arguments(built, probes, "probe");
        for (const std::string& name : text_arguments(springs, "spring")) {
          try {
            request.springs.push_back(spring_element(built, name));
          } catch (const Error&) {
            throw Error(fmt::format("spring '{}': no spring-damper has that name", name));
          }
        }
        request.newton_tol = newton_tol;
        request.newton_max_iterations = newton_max_iter;
        request.allow_unstable_step = allow_unstable;
        if (jacobian != "exact" && jacobian != "linear")
          throw Error(fmt::format("jacobian='{}': expected 'exact' or 'linear'", jacobian));
        request.exact_jacobian = jacobian == "exact";
        if (jacobian_interval) request.jacobian_interval = jacobian_interval;
        if (!blowup.is_none())
          request.blowup_limit = py::isinstance<py::str>(blowup)
                                     ? parse_quantity(blowup.cast<std::string>(), Quantity::length)
                                     : blowup.cast<double>();
        request.modes = modes;
        request.static_loads = static_loads;
        request.gravity = gravity;
        request.start = std::move(start);
        request.drive = drive;
        PyRunupResult out{{}, runup_settings(built, file->spec.runup, request), {}};
        const auto [low, high] = speed_span(built, out.options);
        out.context = result_context(file, low, high);
        std::atomic<bool> flag{false};
        out.options.stop = StopToken(flag);
        bool interrupted = false;
        run_watched([&] { out.result = run_transient(built, out.options); }, flag, interrupted);
        if (interrupted) raise_interrupted(py::cast(std::move(out)));
        // Refused before the first step (rk3 above its stability limit): a bad option.
        if (out.result.info.status == SolverStatus::numerical_failure && out.result.steps == 0)
          throw Error(out.result.info.message);
        return out;
      },
      py::arg("model"), py::kw_only(), py::arg("speed") = py::none(), py::arg("from_") = py::none(),
      py::arg("to") = py::none(), py::arg("ramp_time") = py::none(), py::arg("table") = py::none(),
      py::arg("duration") = py::none(), py::arg("integrator") = py::none(), py::arg("dt") = py::none(),
      py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("output_interval") = py::none(),
      py::arg("probe") = py::none(), py::arg("spring") = py::none(), py::arg("newton_tol") = py::none(),
      py::arg("newton_max_iter") = py::none(), py::arg("allow_unstable") = false, py::arg("jacobian") = "exact",
      py::arg("jacobian_interval") = py::none(), py::arg("blowup") = py::none(), py::arg("modes") = py::none(),
      py::arg("static_loads") = false, py::arg("gravity") = false, py::arg("start") = py::none(),
      py::arg("drive") = py::none(),
      "A run-up, as feran runup. The speed profile is one of: speed (constant); from_, to,\n"
      "ramp_time (a ramp, then held); table [(time, speed), …] or 'TIME:SPEED,…'. Speeds as\n"
      "'80 Hz' or rad/s, times as '5 s' or s. The other keywords are the CLI's options\n"
      "(--rtol → rtol, --newton-max-iter → newton_max_iter, --static-loads → static_loads,\n"
      "--gravity → gravity, --start → start, --drive → drive);\n"
      "unset ones come from the model's [runup] table. A run that stops early (blow-up,\n"
      "failure) returns its samples so far with complete False; Ctrl-C raises\n"
      "feran.Interrupted with them.");
}

}  // namespace feran::python

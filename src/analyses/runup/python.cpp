// The run-up's Python result: the samples as numpy arrays (probe × sample × DOF), the
// |r| envelopes over speed and the integrator's work (analysis_binding.hpp binds
// feran.runup and what every result has).
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/runup/waterfall.hpp>
#include <feran/core/units.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

using PyRunupResult = Outcome<RunupAnalysis>;

std::size_t samples(const PyRunupResult& r) { return r.result.samples.size(); }

}  // namespace

template <>
void bind_result<RunupAnalysis>(py::class_<Outcome<RunupAnalysis>>& result) {
  result
      .def_property_readonly(
          "time",
          [](const PyRunupResult& r) {
            return array_1d(samples(r), [&](std::size_t k) { return r.result.samples[k].t; });
          },
          "sample times [s]")
      .def_property_readonly(
          "speed",
          [](const PyRunupResult& r) {
            return array_1d(samples(r), [&](std::size_t k) { return r.result.samples[k].speed; });
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
                r.options.probes.size(), samples(r), dofs_per_node,
                [&](std::size_t i, std::size_t k, std::size_t d) { return r.result.samples[k].probes[i][d]; });
          },
          "u, v, w, rx, ry, rz of each probe [m, rad], shape (probes, samples, 6)")
      .def_property_readonly(
          "magnitude",
          [](const PyRunupResult& r) {
            return array_2d(r.options.probes.size(), samples(r),
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
                r.options.springs.size(), samples(r), dofs_per_node,
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
      .def(
          "waterfall",
          [](const PyRunupResult& r, std::size_t probe, int dof, std::optional<Real> window, Real overlap) {
            if (dof < 0 || dof >= dofs_per_node) throw py::value_error("dof: expected 0 … 5 (u, v, w, rx, ry, rz)");
            const Waterfall w = waterfall(r.result, probe, static_cast<Dof>(dof), window, overlap);
            return py::make_tuple(
                array_1d(w.speeds.size(), [&](std::size_t k) { return w.speeds[k]; }),
                array_1d(w.frequencies.size(), [&](std::size_t k) { return w.frequencies[k]; }),
                array_2d(static_cast<std::size_t>(w.amplitude.rows()), static_cast<std::size_t>(w.amplitude.cols()),
                         [&](std::size_t i, std::size_t k) {
                           return w.amplitude(static_cast<Index>(i), static_cast<Index>(k));
                         }));
          },
          py::arg("probe") = 0, py::arg("dof") = 1, py::arg("window") = py::none(), py::arg("overlap") = 0.5,
          "the waterfall of DOF dof (0 … 5: u, v, w, rx, ry, rz) of a probe (its index): windows of window\n"
          "seconds (default a twentieth of the run) overlapping by overlap, each with its mean removed and a\n"
          "Hann taper; returns (speed at each window's middle [rad/s], frequencies [Hz], amplitudes of shape\n"
          "(windows, frequencies) as the amplitude of a sine in the DOF's unit) — the report's definition")
      .def_property_readonly("t_end", [](const PyRunupResult& r) { return r.result.t_end; })
      .def_property_readonly("steps", [](const PyRunupResult& r) { return r.result.steps; })
      .def_property_readonly("rejected", [](const PyRunupResult& r) { return r.result.rejected; })
      .def_property_readonly("integrator", [](const PyRunupResult& r) { return r.options.integrator; })
      .def_property_readonly(
          "complete", [](const PyRunupResult& r) { return r.result.info.converged(); },
          "False when the run stopped early (failure, blow-up, interrupt); samples so far kept")
      .def_property_readonly("message", [](const PyRunupResult& r) { return r.result.info.message; })
      .def_property_readonly("warning", [](const PyRunupResult& r) { return r.result.warning; });
}

}  // namespace feran::python

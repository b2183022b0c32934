// The steady-state response's Python result: speed and frequency sweeps, with complex
// amplitudes of probes, spring forces and support reactions as numpy arrays (item ×
// point × DOF), orbits, and shaft stresses (analysis_binding.hpp binds feran.response
// and what every result has).
#include <cmath>
#include <complex>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <feran/analyses/response/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

using PyResponseResult = Outcome<ResponseAnalysis>;

std::size_t points(const PyResponseResult& r) { return r.result.speeds.size(); }

/// Items × points × 6 complex amplitudes.
template <class Items, class Get>
py::array_t<std::complex<double>> amplitudes(const PyResponseResult& r, const Items& items, Get&& get) {
  return array_3d<std::complex<double>>(items.size(), points(r), dofs_per_node,
                                        [&](std::size_t i, std::size_t k, std::size_t d) {
                                          const std::vector<NodeAmplitudes>& v = get(items[i]);
                                          return k < v.size() ? v[k][d] : std::complex<double>(NAN, NAN);
                                        });
}

template <class F>
py::array_t<double> orbit_values(const PyResponseResult& r, F&& value) {
  return array_2d(r.result.probes.size(), points(r), [&](std::size_t i, std::size_t k) {
    const auto& orbit = r.result.probes[i].orbit;
    return k < orbit.size() ? value(orbit[k]) : NAN;
  });
}

template <class F>
py::array_t<double> peak_values(const PyResponseResult& r, F&& peak) {
  return array_1d(r.result.station_peaks.size(), [&](std::size_t k) { return peak(r.result.station_peaks[k]).value; });
}

template <class F>
py::array_t<double> peak_places(const PyResponseResult& r, F&& peak) {
  return array_1d(r.result.station_peaks.size(), [&](std::size_t k) {
    const Index s = peak(r.result.station_peaks[k]).station;
    return s < 0 ? NAN : r.result.shaft_stations[static_cast<std::size_t>(s)].x;
  });
}

// The speeds or frequencies swept and the stability at each.
void bind_sweep(py::class_<PyResponseResult>& result) {
  result.def_property_readonly("frequency_sweep", [](const PyResponseResult& r) { return r.result.frequency_sweep; })
      .def_property_readonly(
          "speeds",
          [](const PyResponseResult& r) {
            return array_1d(points(r), [&](std::size_t k) { return r.result.speeds[k]; });
          },
          "rotor speed per point [rad/s]")
      .def_property_readonly(
          "frequencies",
          [](const PyResponseResult& r) {
            return array_1d(r.result.frequencies.size(), [&](std::size_t k) { return r.result.frequencies[k]; });
          },
          "excitation frequency per point [rad/s] (the speed itself in a speed sweep)")
      .def_property_readonly(
          "unstable",
          [](const PyResponseResult& r) {
            return array_1d(r.result.stability.size(), [&](std::size_t k) {
              const StabilityPoint& p = r.result.stability[k];
              return p.known ? (p.unstable ? 1.0 : 0.0) : NAN;
            });
          },
          "per point: 1 where the rotor is unstable at its speed (the response there is no steady state), 0 "
          "where stable, NaN where unknown; empty when not judged (stability=False)")
      .def_property_readonly(
          "growth_rate",
          [](const PyResponseResult& r) {
            return array_1d(r.result.stability.size(),
                            [&](std::size_t k) { return r.result.stability[k].growth_rate; });
          },
          "per point: the largest real part of a non-rigid eigenvalue [1/s] (> 0: unstable); NaN where the "
          "energy test decided (stable) or unknown")
      .def_property_readonly(
          "first_unstable_speed",
          [](const PyResponseResult& r) -> py::object {
            const Index k = first_unstable_point(r.result);
            if (k < 0) return py::none();
            return py::float_(r.result.stability[static_cast<std::size_t>(k)].speed);
          },
          "the lowest speed of the sweep at which the rotor is unstable [rad/s], or None");
}

// The orbits at the probes.
void bind_probes(py::class_<PyResponseResult>& result) {
  result
      .def_property_readonly(
          "probes",
          [](const PyResponseResult& r) {
            return string_list(r.result.probes.size(),
                               [&](std::size_t i) { return node_name(r.model(), r.result.probes[i].node); });
          },
          "the probe nodes, by name (else number)")
      .def_property_readonly(
          "probe_x",
          [](const PyResponseResult& r) {
            return array_1d(r.result.probes.size(), [&](std::size_t i) {
              return r.model().nodes[static_cast<std::size_t>(r.result.probes[i].node)].x;
            });
          },
          "axial position of each probe [m]")
      .def_property_readonly(
          "displacement",
          [](const PyResponseResult& r) {
            return amplitudes(r, r.result.probes,
                              [](const ProbeResponse& p) -> const std::vector<NodeAmplitudes>& { return p.q; });
          },
          "complex amplitudes of u, v, w, rx, ry, rz [m, rad], shape (probes, points, 6)")
      .def_property_readonly(
          "orbit_major",
          [](const PyResponseResult& r) { return orbit_values(r, [](const Orbit& o) { return o.major; }); },
          "major semi-axis of the (v, w) orbit [m], shape (probes, points)")
      .def_property_readonly(
          "orbit_minor",
          [](const PyResponseResult& r) { return orbit_values(r, [](const Orbit& o) { return o.minor; }); })
      .def_property_readonly(
          "orbit_inclination",
          [](const PyResponseResult& r) { return orbit_values(r, [](const Orbit& o) { return o.inclination; }); },
          "angle of the major axis from +y towards +z [rad]")
      .def_property_readonly(
          "orbit_forward",
          [](const PyResponseResult& r) { return orbit_values(r, [](const Orbit& o) { return o.forward; }); })
      .def_property_readonly(
          "orbit_backward",
          [](const PyResponseResult& r) { return orbit_values(r, [](const Orbit& o) { return o.backward; }); })
      .def(
          "probe_index",
          [](const PyResponseResult& r, const py::object& node) {
            const std::vector<Index> wanted = node_arguments(r.model(), node, "node");
            for (std::size_t i = 0; i < r.result.probes.size(); ++i)
              if (r.result.probes[i].node == wanted.at(0)) return i;
            throw Error(fmt::format("node {}: not a probe of this response", py::repr(node).cast<std::string>()));
          },
          py::arg("node"), "The index in probes of a node (name or number)");
}

// The springs' and bearings' forces and the bearings' operating state.
void bind_supports(py::class_<PyResponseResult>& result) {
  result
      .def_property_readonly(
          "springs",
          [](const PyResponseResult& r) {
            return string_list(r.result.springs.size(), [&](std::size_t i) {
              return r.model().elements[static_cast<std::size_t>(r.result.springs[i].element)].label();
            });
          })
      .def_property_readonly(
          "spring_force",
          [](const PyResponseResult& r) {
            return amplitudes(
                r, r.result.springs,
                [](const SpringForceResponse& s) -> const std::vector<NodeAmplitudes>& { return s.force; });
          },
          "complex force amplitudes of each spring-damper [N, N m], shape (springs, points, 6)")
      .def_property_readonly(
          "spring_peak",
          [](const PyResponseResult& r) {
            return array_2d(r.result.springs.size(), points(r),
                            [&](std::size_t i, std::size_t k) { return r.result.springs[i].peak_lateral[k]; });
          },
          "largest lateral spring force over a period [N], shape (springs, points)")
      .def_property_readonly(
          "bearings",
          [](const PyResponseResult& r) {
            return string_list(r.result.supports.size(), [&](std::size_t i) {
              return r.model().forces[static_cast<std::size_t>(r.result.supports[i].force)].label();
            });
          },
          "journal bearings ([[journal_bearings]] names)")
      .def_property_readonly(
          "bearing_data", [](const PyResponseResult& r) { return bearing_data(r.result.operating); },
          "per bearing (as bearings), its operating state at the equilibrium at each point's speed: a dict\n"
          "of numpy arrays over the points, named with their units as in static's bearing_data\n"
          "(eccentricity_ratio, attitude_angle_deg, min_film_thickness_m, sommerfeld_number,\n"
          "friction_torque_nm, power_loss_w, ...; max_element_load_n, ... for rolling bearings)")
      .def_property_readonly(
          "bearing_force",
          [](const PyResponseResult& r) {
            return amplitudes(
                r, r.result.supports,
                [](const SupportForceResponse& s) -> const std::vector<NodeAmplitudes>& { return s.amplitude; });
          },
          "complex dynamic force each journal bearing transmits [N], shape (bearings, points, 6)")
      .def_property_readonly(
          "bearing_peak",
          [](const PyResponseResult& r) {
            return array_2d(r.result.supports.size(), points(r),
                            [&](std::size_t i, std::size_t k) { return r.result.supports[i].peak_lateral[k]; });
          },
          "largest lateral journal-bearing force over a period [N], shape (bearings, points)")
      .def_property_readonly(
          "bearing_orbit",
          [](const PyResponseResult& r) {
            return array_2d(r.result.supports.size(), points(r),
                            [&](std::size_t i, std::size_t k) { return r.result.supports[i].orbit[k]; });
          },
          "major semi-axis of each journal's orbit relative to its housing [m], shape (bearings, points)")
      .def_property_readonly(
          "bearing_orbit_ratio",
          [](const PyResponseResult& r) {
            return array_2d(r.result.supports.size(), points(r), [&](std::size_t i, std::size_t k) {
              return r.result.supports[i].orbit_clearance_ratio[k];
            });
          },
          "that orbit over the bearing's radial clearance (NaN without one), shape (bearings, points);\n"
          "above 1 the linearised response is no motion the bearing allows (a warning says so)");
}

// The reactions of the fixed DOFs and the shaft's stresses and section forces.
void bind_stations(py::class_<PyResponseResult>& result) {
  result
      .def_property_readonly(
          "reactions",
          [](const PyResponseResult& r) {
            return string_list(r.result.reactions.size(),
                               [&](std::size_t i) { return node_name(r.model(), r.result.reactions[i].node); });
          },
          "nodes with fixed DOFs")
      .def_property_readonly(
          "reaction_force",
          [](const PyResponseResult& r) {
            return amplitudes(r, r.result.reactions,
                              [](const ReactionResponse& s) -> const std::vector<NodeAmplitudes>& { return s.force; });
          },
          "complex support reactions [N, N m], shape (reactions, points, 6)")
      .def_property_readonly("reaction_peak",
                             [](const PyResponseResult& r) {
                               return array_2d(r.result.reactions.size(), points(r), [&](std::size_t i, std::size_t k) {
                                 return r.result.reactions[i].peak_lateral[k];
                               });
                             })
      .def_property_readonly(
          "peak_von_mises",
          [](const PyResponseResult& r) { return peak_values(r, [](const StationPeaks& p) { return p.von_mises; }); },
          "per point: the largest equivalent stress over the shaft stations [Pa]")
      .def_property_readonly(
          "peak_von_mises_x",
          [](const PyResponseResult& r) { return peak_places(r, [](const StationPeaks& p) { return p.von_mises; }); },
          "per point: where along x it is [m]")
      .def_property_readonly("peak_bending_moment",
                             [](const PyResponseResult& r) {
                               return peak_values(r, [](const StationPeaks& p) { return p.bending_moment; });
                             })
      .def_property_readonly(
          "peak_shear_force",
          [](const PyResponseResult& r) { return peak_values(r, [](const StationPeaks& p) { return p.shear_force; }); })
      .def_property_readonly(
          "station_x",
          [](const PyResponseResult& r) {
            return array_1d(r.result.stations.size(), [&](std::size_t s) { return r.result.stations[s].station.x; });
          },
          "with stations='all': the axial position of each station [m]")
      .def_property_readonly(
          "station_von_mises",
          [](const PyResponseResult& r) {
            return array_2d(r.result.stations.size(), points(r),
                            [&](std::size_t s, std::size_t k) { return r.result.stations[s].stress[k].von_mises; });
          },
          "with stations='all': equivalent stress [Pa], shape (stations, points)")
      .def_property_readonly(
          "section_forces",
          [](const PyResponseResult& r) {
            return array_3d<std::complex<double>>(r.result.stations.size(), points(r), 6,
                                                  [&](std::size_t s, std::size_t k, std::size_t c) {
                                                    const SectionForces& f = r.result.stations[s].forces[k];
                                                    const Complex v[6] = {f.N, f.Vy, f.Vz, f.T, f.My, f.Mz};
                                                    return v[c];
                                                  });
          },
          "with stations='all': N, Vy, Vz, T, My, Mz [N, N m], shape (stations, points, 6)");
}

}  // namespace

template <>
void bind_result<ResponseAnalysis>(py::class_<Outcome<ResponseAnalysis>>& result) {
  bind_sweep(result);
  bind_probes(result);
  bind_supports(result);
  bind_stations(result);
  result.def_property_readonly("complete", [](const PyResponseResult& r) { return r.result.info.converged(); })
      .def_property_readonly("message", [](const PyResponseResult& r) { return r.result.info.message; });
}

}  // namespace feran::python

// The static analysis's Python result: deflection of every node, spring and bearing
// forces, support reactions, shaft section forces and stresses as numpy arrays
// (analysis_binding.hpp binds the function feran.static and what every result has).
#include <pybind11/stl.h>

#include <feran/analyses/static/analysis.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

template <>
void bind_result<StaticAnalysis>(py::class_<Outcome<StaticAnalysis>>& result) {
  using R = Outcome<StaticAnalysis>;
  result
      .def_property_readonly(
          "displacement",
          [](const R& r) {
            return array_2d(r.model().nodes.size(), dofs_per_node, [&](std::size_t i, std::size_t d) {
              return r.result.q(static_cast<Index>(dofs_per_node * i + d));
            });
          },
          "u, v, w, rx, ry, rz of every node [m, rad], shape (nodes, 6)")
      .def_property_readonly("springs",
                             [](const R& r) {
                               return string_list(r.result.springs.size(), [&](std::size_t i) {
                                 return r.model().elements[static_cast<std::size_t>(r.result.springs[i].first)].label();
                               });
                             })
      .def_property_readonly(
          "spring_force",
          [](const R& r) {
            return array_2d(r.result.springs.size(), dofs_per_node,
                            [&](std::size_t i, std::size_t d) { return r.result.springs[i].second[d]; });
          },
          "force each spring-damper transmits to its second node or ground, K (q_a - q_b) [N, N m],\n"
          "shape (springs, 6)")
      .def_property_readonly(
          "bearings",
          [](const R& r) {
            return string_list(r.result.supports.size(), [&](std::size_t i) {
              return r.model().forces[static_cast<std::size_t>(r.result.supports[i].first)].label();
            });
          },
          "journal bearings ([[journal_bearings]] names)")
      .def_property_readonly(
          "stability",
          [](const R& r) {
            const StabilityPoint& p = r.result.stability;
            py::dict d;
            d["kind"] = stability_kind(p);
            d["unstable"] = p.known ? py::object(py::bool_(p.unstable)) : py::object(py::none());
            d["growth_rate"] = p.growth_rate;
            d["frequency_hz"] =
                p.unstable && !p.divergence ? py::object(py::float_(p.frequency_hz)) : py::object(py::none());
            d["message"] = stability_phrase(p);
            return d;
          },
          "whether the rotor stays at this equilibrium when disturbed: a dict of kind ('stable',\n"
          "'flutter', 'divergence', 'unknown'), unstable (None: unknown), growth_rate [1/s] (NaN when\n"
          "decided without eigenvalues), frequency_hz of a growing oscillation, and message")
      .def_property_readonly(
          "unstable", [](const R& r) { return r.result.stability.known && r.result.stability.unstable; },
          "True when the equilibrium is unstable (see stability)")
      .def_property_readonly(
          "bearing_data",
          [](const R& r) {
            py::list out;
            for (const auto& data : r.result.support_data) {
              py::dict d;
              for (const OperatingValue& o : data) d[py::str(o.name)] = o.value;
              out.append(d);
            }
            return out;
          },
          "per bearing (as bearings), its operating state at the equilibrium: a dict of numbers whose\n"
          "names carry their units (eccentricity_ratio, attitude_angle_deg, min_film_thickness_m,\n"
          "min_film_angle_deg, load_n, sommerfeld_number, friction_torque_nm, power_loss_w,\n"
          "peak_pressure_pa; for rolling bearings max_element_load_n, loaded_elements,\n"
          "max_contact_stress_pa), as the JSON's supports[].operating")
      .def_property_readonly(
          "bearing_force",
          [](const R& r) {
            return array_2d(r.result.supports.size(), dofs_per_node,
                            [&](std::size_t i, std::size_t d) { return r.result.supports[i].second[d]; });
          },
          "force each journal bearing transmits to its housing or ground at the equilibrium [N], shape (bearings, 6)")
      .def_property_readonly("reactions",
                             [](const R& r) {
                               return string_list(r.result.reactions.size(), [&](std::size_t i) {
                                 return node_name(r.model(), r.result.reactions[i].first);
                               });
                             })
      .def_property_readonly(
          "reaction_force",
          [](const R& r) {
            return array_2d(r.result.reactions.size(), dofs_per_node,
                            [&](std::size_t i, std::size_t d) { return r.result.reactions[i].second[d]; });
          },
          "the force the rotor puts on the support at each node with fixed DOFs [N, N m],\n"
          "shape (reactions, 6); zero in free directions")
      .def_property_readonly("station_x",
                             [](const R& r) {
                               return array_1d(r.result.stations.size(),
                                               [&](std::size_t s) { return r.result.stations[s].x; });
                             })
      .def_property_readonly(
          "section_forces",
          [](const R& r) {
            return array_2d(r.result.stations.size(), 6, [&](std::size_t s, std::size_t c) {
              const SectionForces& f = r.result.section_forces[s];
              const Complex v[6] = {f.N, f.Vy, f.Vz, f.T, f.My, f.Mz};
              return v[c].real();
            });
          },
          "N, Vy, Vz, T, My, Mz at each shaft station [N, N m], shape (stations, 6)")
      .def_property_readonly(
          "von_mises",
          [](const R& r) {
            return array_1d(r.result.stresses.size(), [&](std::size_t s) { return r.result.stresses[s].von_mises; });
          },
          "equivalent stress at each shaft station [Pa]")
      .def_property_readonly(
          "total_load",
          [](const R& r) { return array_1d(dofs_per_node, [&](std::size_t d) { return r.result.total_load[d]; }); },
          "sum of the applied forces and moments about the origin [N, N m]");
}

}  // namespace feran::python

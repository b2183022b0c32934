// The modal analysis's Python result: frequencies, damping, whirl and shapes of the
// modes as numpy arrays (analysis_binding.hpp binds feran.modal and what every result
// has).
#include <complex>

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <feran/analyses/modal/analysis.hpp>

#include "analysis_binding.hpp"

namespace feran::python {

namespace {

template <class F>
py::array_t<double> per_mode(const Outcome<ModalAnalysis>& r, F&& value) {
  py::array_t<double> out(static_cast<py::ssize_t>(r.result.modes.size()));
  auto a = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < r.result.modes.size(); ++i) a(static_cast<py::ssize_t>(i)) = value(r.result.modes[i]);
  return out;
}

}  // namespace

template <>
void bind_result<ModalAnalysis>(py::class_<Outcome<ModalAnalysis>>& result) {
  using R = Outcome<ModalAnalysis>;
  result
      .def_property_readonly(
          "speed", [](const R& r) { return r.result.speed; }, "rotor speed [rad/s]")
      .def_property_readonly("speed_hz", [](const R& r) { return rad_to_hz(r.result.speed); })
      .def_property_readonly(
          "complete", [](const R& r) { return r.result.info.converged(); }, "whether every mode asked for was computed")
      .def_property_readonly("message", [](const R& r) { return r.result.info.message; })
      .def_property_readonly(
          "bearings", [](const R& r) { return bearing_labels(r.result.operating, r.model()); },
          "the bearings (journal and rolling) by their names")
      .def_property_readonly(
          "bearing_data", [](const R& r) { return bearing_data(r.result.operating, true); },
          "per bearing (as bearings), its operating state at the equilibrium at this speed: a dict of\n"
          "numbers named with their units, as static's bearing_data")
      .def_property_readonly(
          "frequency_iterations", [](const R& r) { return r.result.frequency_iterations; },
          "the most eigen solves one mode needed to settle on its own frequency (0 unless a coefficient "
          "depends on the frequency of the motion)")
      .def_property_readonly("frequency_hz",
                             [](const R& r) { return per_mode(r, [](const Mode& x) { return x.frequency_hz; }); })
      .def_property_readonly("damping_ratio",
                             [](const R& r) { return per_mode(r, [](const Mode& x) { return x.damping_ratio; }); })
      .def_property_readonly("log_decrement",
                             [](const R& r) { return per_mode(r, [](const Mode& x) { return x.log_decrement; }); })
      .def_property_readonly("directivity",
                             [](const R& r) { return per_mode(r, [](const Mode& x) { return x.directivity; }); })
      .def_property_readonly(
          "eigenvalues",
          [](const R& r) {
            py::array_t<std::complex<double>> out(static_cast<py::ssize_t>(r.result.modes.size()));
            auto a = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < r.result.modes.size(); ++i)
              a(static_cast<py::ssize_t>(i)) = r.result.modes[i].eigenvalue;
            return out;
          },
          "p = -delta + i omega [1/s]")
      .def_property_readonly("whirl",
                             [](const R& r) {
                               py::list out;
                               for (const Mode& x : r.result.modes) out.append(to_string(x.whirl));
                               return out;
                             })
      .def_property_readonly("type",
                             [](const R& r) {
                               py::list out;
                               for (const Mode& x : r.result.modes) out.append(to_string(x.type));
                               return out;
                             })
      .def_property_readonly(
          "shape",
          [](const R& r) {
            py::list out;
            for (const Mode& x : r.result.modes) out.append(to_string(x.shape_kind));
            return out;
          },
          "per mode: 'cylindrical', 'conical' (rigid on its supports) or 'bending'; 'none'")
      .def_property_readonly(
          "bending",
          [](const R& r) {
            return array_1d(r.result.modes.size(), [&](std::size_t i) { return r.result.modes[i].bending; });
          },
          "per mode: the rotor's bending fraction (0 rigid, towards 1 bending)")
      .def_property_readonly(
          "shapes",
          [](const R& r) {
            const auto& modes = r.result.modes;
            const std::size_t nodes = r.options.options.shapes ? r.model().nodes.size() : 0;
            return array_3d<std::complex<double>>(r.options.options.shapes ? modes.size() : 0, nodes, dofs_per_node,
                                                  [&](std::size_t i, std::size_t n, std::size_t d) {
                                                    const auto& shape = modes[i].shape;
                                                    const auto k = static_cast<Index>(dofs_per_node * n + d);
                                                    return k < shape.size() ? shape(k) : std::complex<double>(0.0, 0.0);
                                                  });
          },
          "with shapes=True: complex u, v, w, rx, ry, rz of every node per mode, shape\n"
          "(modes, nodes, 6), scaled so that the largest component is 1")
      .def("__len__", [](const R& r) { return r.result.modes.size(); });
}

}  // namespace feran::python

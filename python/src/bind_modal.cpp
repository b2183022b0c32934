// Modal analysis: natural frequencies, damping, whirl and shapes at one speed, with
// the settings of the command line (analyses/settings.hpp), the arrays as numpy
// arrays and to_dict() the content of the JSON file.
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

#include "bindings.hpp"

namespace feran::python {

namespace {

/// A modal result with the model it belongs to (for the JSON and the table).
struct PyModalResult {
  std::shared_ptr<const ModelFile> file;
  ModalResult result;
  bool shapes = false;
};

template <class F>
py::array_t<double> per_mode(const PyModalResult& r, F&& value) {
  py::array_t<double> out(static_cast<py::ssize_t>(r.result.modes.size()));
  auto a = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < r.result.modes.size(); ++i) a(static_cast<py::ssize_t>(i)) = value(r.result.modes[i]);
  return out;
}

}  // namespace

void bind_modal(py::module_& m) {
  py::class_<PyModalResult>(m, "ModalResult", "Natural frequencies, damping and mode shapes at one speed")
      .def_property_readonly(
          "speed", [](const PyModalResult& r) { return r.result.speed; }, "rotor speed [rad/s]")
      .def_property_readonly("speed_hz", [](const PyModalResult& r) { return rad_to_hz(r.result.speed); })
      .def_property_readonly(
          "complete", [](const PyModalResult& r) { return r.result.info.converged(); },
          "whether every mode asked for was computed")
      .def_property_readonly("message", [](const PyModalResult& r) { return r.result.info.message; })
      .def_property_readonly(
          "bearings", [](const PyModalResult& r) { return bearing_labels(r.result.operating, r.file->model); },
          "the bearings (journal and rolling) by their names")
      .def_property_readonly(
          "bearing_data", [](const PyModalResult& r) { return bearing_data(r.result.operating, true); },
          "per bearing (as bearings), its operating state at the equilibrium at this speed: a dict of\n"
          "numbers named with their units, as static's bearing_data")
      .def_property_readonly(
          "frequency_iterations", [](const PyModalResult& r) { return r.result.frequency_iterations; },
          "the most eigen solves one mode needed to settle on its own frequency (0 unless a coefficient "
          "depends on the frequency of the motion)")
      .def_property_readonly(
          "frequency_hz",
          [](const PyModalResult& r) { return per_mode(r, [](const Mode& x) { return x.frequency_hz; }); })
      .def_property_readonly(
          "damping_ratio",
          [](const PyModalResult& r) { return per_mode(r, [](const Mode& x) { return x.damping_ratio; }); })
      .def_property_readonly(
          "log_decrement",
          [](const PyModalResult& r) { return per_mode(r, [](const Mode& x) { return x.log_decrement; }); })
      .def_property_readonly(
          "directivity",
          [](const PyModalResult& r) { return per_mode(r, [](const Mode& x) { return x.directivity; }); })
      .def_property_readonly(
          "eigenvalues",
          [](const PyModalResult& r) {
            py::array_t<std::complex<double>> out(static_cast<py::ssize_t>(r.result.modes.size()));
            auto a = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < r.result.modes.size(); ++i)
              a(static_cast<py::ssize_t>(i)) = r.result.modes[i].eigenvalue;
            return out;
          },
          "p = -delta + i omega [1/s]")
      .def_property_readonly("whirl",
                             [](const PyModalResult& r) {
                               py::list out;
                               for (const Mode& x : r.result.modes) out.append(to_string(x.whirl));
                               return out;
                             })
      .def_property_readonly("type",
                             [](const PyModalResult& r) {
                               py::list out;
                               for (const Mode& x : r.result.modes) out.append(to_string(x.type));
                               return out;
                             })
      .def_property_readonly(
          "shape",
          [](const PyModalResult& r) {
            py::list out;
            for (const Mode& x : r.result.modes) out.append(to_string(x.shape_kind));
            return out;
          },
          "per mode: 'cylindrical', 'conical' (rigid on its supports) or 'bending'; 'none'")
      .def_property_readonly(
          "bending",
          [](const PyModalResult& r) {
            return array_1d(r.result.modes.size(), [&](std::size_t i) { return r.result.modes[i].bending; });
          },
          "per mode: the rotor's bending fraction (0 rigid, towards 1 bending)")
      .def_property_readonly(
          "shapes",
          [](const PyModalResult& r) {
            const auto& modes = r.result.modes;
            const std::size_t nodes = r.shapes ? r.file->model.nodes.size() : 0;
            return array_3d<std::complex<double>>(r.shapes ? modes.size() : 0, nodes, dofs_per_node,
                                                  [&](std::size_t i, std::size_t n, std::size_t d) {
                                                    const auto& shape = modes[i].shape;
                                                    const auto k = static_cast<Index>(dofs_per_node * n + d);
                                                    return k < shape.size() ? shape(k) : std::complex<double>(0.0, 0.0);
                                                  });
          },
          "with shapes=True: complex u, v, w, rx, ry, rz of every node per mode, shape\n"
          "(modes, nodes, 6), scaled so that the largest component is 1")
      .def_property_readonly("nodes",
                             [](const PyModalResult& r) {
                               return string_list(r.file->model.nodes.size(), [&](std::size_t i) {
                                 return node_name(r.file->model, static_cast<Index>(i));
                               });
                             })
      .def_property_readonly(
          "x",
          [](const PyModalResult& r) {
            return array_1d(r.file->model.nodes.size(), [&](std::size_t i) { return r.file->model.nodes[i].x; });
          },
          "axial position of each node [m]")
      .def("__len__", [](const PyModalResult& r) { return r.result.modes.size(); })
      .def(
          "to_json",
          [](const PyModalResult& r) {
            return modal_json(r.result, r.file->model, ResultSource{r.file->path, r.file->title}, r.shapes);
          },
          "The JSON text that feran modal --json writes (docs/output-format.md)")
      .def(
          "report",
          [](const PyModalResult& r) {
            return modal_report(r.result, r.file->model, ResultSource{r.file->path, r.file->title});
          },
          "The table that feran modal prints");

  m.def(
      "modal",
      [](const PyModel& model, const py::object& speed, std::optional<int> modes, const std::string& solver,
         bool shapes) {
        ModalRequest request;
        if (!speed.is_none()) request.speed = speed_argument(speed, "speed");
        request.modes = modes;
        request.solver = parse_solver_name(solver, "solver");
        request.shapes = shapes;
        auto file = std::make_shared<const ModelFile>(model.built());
        const ModalSettings settings = modal_settings(file->spec.modal, request);
        PyModalResult out{file, {}, shapes};
        {
          py::gil_scoped_release release;
          out.result = run_modal(file->model, settings.speed, settings.options, file->assembler);
        }
        return out;
      },
      py::arg("model"), py::kw_only(), py::arg("speed") = py::none(), py::arg("modes") = py::none(),
      py::arg("solver") = "auto", py::arg("shapes") = false,
      "Natural frequencies, damping and mode shapes at one speed, as feran modal.\n"
      "speed: text with its unit ('30 Hz', '1800 rpm') or a number in rad/s; default the model's\n"
      "[modal] speed, else 0. modes, solver, shapes: as --modes, --solver, --shapes.");
}

}  // namespace feran::python

// Models: reading, parameters by path, writing back, errors as Python exceptions.
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/spec/parameters.hpp>

#include "bindings.hpp"

namespace feran::python {

void PyModel::set(const std::string& path, const std::string& value) {
  const std::string canonical = set_parameter(spec_, path, value);
  changed_.emplace_back(fmt::format("model['{}'] = '{}'", path, value), canonical);
  built_.reset();
}

void PyModel::set(const std::string& path, double si) {
  const std::string canonical = set_parameter(spec_, path, si);
  changed_.emplace_back(fmt::format("model['{}'] = {}", path, si), canonical);
  built_.reset();
}

const ModelFile& PyModel::built() const {
  if (!built_) built_ = std::make_shared<const ModelFile>(build_model_file(spec_, source_, path_, changed_));
  return *built_;
}

double speed_argument(const py::handle& value, const char* name) {
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    try {
      return parse_quantity(text, Quantity::speed);
    } catch (const Error& e) {
      throw Error(fmt::format("{}='{}': {}", name, text, e.what()));
    }
  }
  return value.cast<double>();
}

namespace {

PyModel read(const std::string& path_or_text) {
  // Text holds a line break or an '='; a path does not.
  const bool text = path_or_text.find_first_of("\n=") != std::string::npos;
  if (text) {
    SpecSource source;
    ModelSpec spec = read_model_spec(path_or_text, "<string>", &source);
    PyModel model(std::move(spec), std::move(source), "<string>");
    (void)model.built();  // checked now, as a file is
    return model;
  }
  SpecSource source;
  ModelSpec spec = read_model_spec(read_text_file(path_or_text), path_or_text, &source);
  PyModel model(std::move(spec), std::move(source), path_or_text);
  (void)model.built();
  return model;
}

}  // namespace

void bind_model(py::module_& m) {
  // Errors: feran.Error for every error of feran, feran.ModelError (a problem in a
  // model, with file, line, column and message attributes) and feran.ParameterError
  // (a bad path or value) under it. The types live as long as the interpreter.
  static PyObject* error = PyErr_NewException("feran.Error", PyExc_RuntimeError, nullptr);
  static PyObject* model_error = PyErr_NewException("feran.ModelError", error, nullptr);
  static PyObject* parameter_error = PyErr_NewException("feran.ParameterError", error, nullptr);
  m.attr("Error") = py::handle(error);
  m.attr("ModelError") = py::handle(model_error);
  m.attr("ParameterError") = py::handle(parameter_error);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ModelError& e) {
      py::object value = py::handle(model_error)(e.what());
      value.attr("file") = e.where().file;
      value.attr("line") = e.where().line;
      value.attr("column") = e.where().column;
      value.attr("message") = e.message();
      PyErr_SetObject(model_error, value.ptr());
    } catch (const ParameterError& e) {
      PyErr_SetString(parameter_error, e.what());
    } catch (const Error& e) {
      PyErr_SetString(error, e.what());
    }
  });

  py::class_<PyModel>(m, "Model", "A rotor model (docs/model-format.md); read_model() makes one.")
      .def_property_readonly("path", &PyModel::path, "the file it was read from, or '<string>'")
      .def_property_readonly("title", [](const PyModel& self) { return self.spec().title; })
      .def("__getitem__",
           [](const PyModel& self, const std::string& path) { return get_parameter(self.spec(), path).value; },
           "The value (SI units) of the parameter at a path, e.g. model['springs[bearing 1].ky']")
      .def("__setitem__", py::overload_cast<const std::string&, const std::string&>(&PyModel::set),
           "Sets a parameter by its path, the value with its unit: model['springs[bearing 1].ky'] = '2e7 N/m'")
      .def("__setitem__", py::overload_cast<const std::string&, double>(&PyModel::set),
           "Sets a parameter by its path to a number in SI units")
      .def(
          "params",
          [](const PyModel& self) {
            py::list out;
            for (const Parameter& p : list_parameters(self.spec())) {
              py::dict d;
              d["path"] = p.path;
              d["value"] = p.value;
              d["unit"] = p.quantity ? std::string(si_unit(*p.quantity)) : std::string();
              d["text"] = p.text();
              d["doc"] = p.doc;
              out.append(d);
            }
            return out;
          },
          "Every settable parameter: dicts with path, value (SI), unit (SI), text (as written) and doc")
      .def("to_toml", [](const PyModel& self) { return write_toml(self.spec()); },
           "The model as TOML text (reads back to the same model)")
      .def("copy", [](const PyModel& self) { return PyModel(self); }, "An independent copy")
      .def("__copy__", [](const PyModel& self) { return PyModel(self); })
      .def("__deepcopy__", [](const PyModel& self, py::dict) { return PyModel(self); })
      .def_property_readonly("n_dofs", [](const PyModel& self) { return self.built().model.n_dofs(); },
                             "degrees of freedom of the built model (6 per node)")
      .def("check", [](const PyModel& self) { (void)self.built(); },
           "Builds and checks the model (raises ModelError as reading does)");

  m.def("read_model", &read, py::arg("path_or_text"),
        "Reads and checks a model from a file path or from TOML text (docs/model-format.md).\n"
        "Raises feran.ModelError with file, line, column and message.");
}

}  // namespace feran::python

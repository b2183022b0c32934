// Models: reading, parameters by path, writing back, errors as Python exceptions.
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <feran/core/error.hpp>
#include <feran/core/operating_point.hpp>
#include <feran/core/units.hpp>
#include <feran/model/element.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/spec/fields.hpp>
#include <feran/spec/parameters.hpp>
#include <feran/spec/spec_path.hpp>

#include "bindings.hpp"

namespace feran::python {

void PyModel::set(const std::string& path, const std::string& value) {
  ModelSpec before = spec_;
  const std::string canonical = set_parameter(spec_, path, value);
  changed_.emplace_back(fmt::format("model['{}'] = '{}'", path, value), canonical);
  check_assignment(std::move(before), changed_.back().first);
}

void PyModel::set(const std::string& path, double si) {
  ModelSpec before = spec_;
  const std::string canonical = set_parameter(spec_, path, si);
  changed_.emplace_back(fmt::format("model['{}'] = {}", path, si), canonical);
  check_assignment(std::move(before), changed_.back().first);
}

void PyModel::check_assignment(ModelSpec before, const std::string& assignment) {
  built_.reset();
  try {
    (void)built();  // kept for the analysis that follows
  } catch (const Error& e) {
    // The builder names the latest assignment to the path where it found the problem.
    if (std::string_view(e.what()).starts_with(assignment + ": ")) {
      spec_ = std::move(before);
      changed_.pop_back();
      built_.reset();
      throw ParameterError(e.what());
    }
  }
}

void PyModel::add(const std::string& table, const std::string& keys_toml, const std::string& call) {
  bool known = false, array = false;
  spec::visit_tables(spec_, [&](std::string_view key, spec::TableForm form, std::string_view, auto&) {
    if (key == table) {
      known = true;
      array = form == spec::TableForm::array_of_tables;
    }
  });
  if (!known) throw Error(fmt::format("{}: no table '{}' in a model (docs/model-format.md)", call, table));
  const std::string document = (array ? "[[" + table + "]]\n" : "[" + table + "]\n") + keys_toml;
  ModelSpec read;
  try {
    read = read_model_spec(document, "<code>");
  } catch (const ModelError& e) {
    throw Error(fmt::format("{}: {}", call, e.message()));
  }
  std::string path;
  spec::visit_tables(spec_, [&](std::string_view key, spec::TableForm, std::string_view, auto& mine) {
    if (key != table) return;
    spec::visit_tables(read, [&](std::string_view other, spec::TableForm, std::string_view, auto& theirs) {
      if constexpr (std::is_same_v<decltype(mine), decltype(theirs)>) {
        if (other != key) return;
        if constexpr (requires { mine.push_back(theirs.front()); }) {
          path = spec::element(std::string(key), mine.size());
          mine.push_back(theirs.front());
        } else {
          path = std::string(key);
          mine = theirs;
        }
      }
    });
  });
  changed_.emplace_back(call, path);
  built_.reset();
}

void PyModel::set_title(const std::string& title) {
  spec_.title = title;
  built_.reset();
}

const ModelFile& PyModel::built() const {
  if (!built_) built_ = std::make_shared<const ModelFile>(build_model_file(spec_, source_, path_, changed_));
  return *built_;
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

py::dict geometry(const PyModel& self) {
  const Model& model = self.built().model;
  std::vector<const Element*> segments, bodies, springs;
  for (const Element& e : model.elements) {
    if (e.shaft_segment())
      segments.push_back(&e);
    else if (e.mass_properties())
      bodies.push_back(&e);
    else if (e.connection())
      springs.push_back(&e);
  }
  const auto x = [&](Index node) { return model.nodes[static_cast<std::size_t>(node)].x; };
  py::dict g;
  g["nodes"] = string_list(model.nodes.size(), [&](std::size_t i) { return node_name(model, static_cast<Index>(i)); });
  g["node_x"] = array_1d(model.nodes.size(), [&](std::size_t i) { return model.nodes[i].x; });
  g["node_rotating"] = array_1d<bool>(model.nodes.size(), [&](std::size_t i) { return model.nodes[i].rotating; });
  const auto segment = [&](std::size_t i) { return *segments[i]->shaft_segment(); };
  g["segment_x0"] = array_1d(segments.size(), [&](std::size_t i) { return x(segment(i).node_a); });
  g["segment_x1"] = array_1d(segments.size(), [&](std::size_t i) { return x(segment(i).node_b); });
  g["segment_outer"] = array_1d(segments.size(), [&](std::size_t i) { return segment(i).section.outer_diameter; });
  g["segment_inner"] = array_1d(segments.size(), [&](std::size_t i) { return segment(i).section.inner_diameter; });
  g["segment_outer_end"] =
      array_1d(segments.size(), [&](std::size_t i) { return segment(i).section_b.outer_diameter; });
  g["segment_inner_end"] =
      array_1d(segments.size(), [&](std::size_t i) { return segment(i).section_b.inner_diameter; });
  g["segment_rotating"] = array_1d<bool>(segments.size(), [&](std::size_t i) {
    return model.nodes[static_cast<std::size_t>(segment(i).node_a)].rotating;
  });
  // A rigid body's mass and polar inertia from its own mass matrix at its node.
  std::vector<LocalMatrices> body_matrices;
  for (const Element* e : bodies) body_matrices.push_back(e->local_matrices(OperatingPoint{}));
  const auto body_node = [&](std::size_t i) { return body_matrices[i].dofs.at(0) / dofs_per_node; };
  g["body_names"] = string_list(bodies.size(), [&](std::size_t i) { return bodies[i]->label(); });
  g["body_x"] = array_1d(bodies.size(), [&](std::size_t i) { return x(body_node(i)); });
  g["body_mass"] = array_1d(bodies.size(), [&](std::size_t i) { return body_matrices[i].M(0, 0); });
  g["body_Jp"] = array_1d(bodies.size(), [&](std::size_t i) { return body_matrices[i].M(3, 3); });
  g["body_rotating"] = array_1d<bool>(
      bodies.size(), [&](std::size_t i) { return model.nodes[static_cast<std::size_t>(body_node(i))].rotating; });
  std::vector<Transmission> links;
  for (const Element* e : springs) links.push_back(*e->transmission(0.0));
  g["spring_names"] = string_list(springs.size(), [&](std::size_t i) { return springs[i]->label(); });
  g["spring_x"] = array_1d(springs.size(), [&](std::size_t i) { return x(links[i].node_a); });
  g["spring_to_x"] = array_1d(springs.size(), [&](std::size_t i) {
    return links[i].node_b ? x(*links[i].node_b) : std::numeric_limits<double>::quiet_NaN();
  });
  return g;
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
  // Ctrl-C during an analysis: a KeyboardInterrupt that carries the results so far.
  static PyObject* interrupted = PyErr_NewException("feran.Interrupted", PyExc_KeyboardInterrupt, nullptr);
  m.attr("Interrupted") = py::handle(interrupted);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ModelError& e) {
      py::object value = py::handle(model_error)(e.what());
      value.attr("file") = e.where().file;
      value.attr("line") = e.where().line;
      value.attr("column") = e.where().column;
      value.attr("message") = e.message();
      value.attr("path") = py::none();
      PyErr_SetObject(model_error, value.ptr());
    } catch (const SpecError& e) {
      // A model built in code: located by its path into the model ("shafts[0].sections[1].length").
      py::object value = py::handle(model_error)(e.what());
      value.attr("file") = "<code>";
      value.attr("line") = 0;
      value.attr("column") = 0;
      value.attr("message") = e.message();
      value.attr("path") = e.path();
      PyErr_SetObject(model_error, value.ptr());
    } catch (const ParameterError& e) {
      PyErr_SetString(parameter_error, e.what());
    } catch (const Error& e) {
      PyErr_SetString(error, e.what());
    }
  });

  py::class_<PyModel>(m, "Model",
                      "A rotor model (docs/model-format.md): read_model() reads one; Model(title) starts an\n"
                      "empty one to build in code (add_material(), add_shaft(), …; docs/python.md).")
      .def(py::init([](const std::string& title) {
             ModelSpec spec;
             spec.title = title;
             return PyModel(std::move(spec), SpecSource{}, "<code>");
           }),
           py::arg("title") = "")
      .def("_add", &PyModel::add, py::arg("table"), py::arg("keys_toml"), py::arg("call"))
      .def(
          "__eq__", [](const PyModel& a, const PyModel& b) { return a == b; },
          "Whether two models say the same (every table and key, values in SI units)")
      .def_property_readonly("path", &PyModel::path, "the file it was read from, or '<string>'")
      .def_property(
          "title", [](const PyModel& self) { return self.spec().title; }, &PyModel::set_title)
      .def(
          "__getitem__",
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
      .def(
          "to_toml", [](const PyModel& self) { return write_toml(self.spec()); },
          "The model as TOML text (reads back to the same model)")
      .def(
          "copy", [](const PyModel& self) { return PyModel(self); }, "An independent copy")
      .def("__copy__", [](const PyModel& self) { return PyModel(self); })
      .def("__deepcopy__", [](const PyModel& self, py::dict) { return PyModel(self); })
      .def_property_readonly(
          "n_dofs", [](const PyModel& self) { return self.built().model.n_dofs(); },
          "degrees of freedom of the built model (6 per node)")
      .def("geometry", &geometry,
           "What a drawing of the rotor needs, as numpy arrays (all lengths in m): nodes (names),\n"
           "node_x, node_rotating; shaft segments (segment_x0, segment_x1, segment_outer,\n"
           "segment_inner at x0, segment_outer_end, segment_inner_end at x1, segment_rotating); rigid bodies "
           "(body_names, body_x, body_mass, body_Jp,\n"
           "body_rotating); spring-dampers (spring_names, spring_x, spring_to_x, NaN to ground).")
      .def(
          "check", [](const PyModel& self) { (void)self.built(); },
          "Builds and checks the model (raises ModelError as reading does)");

  m.def(
      "_speed", [](const py::object& value) { return speed_argument(value, "speed"); }, py::arg("value"),
      "A speed as the analyses take it ('30 Hz', '1800 rpm', or a number in rad/s), in rad/s");
  m.def(
      "_model_tables",
      [] {
        py::list out;
        const ModelSpec spec;
        spec::visit_tables(spec, [&](std::string_view key, spec::TableForm form, std::string_view doc, const auto&) {
          out.append(py::make_tuple(std::string(key), form == spec::TableForm::array_of_tables, std::string(doc)));
        });
        return out;
      },
      "The tables of a model file in file order, as (key, is an array of tables, doc): the one list\n"
      "(spec::visit_tables) the package's add_<entry> and set_table are made from");
  m.def("read_model", &read, py::arg("path_or_text"),
        "Reads and checks a model from a file path or from TOML text (docs/model-format.md).\n"
        "Raises feran.ModelError with file, line, column and message.");
}

}  // namespace feran::python

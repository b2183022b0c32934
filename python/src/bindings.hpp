#pragma once
// What the binding files share: the model as Python holds it, and the functions that
// add each area to the module.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include <feran/io/model_reader.hpp>
#include <feran/spec/model_spec.hpp>

namespace feran::python {

namespace py = pybind11;

/// A model as Python holds it: the specification as read (or built in code), where
/// its parts were written, and the parameters set since; built into a ModelFile when
/// an analysis asks, and built again after a change. Copies are independent.
class PyModel {
 public:
  PyModel(ModelSpec spec, SpecSource source, std::string path)
      : spec_(std::move(spec)), source_(std::move(source)), path_(std::move(path)) {}

  const ModelSpec& spec() const { return spec_; }
  const std::string& path() const { return path_; }
  /// Sets a parameter by its path ("springs[bearing 1].ky", "2e7 N/m").
  void set(const std::string& path, const std::string& value);
  void set(const std::string& path, double si);
  /// The built and checked model (ModelError, or Error for a value set since).
  const ModelFile& built() const;

 private:
  ModelSpec spec_;
  SpecSource source_;
  std::string path_;
  std::vector<std::pair<std::string, std::string>> changed_;
  mutable std::shared_ptr<const ModelFile> built_;
};

void bind_model(py::module_& m);
void bind_modal(py::module_& m);

/// A speed given as text with its unit ("30 Hz", "1800 rpm") or as a number in rad/s.
double speed_argument(const py::handle& value, const char* name);

}  // namespace feran::python

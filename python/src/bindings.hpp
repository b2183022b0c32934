#pragma once
// What the binding files share: the model as Python holds it, and the functions that
// add each area to the module.

#include <atomic>
#include <limits>
#include <functional>
#include <cstddef>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <feran/analyses/common/operating_state.hpp>
#include <feran/core/stop.hpp>
#include <feran/io/result_writer.hpp>

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
  /// Sets a parameter by its path ("springs[bearing 1].ky", "2e7 N/m"). A value the
  /// model cannot take (out of its bounds, or in conflict with the model where that is
  /// checked at this very path) is refused here, naming the assignment, and the model
  /// stays as it was; a problem elsewhere in a model still being built in code is left
  /// to the analysis.
  void set(const std::string& path, const std::string& value);
  void set(const std::string& path, double si);
  /// Adds an entry to an array of tables ("materials") or sets a table ("campbell"),
  /// given as TOML text of its keys and read by the model reader's rules; @p call
  /// names it in messages ("add_material(name='steel')"). Problems the builder finds
  /// in it later are reported as "CALL: …".
  void add(const std::string& table, const std::string& keys_toml, const std::string& call);
  void set_title(const std::string& title);
  bool operator==(const PyModel& other) const { return spec_ == other.spec_; }
  /// The built and checked model (ModelError, or Error for a value set since).
  const ModelFile& built() const;

 private:
  ModelSpec spec_;
  SpecSource source_;
  std::string path_;
  std::vector<std::pair<std::string, std::string>> changed_;
  mutable std::shared_ptr<const ModelFile> built_;

  /// Builds the model after the assignment @p assignment; if the build fails because
  /// of it, restores @p before and throws.
  void check_assignment(ModelSpec before, const std::string& assignment);
};

void bind_model(py::module_& m);
void bind_study(py::module_& m);
void bind_report(py::module_& m);

/// A speed given as text with its unit ("30 Hz", "1800 rpm") or as a number in rad/s.
double speed_argument(const py::handle& value, const char* name);
/// The same, None for an argument left out.
std::optional<double> optional_speed(const py::handle& value, const char* name);
/// A positive time given as text with its unit ("5 s", "0.1 ms") or a number in s.
std::optional<double> optional_time(const py::handle& value, const char* name);
/// Node references: None (none), one name or number, or a list of them.
std::vector<Index> node_arguments(const Model& model, const py::handle& value, const char* name);
/// Names: None (none), one string, or a list of strings.
std::vector<std::string> text_arguments(const py::handle& value, const char* name);

/// What every result keeps: the model it was computed on and where it came from.
struct ResultContext {
  std::shared_ptr<const ModelFile> file;
  ResultSource source;
};
/// The context of an analysis of @p file over the speeds [@p low, @p high] (rad/s):
/// the range warnings are issued as Python warnings (UserWarning) and kept.
ResultContext result_context(std::shared_ptr<const ModelFile> file, double low, double high);

/// Runs @p solve (which fills its result) with the GIL released, watching for
/// Ctrl-C: a KeyboardInterrupt sets @p flag (the analysis's StopToken), the analysis
/// ends at its next clean point with its results so far, and the interrupt is raised
/// again by the caller with the result attached (raise_interrupted()): @p interrupted
/// says whether to.
void run_watched(const std::function<void()>& solve, std::atomic<bool>& flag, bool& interrupted);
/// Raises feran.Interrupted with @p result attached.
[[noreturn]] void raise_interrupted(py::object result);

/// numpy arrays filled from a function of the index, without Python loops.
template <class T = double, class F>
py::array_t<T> array_1d(std::size_t n, F&& value) {
  py::array_t<T> out(static_cast<py::ssize_t>(n));
  auto a = out.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) a(static_cast<py::ssize_t>(i)) = value(i);
  return out;
}
template <class T = double, class F>
py::array_t<T> array_2d(std::size_t rows, std::size_t cols, F&& value) {
  py::array_t<T> out({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  auto a = out.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) a(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = value(i, j);
  return out;
}
template <class T = double, class F>
py::array_t<T> array_3d(std::size_t n0, std::size_t n1, std::size_t n2, F&& value) {
  py::array_t<T> out({static_cast<py::ssize_t>(n0), static_cast<py::ssize_t>(n1), static_cast<py::ssize_t>(n2)});
  auto a = out.template mutable_unchecked<3>();
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t j = 0; j < n1; ++j)
      for (std::size_t k = 0; k < n2; ++k)
        a(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j), static_cast<py::ssize_t>(k)) = value(i, j, k);
  return out;
}

/// A node as Python names it: its name, else its number.
inline std::string node_name(const Model& model, Index node) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return n.name.empty() ? std::to_string(n.number) : n.name;
}

/// A Python list of the strings f(i), i < n.
template <class F>
py::list string_list(std::size_t n, F&& f) {
  py::list out;
  for (std::size_t i = 0; i < n; ++i) out.append(py::str(std::string(f(i))));
  return out;
}

/// Per support of @p series (Force::supports(), as the result's bearings), a dict of
/// its operating quantities by their names, which carry their units: a numpy array over
/// the result's points, or with @p one_point a number.
inline py::list bearing_data(const std::vector<OperatingSeries>& series, bool one_point = false) {
  py::list out;
  for (const OperatingSeries& s : series) {
    py::dict d;
    for (std::size_t q = 0; q < s.quantities.size(); ++q) {
      if (one_point)
        d[py::str(s.quantities[q])] = s.values.empty() ? std::numeric_limits<double>::quiet_NaN() : s.values.front()[q];
      else
        d[py::str(s.quantities[q])] = array_1d(s.values.size(), [&](std::size_t k) { return s.values[k][q]; });
    }
    out.append(d);
  }
  return out;
}

/// The bearings of @p series by their labels.
inline py::list bearing_labels(const std::vector<OperatingSeries>& series, const Model& model) {
  return string_list(series.size(),
                     [&](std::size_t i) { return model.forces[static_cast<std::size_t>(series[i].force)].label(); });
}

}  // namespace feran::python

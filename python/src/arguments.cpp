// Keyword arguments as the analyses take them (speeds, times, nodes, names), the
// context every result keeps, and solves that Ctrl-C can stop.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/core/units.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/io/option_text.hpp>

#include "analysis_binding.hpp"
#include "bindings.hpp"

namespace feran::python {

namespace {

double number_argument(const py::handle& value, const char* name, const char* expected) {
  if ((!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value)) || py::isinstance<py::bool_>(value))
    throw Error(fmt::format("{}={}: expected {}", name, py::repr(value).cast<std::string>(), expected));
  const double x = value.cast<double>();
  if (!std::isfinite(x)) throw Error(fmt::format("{}={}: expected a finite number", name, x));
  return x;
}

}  // namespace

double speed_argument(const py::handle& value, const char* name) {
  if (py::isinstance<py::str>(value)) return parse_speed_text(value.cast<std::string>(), name);
  const double x = number_argument(value, name, "a speed as text with its unit ('30 Hz') or a number in rad/s");
  const Real largest = physical_range(Quantity::speed).largest;
  if (std::abs(x) > largest)
    throw Error(fmt::format("{}={:g}: beyond the physical range of a speed (at most {:g} rad/s in magnitude)", name, x,
                            largest));
  return x;
}

std::optional<double> optional_speed(const py::handle& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  return speed_argument(value, name);
}

std::optional<double> optional_time(const py::handle& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(value)) return parse_time_text(value.cast<std::string>(), name);
  const double t = number_argument(value, name, "a time as text with its unit ('5 s') or a number in s");
  if (!(t > 0)) throw Error(fmt::format("{}={:g}: must be positive (a time such as '5 s' or 0.1)", name, t));
  return t;
}

std::vector<Index> node_arguments(const Model& model, const py::handle& value, const char* name) {
  std::vector<Index> out;
  if (value.is_none()) return out;
  const auto one = [&](const py::handle& v) {
    if (py::isinstance<py::str>(v)) return find_node_reference(model, v.cast<std::string>(), name);
    if (py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v))
      return find_node_reference(model, std::to_string(v.cast<long long>()), name);
    throw Error(
        fmt::format("{}: a node is a name (str) or a number (int), got {}", name, py::repr(v).cast<std::string>()));
  };
  if (py::isinstance<py::str>(value) || py::isinstance<py::int_>(value) || !py::isinstance<py::iterable>(value)) {
    out.push_back(one(value));
    return out;
  }
  for (const py::handle& v : py::iter(value)) out.push_back(one(v));
  return out;
}

std::vector<std::string> text_arguments(const py::handle& value, const char* name) {
  std::vector<std::string> out;
  if (value.is_none()) return out;
  if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
  if (!py::isinstance<py::iterable>(value))
    throw Error(fmt::format("{}: expected text or a list of texts, got {}", name, py::repr(value).cast<std::string>()));
  for (const py::handle& v : py::iter(value)) {
    if (!py::isinstance<py::str>(v))
      throw Error(fmt::format("{}: expected text, got {}", name, py::repr(v).cast<std::string>()));
    out.push_back(v.cast<std::string>());
  }
  return out;
}

int threads_keyword(const py::kwargs& keywords, std::string_view function) {
  if (!keywords.contains("threads")) return 0;
  const py::handle v = keywords["threads"];
  if (v.is_none()) return 0;
  if (!py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v))
    throw py::type_error(fmt::format("{}(): 'threads' must be an integer, got {}", function, given(v)));
  return v.cast<int>();
}

std::string python_name(std::string_view option) {
  static const std::vector<std::string_view> reserved = {
      "False", "None",     "True",  "and",    "as",   "assert", "async",  "await",    "break",
      "class", "continue", "def",   "del",    "elif", "else",   "except", "finally",  "for",
      "from",  "global",   "if",    "import", "in",   "is",     "lambda", "nonlocal", "not",
      "or",    "pass",     "raise", "return", "try",  "while",  "with",   "yield"};
  std::string name(option);
  if (std::find(reserved.begin(), reserved.end(), option) != reserved.end()) name += '_';
  return name;
}

std::string time_table_keyword(const py::handle& value, Quantity kind, std::string_view function,
                               std::string_view key) {
  const auto wrong = [&] {
    throw py::type_error(
        fmt::format("{}(): '{}' must be text such as '0s:0Hz,5s:80Hz' or a list of (time, value) pairs or None, got {}",
                    function, key, given(value)));
  };
  if (!py::isinstance<py::iterable>(value)) wrong();
  const auto part = [&](const py::handle& v, std::string_view unit) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if ((py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) && !py::isinstance<py::bool_>(v))
      return fmt::format("{:.17g}{}", v.cast<double>(), unit);
    wrong();
    return std::string();
  };
  std::string text;
  for (const py::handle& point : py::iter(value)) {
    if (!py::isinstance<py::sequence>(point) || py::isinstance<py::str>(point) || py::len(point) != 2) wrong();
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    if (!text.empty()) text += ',';
    text += part(pair[0], "s") + ":" + part(pair[1], si_unit(kind));
  }
  return text;
}

std::string given(const py::handle& value) {
  std::string text = py::repr(value).cast<std::string>();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return fmt::format("{} {}", py::type::of(value).attr("__name__").cast<std::string>(), text);
}

void issue_warnings(const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : warnings) warn(w, py::handle(PyExc_UserWarning), 2);
}

ResultContext result_context(std::shared_ptr<const ModelFile> file, double low, double high) {
  ResultContext out{file, ResultSource{file->path, file->title, range_warnings(file->model, low, high)}};
  issue_warnings(out.source.warnings);
  return out;
}

void run_watched(const std::function<void()>& solve, std::atomic<bool>& flag, bool& interrupted) {
  // The solve runs on a thread of its own while this one, the caller's, wakes every
  // 50 ms and asks Python whether a signal came (PyErr_CheckSignals needs the GIL;
  // only the main thread ever sees one). Errors cross back as exceptions.
  std::mutex mutex;
  std::condition_variable done_signal;
  bool done = false;
  std::exception_ptr error;
  interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        solve();
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      done_signal.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!done_signal.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      if (interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {
          PyErr_Clear();  // raised again, with the results, once the solve has ended
          interrupted = true;
          flag = true;
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (error) std::rethrow_exception(error);
}

void raise_interrupted(py::object result) {
  const py::object type = py::module_::import("feran._feran").attr("Interrupted");
  py::object value = type("interrupted: the results so far are in .result");
  value.attr("result") = std::move(result);
  PyErr_SetObject(type.ptr(), value.ptr());
  throw py::error_already_set();
}

}  // namespace feran::python

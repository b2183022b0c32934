// Design studies: the compiled part of feran.Study (python/feran/study.py). A study
// is read by the study reader (from a file, or from the TOML text feran.Study writes
// of its arguments, with the base model given in code); Python functions become
// quantities of kind "function"; the study runs on threads here, or batch by batch on
// an engine given as a Python callable (feran.Study's dask.distributed engine), the
// evaluations crossing as exact bytes (pack_evaluations).
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <feran/core/error.hpp>
#include <feran/core/parallel.hpp>
#include <feran/core/units.hpp>
#include <feran/io/study_log.hpp>
#include <feran/io/study_reader.hpp>
#include <feran/study/distributed.hpp>
#include <feran/study/sensitivity.hpp>

#include "bindings.hpp"

namespace feran::python {

namespace {

// A Python object whose last reference may be dropped on any thread: released
// under the GIL.
struct HeldObject {
  explicit HeldObject(py::object o) : object(std::move(o)) {}
  HeldObject(const HeldObject&) = delete;
  HeldObject& operator=(const HeldObject&) = delete;
  ~HeldObject() {
    py::gil_scoped_acquire gil;
    object = py::object();
  }
  py::object object;
};

// "ValueError: the message" of the Python exception being handled.
std::string python_error_text(const py::error_already_set& e) {
  const std::string type = py::str(e.type().attr("__name__"));
  const std::string value = py::str(e.value());
  return value.empty() ? type : type + ": " + value;
}

// A Python function f(model) -> float as a study quantity: called with the design's
// model (a feran.Model), under the GIL, from the study's worker threads.
std::shared_ptr<const QuantityFunction> python_quantity(py::object function, SpecSource source, std::string path) {
  auto held = std::make_shared<HeldObject>(std::move(function));
  return std::make_shared<const QuantityFunction>([held, source = std::move(source), path = std::move(path)](
                                                      const ModelSpec& spec, const Model&) -> Real {
    py::gil_scoped_acquire gil;
    try {
      const py::object value = held->object(PyModel(spec, source, path));
      if (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value) && !py::hasattr(value, "__float__"))
        throw Error(fmt::format("the function returned {}, not a number", std::string(py::repr(value))));
      return value.cast<double>();
    } catch (const py::error_already_set& e) {
      throw Error(fmt::format("the function raised {}", python_error_text(e)));
    }
  });
}

struct PyStudy {
  StudyFile file;
  const StudySpec& study() const { return file.study; }
};

// An evaluated study: the evaluations in index order and what was written.
struct PyStudyResult {
  std::shared_ptr<const PyStudy> study;
  std::vector<Evaluation> evaluations;
  std::string directory;                 // empty: kept in memory only
  std::vector<std::string> model_files;  // best.toml or pareto-*.toml
  bool complete = false;
  Index resumed = 0;
};

// Evaluates each batch by calling a Python engine: engine(indices, units, stopped)
// returns, per design, its packed evaluation (bytes, from Study._evaluate) or None
// for a design it did not evaluate because stopped() turned true.
class CallbackEvaluator : public BatchEvaluator {
 public:
  CallbackEvaluator(py::object engine, std::atomic<bool>& flag)
      : engine_(std::make_shared<HeldObject>(std::move(engine))), flag_(flag) {}

  std::vector<Evaluation> evaluate(const StudySpec& study,
                                   const std::vector<std::pair<Index, UnitPoint>>& batch) override {
    std::vector<Evaluation> out(batch.size());
    py::gil_scoped_acquire gil;
    py::list indices;
    for (const auto& [index, point] : batch) indices.append(index);
    const auto dim = study.variables.size();
    const auto units = array_2d(batch.size(), dim, [&](std::size_t i, std::size_t j) { return batch[i].second[j]; });
    std::atomic<bool>* flag = &flag_;
    const py::cpp_function stopped([flag] { return flag->load(); });
    py::list results;
    try {
      results = py::list(engine_->object(indices, units, stopped));
    } catch (const py::error_already_set& e) {
      throw Error(fmt::format("the study's engine failed: {}", python_error_text(e)));
    }
    if (results.size() != batch.size())
      throw Error(fmt::format("the study's engine returned {} results for {} designs", results.size(), batch.size()));
    for (std::size_t i = 0; i < batch.size(); ++i) {
      if (results[i].is_none()) {
        out[i].index = batch[i].first;
        out[i].unit = batch[i].second;
        out[i].interrupted = true;
        continue;
      }
      auto one = unpack_evaluations(std::string(py::bytes(results[i])));
      if (one.size() != 1 || one.front().index != batch[i].first)
        throw Error(fmt::format("the study's engine returned another design's result for design {}", batch[i].first));
      out[i] = std::move(one.front());
    }
    return out;
  }

 private:
  std::shared_ptr<HeldObject> engine_;
  std::atomic<bool>& flag_;
};

std::shared_ptr<PyStudy> read_file(const std::string& path) {
  auto s = std::make_shared<PyStudy>();
  s->file = read_study_file(path);
  return s;
}

std::shared_ptr<PyStudy> from_code(const std::string& toml_text, const PyModel& model, const std::string& model_name,
                                   const py::dict& functions) {
  StudyCode code;
  code.base = model.built();
  code.model_name = model_name;
  auto s = std::make_shared<PyStudy>();
  s->file = read_study_string(toml_text, "<study>", code);
  for (auto& q : s->file.study.quantities) {
    if (!row_of(q).code_only) continue;
    if (!functions.contains(q.name))
      throw Error(fmt::format("quantity '{}' of kind \"function\" has no function", q.name));
    const py::object f = functions[py::str(q.name)];
    if (!PyCallable_Check(f.ptr()))
      throw Error(
          fmt::format("quantity '{}': the function must be callable, got {}", q.name, std::string(py::repr(f))));
    q.function = python_quantity(f, code.base.source, model.path());
  }
  return s;
}

PyModel design_model(const PyStudy& s, const Evaluation& e) {
  return PyModel(apply_design(s.study().base, s.study().variables, e.values), s.file.base.source, s.file.base.path);
}

py::bytes evaluate(const PyStudy& s, const std::vector<Index>& indices, const py::array_t<double>& units, int threads) {
  const auto dim = s.study().variables.size();
  if (units.ndim() != 2 || static_cast<std::size_t>(units.shape(0)) != indices.size() ||
      static_cast<std::size_t>(units.shape(1)) != dim)
    throw Error(fmt::format("units must be an array of {} rows of {} coordinates", indices.size(), dim));
  const auto u = units.unchecked<2>();
  std::vector<std::pair<Index, UnitPoint>> batch;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    UnitPoint p(dim);
    for (std::size_t j = 0; j < dim; ++j) p[j] = u(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j));
    batch.emplace_back(indices[i], std::move(p));
  }
  std::vector<Evaluation> out;
  {
    py::gil_scoped_release release;
    ThreadEvaluator local(threads);
    out = local.evaluate(s.study(), batch);
  }
  return py::bytes(pack_evaluations(out));
}

PyStudyResult run(const std::shared_ptr<PyStudy>& s, const std::optional<std::string>& output, bool resume, int threads,
                  std::optional<Index> batch, const py::object& engine) {
  const StudySpec& study = s->study();
  if (resume && !output) throw Error("resume=True continues a study recorded on disk: give it output=DIRECTORY");
  std::unique_ptr<StudyLog> log;
  if (output)
    log = std::make_unique<StudyLog>(*output, study, resume, std::vector<std::string>{s->file.path, s->file.base.path});
  const std::vector<Evaluation> done = log ? log->done() : std::vector<Evaluation>{};
  std::atomic<bool> flag{false};
  const StopToken stop(flag);
  std::unique_ptr<BatchEvaluator> evaluator;
  if (engine.is_none())
    evaluator = std::make_unique<ThreadEvaluator>(threads, stop);
  else
    evaluator = std::make_unique<CallbackEvaluator>(engine, flag);
  const Index size = batch.value_or(4 * resolve_threads(threads));
  if (size < 1) throw Error("batch must be at least 1");
  PyStudyResult result;
  result.study = s;
  result.resumed = static_cast<Index>(done.size());
  bool interrupted = false;
  run_watched(
      [&] {
        result.evaluations = run_exploration(
            study, *evaluator, done,
            [&](std::span<const Evaluation> e) {
              if (log) log->append(e);
            },
            size, stop);
      },
      flag, interrupted);
  const bool optimiser =
      study.explore.method == ExploreMethod::optimise || study.explore.method == ExploreMethod::pareto;
  result.complete =
      !interrupted && (optimiser || static_cast<Index>(result.evaluations.size()) == planned_evaluations(study));
  if (log) {
    result.directory = log->directory();
    result.model_files = log->finish(result.evaluations, result.complete);
  }
  if (interrupted) raise_interrupted(py::cast(std::move(result)));
  return result;
}

// The SI unit of a variable's or quantity's values ("" for a pure number).
std::string unit_of(const std::optional<Quantity>& kind) { return kind ? std::string(si_unit(*kind)) : std::string(); }

}  // namespace

void bind_study(py::module_& m) {
  py::class_<PyStudy, std::shared_ptr<PyStudy>>(m, "_Study", "A design study as read (use feran.Study)")
      .def_static("read", &read_file, py::arg("path"), "Reads a study file (docs/study-format.md)")
      .def_static("from_code", &from_code, py::arg("toml"), py::arg("model"), py::arg("model_name"),
                  py::arg("functions"), "A study of a model given in code; functions: quantity name -> f(model)")
      .def_property_readonly("title", [](const PyStudy& s) { return s.study().title; })
      .def_property_readonly("variable_names",
                             [](const PyStudy& s) {
                               return string_list(s.study().variables.size(),
                                                  [&](std::size_t i) { return s.study().variables[i].name; });
                             })
      .def_property_readonly("variable_units",
                             [](const PyStudy& s) {
                               return string_list(s.study().variables.size(), [&](std::size_t i) {
                                 return unit_of(s.study().variables[i].quantity);
                               });
                             })
      .def_property_readonly("variable_log",
                             [](const PyStudy& s) {
                               py::list out;
                               for (const auto& v : s.study().variables)
                                 out.append(!v.discrete() && v.scale == VariableScale::log);
                               return out;
                             })
      .def_property_readonly("quantity_names",
                             [](const PyStudy& s) {
                               return string_list(s.study().quantities.size(),
                                                  [&](std::size_t i) { return s.study().quantities[i].name; });
                             })
      .def_property_readonly("quantity_units",
                             [](const PyStudy& s) {
                               return string_list(s.study().quantities.size(), [&](std::size_t i) {
                                 return unit_of(quantity_unit(s.study().quantities[i]));
                               });
                             })
      .def_property_readonly(
          "objectives",
          [](const PyStudy& s) {
            py::list out;
            for (const auto& o : s.study().objectives)
              out.append(py::make_tuple(s.study().quantities[static_cast<std::size_t>(o.quantity)].name,
                                        o.sense == Sense::minimise ? "minimise" : "maximise"));
            return out;
          })
      .def_property_readonly("method",
                             [](const PyStudy& s) { return std::string(to_string(s.study().explore.method)); })
      .def_property_readonly(
          "planned", [](const PyStudy& s) { return planned_evaluations(s.study()); },
          "designs the study plans (for an optimiser an upper bound)")
      .def(
          "base_model", [](const PyStudy& s) { return PyModel(s.study().base, s.file.base.source, s.file.base.path); },
          "The base model with the study's settings")
      .def("_evaluate", &evaluate, py::arg("indices"), py::arg("units"), py::arg("threads") = 1,
           "Evaluates designs (indices, unit coordinates) and returns them packed (bytes)")
      .def("_run", &run, py::arg("output"), py::arg("resume"), py::arg("threads"), py::arg("batch"), py::arg("engine"));

  py::class_<PyStudyResult>(m, "StudyResult",
                            "Every evaluated design of a study, in index order (docs/python.md, 'Design studies')")
      .def_property_readonly(
          "index",
          [](const PyStudyResult& r) {
            return array_1d<long long>(r.evaluations.size(),
                                       [&](std::size_t i) { return static_cast<long long>(r.evaluations[i].index); });
          },
          "each design's index (its place in the exploration)")
      .def_property_readonly(
          "unit",
          [](const PyStudyResult& r) {
            const auto d = r.study->study().variables.size();
            return array_2d(r.evaluations.size(), d,
                            [&](std::size_t i, std::size_t j) { return r.evaluations[i].unit[j]; });
          },
          "unit-cube coordinates, one row per design")
      .def_property_readonly(
          "values",
          [](const PyStudyResult& r) {
            const auto d = r.study->study().variables.size();
            return array_2d(r.evaluations.size(), d,
                            [&](std::size_t i, std::size_t j) { return r.evaluations[i].values[j]; });
          },
          "the variables' values (SI), one row per design")
      .def_property_readonly(
          "quantities",
          [](const PyStudyResult& r) {
            const auto q = r.study->study().quantities.size();
            return array_2d(r.evaluations.size(), q, [&](std::size_t i, std::size_t j) {
              const auto& e = r.evaluations[i];
              return e.quantities.empty() ? std::numeric_limits<double>::quiet_NaN() : e.quantities[j];
            });
          },
          "the quantities (SI), one row per design; NaN for a design that failed")
      .def_property_readonly(
          "evaluated",
          [](const PyStudyResult& r) {
            return array_1d<bool>(r.evaluations.size(), [&](std::size_t i) { return r.evaluations[i].evaluated; });
          },
          "every quantity was computed")
      .def_property_readonly(
          "feasible",
          [](const PyStudyResult& r) {
            return array_1d<bool>(r.evaluations.size(), [&](std::size_t i) { return r.evaluations[i].feasible; });
          },
          "evaluated and every constraint holds")
      .def_property_readonly(
          "messages",
          [](const PyStudyResult& r) {
            return string_list(r.evaluations.size(), [&](std::size_t i) { return r.evaluations[i].message; });
          },
          "why a design failed or which constraint it violates ('' otherwise)")
      .def_property_readonly(
          "clipped",
          [](const PyStudyResult& r) {
            py::list out;
            const auto& quantities = r.study->study().quantities;
            for (const auto& e : r.evaluations) {
              py::dict d;
              for (std::size_t i = 0; i < e.clipped.size() && i < quantities.size(); ++i)
                if (!e.clipped[i].empty()) d[py::str(quantities[i].name)] = e.clipped[i];
              out.append(d);
            }
            return out;
          },
          "per design, {quantity: why its value is only a bound} for the quantities clipped by the range an\n"
          "analysis covered (a separation margin or stability threshold beyond the Campbell range's end)")
      .def_property_readonly(
          "seconds",
          [](const PyStudyResult& r) {
            return array_1d(r.evaluations.size(), [&](std::size_t i) { return r.evaluations[i].seconds; });
          },
          "wall time of each evaluation [s]")
      .def_property_readonly(
          "best",
          [](const PyStudyResult& r) -> py::object {
            const auto b = best_design(r.study->study(), r.evaluations);
            return b ? py::cast(*b) : py::none();
          },
          "row of the best feasible design of a single-objective study (None: none feasible)")
      .def_property_readonly(
          "pareto",
          [](const PyStudyResult& r) {
            const auto front = pareto_set(r.study->study(), r.evaluations);
            return array_1d<long long>(front.size(), [&](std::size_t i) { return static_cast<long long>(front[i]); });
          },
          "rows of the feasible designs no other dominates in the objectives")
      .def(
          "sensitivity",
          [](const PyStudyResult& r) {
            py::list out;
            for (const auto& x : sensitivities(r.study->study(), r.evaluations)) {
              py::dict d;
              d["quantity"] = x.quantity;
              d["src"] = array_1d(x.src.size(), [&](std::size_t i) { return x.src[i]; });
              d["r2"] = x.r2;
              d["srrc"] = array_1d(x.srrc.size(), [&](std::size_t i) { return x.srrc[i]; });
              d["r2_ranks"] = x.r2_ranks;
              d["samples"] = x.samples;
              out.append(d);
            }
            return out;
          },
          "Standardised regression coefficients of each quantity on the variables' unit coordinates\n"
          "(src, with the fit's r2) and on their ranks (srrc, r2_ranks): one dict per quantity")
      .def(
          "model",
          [](const PyStudyResult& r, Index row) {
            if (row < 0 || row >= static_cast<Index>(r.evaluations.size()))
              throw py::index_error(fmt::format("row {} of a study result of {} designs", row, r.evaluations.size()));
            return design_model(*r.study, r.evaluations[static_cast<std::size_t>(row)]);
          },
          py::arg("row"), "The model of the design in that row (a feran.Model)")
      .def_property_readonly(
          "directory", [](const PyStudyResult& r) { return r.directory; },
          "where the evaluations were written ('' when kept in memory only)")
      .def_property_readonly(
          "model_files", [](const PyStudyResult& r) { return r.model_files; },
          "the model files of the best design or the Pareto set")
      .def_property_readonly(
          "complete", [](const PyStudyResult& r) { return r.complete; },
          "every planned design was evaluated (False after an interruption)")
      .def_property_readonly(
          "resumed", [](const PyStudyResult& r) { return r.resumed; },
          "designs read back from the directory instead of evaluated")
      .def_property_readonly("variable_names",
                             [](const PyStudyResult& r) {
                               return string_list(r.study->study().variables.size(),
                                                  [&](std::size_t i) { return r.study->study().variables[i].name; });
                             })
      .def_property_readonly("quantity_names",
                             [](const PyStudyResult& r) {
                               return string_list(r.study->study().quantities.size(),
                                                  [&](std::size_t i) { return r.study->study().quantities[i].name; });
                             })
      .def_property_readonly("_study", [](const PyStudyResult& r) { return std::const_pointer_cast<PyStudy>(r.study); })
      .def("__len__", [](const PyStudyResult& r) { return r.evaluations.size(); });
}

}  // namespace feran::python

#pragma once
// The Python door of an analysis, made from its face (analyses/analysis.hpp): the
// function feran.<name>(model, **options), whose keywords are the keys of the
// analysis's field table, each set and checked by the generic request step
// (spec/request.hpp); and its result class, whose arrays the analysis's own folder
// binds (analyses/<name>/python.cpp, bind_result<A>) and whose to_json, to_csv,
// report and warnings every result shares.

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <feran/analyses/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/suggestions.hpp>

#include "bindings.hpp"

namespace feran::python {

/// The arrays and values of analysis A's result, bound by its folder.
template <class A>
void bind_result(py::class_<Outcome<A>>& result);

/// Issues each warning as a Python UserWarning.
void issue_warnings(const std::vector<std::string>& warnings);

/// "str 'x'", "float 2.5": a value as a TypeError shows it (as the package's
/// messages for the other functions do).
std::string given(const py::handle& value);

/// The keyword of an option in Python: its name, with '_' after a word Python keeps
/// for itself ("from_").
std::string python_name(std::string_view option);

/// Time points given in Python as a list of (time, value) pairs, each a number (s, and
/// SI units) or text with its unit, written as the command line writes them
/// ("0s:0Hz,…"); TypeError naming @p function and @p key otherwise.
std::string time_table_keyword(const py::handle& value, Quantity kind, std::string_view function, std::string_view key);

/// One keyword argument's value set on field @p f of @p request: None leaves it unset;
/// a string is read as the command line reads it; a number is in SI units (speeds in
/// rad/s); a list sets a list field. A value of the wrong Python type is a TypeError
/// naming the function @p function and the keyword; a value the field refuses an
/// Error.
template <class S>
void set_keyword(S& request, const spec::Field<S>& f, const py::handle& value, std::string_view function) {
  using spec::FieldKind;
  const std::string key = python_name(spec::option_name(f));
  if (value.is_none()) return;
  const bool is_bool = py::isinstance<py::bool_>(value);
  const bool is_int = py::isinstance<py::int_>(value) && !is_bool;
  const bool is_number = is_int || (py::isinstance<py::float_>(value) && !is_bool);
  const bool is_text = py::isinstance<py::str>(value);
  const auto wrong = [&](std::string_view expected) {
    throw py::type_error(fmt::format("{}(): '{}' must be {} or None, got {}", function, key, expected, given(value)));
  };
  switch (f.kind) {
    case FieldKind::flag:
      if (!is_bool) wrong("True or False");
      spec::set_flag(request, f, value.cast<bool>());
      return;
    case FieldKind::integer:
      if (!is_int) wrong("an integer");
      spec::set_text(request, f, std::to_string(value.cast<long long>()), key);
      return;
    case FieldKind::quantity:
      if (is_text) break;
      if (!is_number) wrong("text with its unit or a number in SI units");
      spec::set_number(request, f, value.cast<double>(), key);
      return;
    case FieldKind::number:
      if (!is_number) wrong("a number");
      spec::set_number(request, f, value.cast<double>(), key);
      return;
    case FieldKind::node:
      if (!is_text && !is_int) wrong("a node name (str) or number (int)");
      spec::set_text(request, f, is_int ? std::to_string(value.cast<long long>()) : value.cast<std::string>(), key);
      return;
    case FieldKind::integer_list:
      if (is_text || is_bool || (!is_int && !py::isinstance<py::iterable>(value))) wrong("a list of integers");
      if (is_int) {
        spec::set_text(request, f, std::to_string(value.cast<long long>()), key);
      } else {
        for (const py::handle& v : py::iter(value)) {
          if (!py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v)) wrong("a list of integers");
          spec::set_text(request, f, std::to_string(v.cast<long long>()), key);
        }
      }
      return;
    case FieldKind::node_list:
    case FieldKind::text_list:
    case FieldKind::choice_list: {
      const auto one = [&](const py::handle& v) {
        if (py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v))
          spec::set_text(request, f, std::to_string(v.cast<long long>()), key);
        else if (py::isinstance<py::str>(v))
          spec::set_text(request, f, v.cast<std::string>(), key);
        else
          wrong("a name or number, or a list of them");
      };
      if (is_text || is_int || !py::isinstance<py::iterable>(value))
        one(value);
      else
        for (const py::handle& v : py::iter(value)) one(v);
      return;
    }
    case FieldKind::time_table:
      if (is_text) break;
      spec::set_text(request, f, time_table_keyword(value, f.quantity, function, key), key);
      return;
    default:
      break;
  }
  if (!is_text) wrong("a string");
  spec::set_text(request, f, value.cast<std::string>(), key);
}

/// The request of analysis A from Python's keyword arguments; an unknown keyword is
/// refused with the known ones.
template <AnalysisFace A>
typename A::Spec request_from_keywords(const py::kwargs& keywords) {
  using S = typename A::Spec;
  S request;
  for (const auto& item : keywords) {
    const py::handle k = item.first, v = item.second;
    const std::string key = py::str(k);
    if (parallel_analysis<A>() && key == "threads") continue;  // the door's, not the analysis's
    const spec::Field<S>* f = spec::find_option<S>(key);
    if (f != nullptr && python_name(key) != key) f = nullptr;  // "from" is spelt from_
    if (f == nullptr && key.ends_with('_') && python_name(key.substr(0, key.size() - 1)) == key)
      f = spec::find_option<S>(key.substr(0, key.size() - 1));
    if (f == nullptr) {
      std::vector<std::string> known;
      for (const spec::Field<S>& field : spec::fields_of<S>())
        known.emplace_back(python_name(spec::option_name(field)));
      if (parallel_analysis<A>()) known.emplace_back("threads");
      std::string message = fmt::format("{}(): has no argument '{}'", A::name, key);
      if (const auto match = detail::closest_match(key, known, 2))
        message += fmt::format("; did you mean '{}'?", *match);
      throw py::type_error(message + fmt::format(" (its options are {})", detail::join_list(known, "and")));
    }
    set_keyword(request, *f, v, A::name);
  }
  return request;
}

/// threads=: 0 (all cores, the default, as the command line) or a count.
int threads_keyword(const py::kwargs& keywords, std::string_view function);

/// A description of analysis A's options for the package, which gives feran.<name>
/// its signature and help: per key (key, kind, description, default as text).
template <AnalysisFace A>
py::list option_descriptions() {
  py::list out;
  for (const spec::Field<typename A::Spec>& f : spec::fields_of<typename A::Spec>())
    out.append(
        py::make_tuple(python_name(spec::option_name(f)), static_cast<int>(f.kind), std::string(f.doc),
                       f.default_text.empty() ? spec::value_text(A::defaults(), f) : std::string(f.default_text)));
  if (parallel_analysis<A>())
    out.append(py::make_tuple(std::string("threads"), -1,
                              std::string("threads for the points: 0 all cores (as the command line), or 1 to run "
                                          "Python threads side by side instead"),
                              std::string("0")));
  return out;
}

/// feran.<name>(model, **options) and its result class, for analysis A.
template <AnalysisFace A>
void bind_analysis(py::module_& m, py::dict& descriptions) {
  using Result = Outcome<A>;
  std::string class_name(A::name);
  class_name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(class_name[0])));
  py::class_<Result> result(m, (class_name + "Result").c_str(), std::string(A::summary).c_str());
  bind_result<A>(result);
  result.def_property_readonly("warnings", [](const Result& r) { return r.source.warnings; })
      .def_property_readonly("nodes",
                             [](const Result& r) {
                               return string_list(r.model().nodes.size(), [&](std::size_t i) {
                                 return node_name(r.model(), static_cast<Index>(i));
                               });
                             })
      .def_property_readonly(
          "x",
          [](const Result& r) {
            return array_1d(r.model().nodes.size(), [&](std::size_t i) { return r.model().nodes[i].x; });
          },
          "axial position of each node [m]")
      .def(
          "to_json", [](const Result& r) { return A::json(r); },
          fmt::format("The JSON text that feran {} --json writes (docs/output-format.md)", A::name).c_str())
      .def(
          "to_csv", [](const Result& r) { return A::csv(r); },
          fmt::format("The CSV text that feran {} --csv writes", A::name).c_str())
      .def(
          "report", [](const Result& r) { return A::terminal(r); },
          fmt::format("The table feran {} prints", A::name).c_str());

  m.def(
      std::string(A::name).c_str(),
      [](const PyModel& model, const py::kwargs& keywords) {
        auto file = std::make_shared<const ModelFile>(model.built());
        typename A::Spec request;
        try {
          request = request_from_keywords<A>(keywords);
        } catch (const Error& e) {
          throw Error(fmt::format("{}: {}", A::name, e.what()));
        }
        const OptionName name = [](std::string_view key) {
          return std::string(spec::option_name<typename A::Spec>(key));
        };
        const int threads = parallel_analysis<A>() ? threads_keyword(keywords, A::name) : 1;
        Result out;
        if constexpr (keeps_partial_results<A>()) {
          // Ctrl-C stops the solve at its next clean point; the results so far are
          // attached to the feran.Interrupted raised.
          std::atomic<bool> flag{false};
          bool interrupted = false;
          run_watched(
              [&] {
                out = run_analysis<A>(file, request, name, RunContext{.stop = StopToken(flag), .threads = threads});
              },
              flag, interrupted);
          if (interrupted) {
            issue_warnings(out.source.warnings);
            raise_interrupted(py::cast(std::move(out)));
          }
        } else {
          py::gil_scoped_release release;
          out = run_analysis<A>(file, request, name, RunContext{.threads = threads});
        }
        issue_warnings(out.source.warnings);
        if (!out.result.info.converged()) {
          // One solve without partial results: a failure leaves nothing to keep; else
          // the results so far are returned, and the failure said as a warning.
          if constexpr (!keeps_partial_results<A>()) throw Error(out.result.info.message);
          issue_warnings({fmt::format("{}: {} (the results so far are kept)", A::name, out.result.info.message)});
        }
        return out;
      },
      py::arg("model"), std::string(A::summary).c_str());
  descriptions[py::str(std::string(A::name))] = option_descriptions<A>();
}

}  // namespace feran::python

#pragma once
// The Python door of an analysis, made from its face (analyses/analysis.hpp): the
// function feran.<name>(model, **options), whose keywords are the keys of the
// analysis's field table, each set and checked by the generic request step
// (spec/request.hpp); and its result class, whose arrays the analysis's own folder
// binds (analyses/<name>/python.cpp, bind_result<A>) and whose to_json, to_csv,
// report and warnings every result shares.

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

/// One keyword argument's value set on field @p f of @p request: None leaves it unset;
/// a string is read as the command line reads it; a number is in SI units (speeds in
/// rad/s); a list sets a list field.
template <class S>
void set_keyword(S& request, const spec::Field<S>& f, const py::handle& value) {
  using spec::FieldKind;
  const std::string key(f.key);
  const auto text_of = [&](const py::handle& v) -> std::string {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v)) return std::to_string(v.cast<long long>());
    throw Error(fmt::format("{}: expected text or an integer, got {}", key, py::repr(v).cast<std::string>()));
  };
  if (value.is_none()) return;
  switch (f.kind) {
    case FieldKind::flag:
      if (!py::isinstance<py::bool_>(value))
        throw Error(fmt::format("{}: expected True or False, got {}", key, py::repr(value).cast<std::string>()));
      spec::set_flag(request, f, value.cast<bool>());
      return;
    case FieldKind::node_list:
    case FieldKind::text_list:
    case FieldKind::integer_list:
    case FieldKind::choice_list:
      if (py::isinstance<py::str>(value) || !py::isinstance<py::iterable>(value)) {
        spec::set_text(request, f, text_of(value), key);
      } else {
        for (const py::handle& v : py::iter(value)) spec::set_text(request, f, text_of(v), key);
      }
      return;
    case FieldKind::quantity:
    case FieldKind::number:
      if (!py::isinstance<py::str>(value)) {
        if (py::isinstance<py::bool_>(value) ||
            (!py::isinstance<py::float_>(value) && !py::isinstance<py::int_>(value)))
          throw Error(fmt::format("{}: expected a number or text with its unit, got {}", key,
                                  py::repr(value).cast<std::string>()));
        spec::set_number(request, f, value.cast<double>(), key);
        return;
      }
      break;
    default:
      break;
  }
  spec::set_text(request, f, text_of(value), key);
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
    const spec::Field<S>* f = spec::find_field<S>(key);
    if (f == nullptr) {
      std::vector<std::string> known;
      for (const spec::Field<S>& field : spec::fields_of<S>()) known.emplace_back(field.key);
      std::string message = fmt::format("{}() got an unexpected keyword argument '{}'", A::name, key);
      if (const auto match = detail::closest_match(key, known, 2))
        message += fmt::format("; did you mean '{}'?", *match);
      throw py::type_error(message + fmt::format(" (its options are {})", detail::join_list(known, "and")));
    }
    set_keyword(request, *f, v);
  }
  return request;
}

/// A description of analysis A's options for the package, which gives feran.<name>
/// its signature and help: per key (key, kind, description, default as text).
template <AnalysisFace A>
py::list option_descriptions() {
  py::list out;
  for (const spec::Field<typename A::Spec>& f : spec::fields_of<typename A::Spec>())
    out.append(py::make_tuple(std::string(f.key), static_cast<int>(f.kind), std::string(f.doc),
                              spec::value_text(A::defaults(), f)));
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
        const OptionName name = [](std::string_view key) { return std::string(key); };
        Result out;
        {
          py::gil_scoped_release release;
          out = run_analysis<A>(file, request, name);
        }
        issue_warnings(out.source.warnings);
        // One solve: a failure leaves nothing to keep.
        if (!out.result.info.converged()) throw Error(out.result.info.message);
        return out;
      },
      py::arg("model"), std::string(A::summary).c_str());
  descriptions[py::str(std::string(A::name))] = option_descriptions<A>();
}

}  // namespace feran::python

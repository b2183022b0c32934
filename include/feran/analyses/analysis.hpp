#pragma once
/// @file
/// What an analysis is to its front ends: one folder, one face.
///
/// Each analysis lives in its own folder, `analyses/<name>/`, and shows its front ends
/// (the command line, the Python module, the report, design studies) one face: a type
/// A, listed once in analyses/list.hpp, with
///
///     static constexpr std::string_view name, summary, example, footer;
///     using Spec;     // its options: its model-file table ([static]), with a field table
///     using Options;  // what its solver takes
///     using Result;   // what it gives, with its own warnings
///     static const Spec& defaults();                 // the built-in defaults
///     static const Spec& file_table(const ModelSpec&);  // its table in a model file
///     static Options settings(const Model&, const Spec& asked, const Spec& resolved,
///                             const OptionName&);   // checks across options (or with
///                                                   // the ModelSpec after the Model)
///     static Result run(const Model&, const Options&, const RunContext&);
///     static std::vector<std::string> warnings(const Model&, const Options&, const Result&);
///     static std::string json(const Outcome<A>&), csv(const Outcome<A>&),
///                        terminal(const Outcome<A>&);
///     static const std::vector<QuantityRow>& quantities();  // optional: study quantities
///     static constexpr bool keeps_partial_results;           // optional, default false
///     static constexpr bool parallel;                        // optional: points side by side
///     static constexpr bool streams_csv;                     // optional: CSV written as it goes
///     static Spec study_request(const Model&, std::span<const QuantitySpec>);  // optional
///     static constexpr std::string_view speed_unit;          // optional: the terminal's
///
/// An analysis that keeps partial results (the modes that converged, a sweep's points
/// so far) is written by every door even when its solve failed, which the door then
/// reports; one that does not (a static solve) writes nothing then.
///
/// Every option is a key of Spec's field table (spec/fields.hpp): the command line's
/// flags, the Python keywords, their help texts and defaults and the documentation's
/// option tables are made from it, and each value is checked where its field is
/// declared (spec/request.hpp). run_analysis() is the one path from a request to an
/// outcome that every door takes.

#include <concepts>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <feran/assembly/assembler.hpp>
#include <feran/core/stop.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/result_source.hpp>
#include <feran/model/model.hpp>
#include <feran/spec/model_spec.hpp>
#include <feran/spec/request.hpp>

namespace feran {

/// What a solve may use besides its model and options: the stop request of a door
/// (Ctrl-C) and the model's assembly when a door already has it (ModelFile::assembler).
struct RunContext {
  StopToken stop = {};
  std::shared_ptr<const Assembler> assembler = {};
  /// For an analysis whose points run side by side (A::parallel): how many threads,
  /// 0 for all cores. A library caller's analyses run on one.
  int threads = 1;
  /// For an analysis that writes its CSV as it goes (A::streams_csv: a run-up's
  /// samples): receives the text, the header first, then whole rows; unset when no CSV
  /// is wanted.
  std::function<void(std::string_view)> csv = {};
  /// For a long analysis: receives how far it is (0 to 1) and its state in a few words
  /// ("t = 0.5 s, speed 40 Hz"), as often as it likes; unset when nobody watches.
  std::function<void(double, const std::string&)> progress = {};
};

/// How a door names an option in its messages: "--g" on the command line, "g" in
/// Python, "static.g" in a model file.
using OptionName = std::function<std::string(std::string_view key)>;

/// An analysis run through a door: the model it ran on, its options, its result, and
/// where it came from (with the warnings it should be read with).
template <class A>
struct Outcome {
  std::shared_ptr<const ModelFile> file;
  typename A::Options options;
  typename A::Result result;
  ResultSource source;
  const Model& model() const { return file->model; }
};

/// An analysis whose settings read another table of the model file besides its own
/// (API 684's journal loads take the gravity of [static]): settings(model, spec, …).
template <class A>
concept SettingsReadTheFile = requires(const Model& model, const ModelSpec& spec, const typename A::Spec& s,
                                       const OptionName& name) {
  { A::settings(model, spec, s, s, name) } -> std::same_as<typename A::Options>;
};

/// The face of an analysis (see the file's comment).
template <class A>
concept AnalysisFace = requires(const Model& model, const ModelSpec& spec, const typename A::Spec& s,
                                const typename A::Options& o, const typename A::Result& r, const Outcome<A>& outcome,
                                const OptionName& name, const RunContext& context) {
  { A::name } -> std::convertible_to<std::string_view>;
  { A::summary } -> std::convertible_to<std::string_view>;
  { A::defaults() } -> std::same_as<const typename A::Spec&>;
  { A::file_table(spec) } -> std::same_as<const typename A::Spec&>;
  requires SettingsReadTheFile<A> || requires {
    { A::settings(model, s, s, name) } -> std::same_as<typename A::Options>;
  };
  { A::run(model, o, context) } -> std::same_as<typename A::Result>;
  { A::warnings(model, o, r) } -> std::same_as<std::vector<std::string>>;
  { A::json(outcome) } -> std::same_as<std::string>;
  { A::csv(outcome) } -> std::same_as<std::string>;
  { A::terminal(outcome) } -> std::same_as<std::string>;
};

/// Whether analysis A solves its points side by side (its doors then offer threads).
template <class A>
constexpr bool parallel_analysis() {
  if constexpr (requires { A::parallel; })
    return A::parallel;
  else
    return false;
}

/// Whether analysis A writes its CSV as it goes (RunContext::csv), not from its result.
template <class A>
constexpr bool streams_csv() {
  if constexpr (requires { A::streams_csv; })
    return A::streams_csv;
  else
    return false;
}

/// Whether analysis A's doors write its results when its solve failed.
template <class A>
constexpr bool keeps_partial_results() {
  if constexpr (requires { A::keeps_partial_results; })
    return A::keeps_partial_results;
  else
    return false;
}

/// Every unset field of @p s taken from @p defaults.
template <class S>
S with_defaults(S s, const S& defaults) {
  for (const spec::Field<S>& f : spec::fields_of<S>())
    if (!spec::has_value(s, f))
      std::visit([&](auto member) { spec::member_of(s, member) = spec::member_of(defaults, member); }, f.member);
  return s;
}

/// The options of analysis A for @p request on @p file: the request laid over the
/// file's table (spec::overlay) and that over A's defaults, checked by A::settings.
/// Throws Error, naming options by @p name.
template <AnalysisFace A>
typename A::Options analysis_options(const ModelSpec& spec, const Model& model, const typename A::Spec& request,
                                     const OptionName& name) {
  // A request built in code is checked as one set from text is (the file's table was
  // checked by build_model()).
  for (const spec::Field<typename A::Spec>& f : spec::fields_of<typename A::Spec>())
    spec::check_field(request, f, name(f.key));
  const typename A::Spec asked = spec::overlay(request, A::file_table(spec));
  if constexpr (SettingsReadTheFile<A>)
    return A::settings(model, spec, asked, with_defaults(asked, A::defaults()), name);
  else
    return A::settings(model, asked, with_defaults(asked, A::defaults()), name);
}
template <AnalysisFace A>
typename A::Options analysis_options(const ModelFile& file, const typename A::Spec& request, const OptionName& name) {
  return analysis_options<A>(file.spec, file.model, request, name);
}

/// Options named as a model file's keys are ("static.g"), for analyses run with a
/// file's own settings (design studies, the report).
template <AnalysisFace A>
OptionName file_key_name() {
  return [](std::string_view key) { return std::string(A::name) + "." + std::string(key); };
}

/// Runs analysis A on @p file as @p request asks: its options, its solve and its
/// warnings, as every door does. Numerical trouble is in the result (SolverInfo), not
/// thrown.
template <AnalysisFace A>
Outcome<A> run_analysis(std::shared_ptr<const ModelFile> file, const typename A::Spec& request, const OptionName& name,
                        RunContext context = {}) {
  Outcome<A> out{file, analysis_options<A>(*file, request, name), {}, {}};
  context.assembler = file->assembler;
  out.result = A::run(file->model, out.options, context);
  out.source = ResultSource{file->path, file->title, A::warnings(file->model, out.options, out.result)};
  return out;
}

}  // namespace feran

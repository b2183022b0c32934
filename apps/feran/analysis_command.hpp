#pragma once
// The sub-command of an analysis, made from its face (analyses/analysis.hpp): one
// flag per key of its options' field table, with the field's description and the
// analysis's default as help; the values given are set and checked by the generic
// request step (spec/request.hpp), and the outcome written by the analysis's own
// writers. No analysis has a command file of its own.

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include <feran/analyses/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/text.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

/// "--key-name" for a field key "key_name".
std::string flag_name(std::string_view key);
/// A field's description as a help line: Markdown's backquotes dropped, the default
/// and the choices added.
std::string flag_help(std::string_view doc, const std::string& default_text, std::span<const std::string_view> choices);
/// Prints each warning once to standard error.
void print_warnings(const std::vector<std::string>& warnings);

/// A long analysis's progress on standard error, rewritten in place: first after a
/// second, then at most twice a second; end() finishes the line if one was shown.
class ProgressLine {
 public:
  explicit ProgressLine(std::string_view analysis);
  void show(double done, const std::string& state);
  void end();

 private:
  std::string analysis_;
  std::chrono::steady_clock::time_point start_, last_;
  bool shown_ = false;
};

template <AnalysisFace A>
Runner add_analysis_command(CLI::App& app) {
  using Spec = typename A::Spec;
  struct Args {
    ModelArgs model;
    OutputOptions out;
    int threads = 0;  // parallel analyses: all cores
    // What was given, per field: (field, text); flags as "true" or "false".
    std::vector<std::pair<const spec::Field<Spec>*, std::string>> given;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(std::string(A::name), std::string(A::summary));
  cmd->footer("Example:\n  " + std::string(A::example) + " --json " + std::string(A::name) + ".json\n\n" +
              std::string(A::footer));
  add_model_argument(*cmd, args->model);
  for (const spec::Field<Spec>& f : spec::fields_of<Spec>()) {
    const spec::Field<Spec>* field = &f;
    const std::string default_text =
        f.default_text.empty() ? spec::value_text(A::defaults(), f) : std::string(f.default_text);
    std::string names;
    if (!f.short_name.empty()) names.append("-").append(f.short_name).append(",");
    names += flag_name(spec::option_name(f));
    if (f.kind == spec::FieldKind::flag) {
      // A flag on by default is turned off (--no-loads), one off by default on.
      const bool on = default_text == "true";
      const std::string flag = on ? "--no-" + flag_name(spec::option_name(f)).substr(2) : names;
      cmd->add_flag_callback(
          flag, [args, field, on] { args->given.emplace_back(field, on ? "false" : "true"); },
          flag_help(std::string(f.key) + (on ? " = false: " : " = true: ") + std::string(f.doc), on ? "true" : "false",
                    {}));
      continue;
    }
    const bool list = f.kind == spec::FieldKind::node_list || f.kind == spec::FieldKind::text_list ||
                      f.kind == spec::FieldKind::integer_list || f.kind == spec::FieldKind::choice_list;
    if (list) {
      // Each occurrence adds to the list ('--probe a --probe b'); counts also as
      // '--orders 1,2'.
      CLI::Option* option = cmd->add_option_function<std::vector<std::string>>(
          names,
          [args, field](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) args->given.emplace_back(field, text);
          },
          flag_help(f.doc, default_text, f.choices));
      repeatable(option);
      if (f.kind == spec::FieldKind::integer_list) option->delimiter(',');
      continue;
    }
    cmd->add_option_function<std::string>(
        names, [args, field](const std::string& text) { args->given.emplace_back(field, text); },
        flag_help(f.doc, default_text, f.choices));
  }
  if constexpr (parallel_analysis<A>()) add_threads_option(*cmd, args->threads);
  add_output_options(*cmd, args->out);
  if constexpr (requires { A::speed_unit; }) args->out.speed_unit = A::speed_unit;

  return [args]() {
    CommandOutputs outputs(args->model, args->out, streams_csv<A>());
    const auto file = std::make_shared<const ModelFile>(read_model(args->model));
    Spec request;
    for (const auto& [field, text] : args->given) {
      if (field->kind == spec::FieldKind::flag)
        spec::set_flag(request, *field, text == "true");
      else
        spec::set_text(request, *field, text, flag_name(spec::option_name(*field)));
    }
    RunContext context{.stop = interrupt_token(), .threads = args->threads};
    if (streams_csv<A>() && outputs.files.wanted(outputs.csv))
      context.csv = [&outputs](std::string_view text) { outputs.files.append(outputs.csv, text); };
    ProgressLine progress(A::name);
    if (!args->out.quiet)
      context.progress = [&progress](double done, const std::string& state) { progress.show(done, state); };
    Outcome<A> outcome = run_analysis<A>(
        file, request, [](std::string_view key) { return flag_name(spec::option_name<Spec>(key)); }, context);
    progress.end();
    print_warnings(outcome.source.warnings);
    outcome.source.speed_unit = args->out.speed_unit;
    const SolverInfo& info = outcome.result.info;
    if constexpr (!keeps_partial_results<A>()) {
      if (const auto stopped = stopped_single_solve()) return *stopped;
      if (!info.converged()) {
        // One solve: nothing was computed before the failure, so nothing is written.
        std::fprintf(stderr, "feran: error: %s\n", printable(info.message, true).c_str());
        return static_cast<int>(numerical_failure);
      }
    }
    outputs.set_json([&] { return A::json(outcome); });
    if constexpr (!streams_csv<A>()) outputs.set_csv([&] { return A::csv(outcome); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(A::terminal(outcome).c_str(), stdout);
    // The results so far were written; a failure or a stop is said and exits non-zero.
    return finish(info);
  };
}

}  // namespace feran::app

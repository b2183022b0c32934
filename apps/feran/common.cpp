#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/core/text.hpp>
#include <feran/core/units.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

CLI::Option* repeatable(CLI::Option* option) {
  return option->take_all()->expected(1)->allow_extra_args(false);
}

void add_model_argument(CLI::App& cmd, ModelArgs& model) {
  cmd.add_option("model", model.path, "Model file (TOML, see docs/model-format.md)")->required();
  repeatable(cmd.add_option("--set", model.assignments,
                            "Set a number of the model by its path, with its unit, e.g.\n"
                            "--set 'springs[bearing 1].ky=2e7 N/m' (repeatable; 'feran params MODEL' lists them)"))
      ->type_name("PATH=VALUE");
}

ModelFile read_model(const ModelArgs& model) { return read_model_file(model.path, model.assignments); }

std::optional<std::pair<double, double>> frequency_span_hz(const std::vector<double>& frequencies_hz) {
  std::optional<std::pair<double, double>> span;
  for (const double f : frequencies_hz) {
    if (!std::isfinite(f)) continue;
    const double w = 2.0 * pi * std::abs(f);
    span = span ? std::pair{std::min(span->first, w), std::max(span->second, w)} : std::pair{w, w};
  }
  return span;
}

std::vector<std::string> speed_range_warnings(const Model& model, double low, double high,
                                              std::optional<std::pair<double, double>> frequencies) {
  std::vector<std::string> warnings = range_warnings(model, low, high, frequencies);
  for (const std::string& w : warnings) std::fprintf(stderr, "feran: warning: %s\n", printable(w, true).c_str());
  return warnings;
}

void add_output_options(CLI::App& cmd, OutputOptions& out) {
  cmd.add_option("--json", out.json_path, "Write the results as JSON to this file (docs/output-format.md)");
  cmd.add_option("--csv", out.csv_path, "Write the results as CSV to this file (docs/output-format.md)");
  cmd.add_flag("-q,--quiet", out.quiet, "Do not print the table on standard output");
  cmd.add_option("--speed-unit", out.speed_unit, "Speeds in the terminal tables: Hz or rpm (default Hz; api684: rpm), frequencies then in Hz or cpm; files keep their units")
      ->check(CLI::IsMember({"Hz", "rpm"}));
}

std::optional<double> optional_speed(const std::string& text, const std::string& option) {
  if (text.empty()) return std::nullopt;
  return parse_speed_text(text, option);
}

CommandOutputs::CommandOutputs(const ModelArgs& model, const OutputOptions& out, bool stream_csv)
    : files(model.path) {
  json = files.add("--json", out.json_path);
  csv = files.add("--csv", out.csv_path, stream_csv);
}

void CommandOutputs::set_json(const std::function<std::string()>& make_text) {
  if (files.wanted(json)) files.write(json, make_text());
}

void CommandOutputs::set_csv(const std::function<std::string()>& make_text) {
  if (files.wanted(csv)) files.write(csv, make_text());
}

int finish(const SolverInfo& info) {
  if (info.status == SolverStatus::interrupted) {
    const int signal = interrupt_signal();
    std::fprintf(stderr, "feran: interrupted by %s: %s (the results up to there were written, marked incomplete)\n",
                 signal_name(signal), printable(info.message, true).c_str());
    return interrupted_base + signal;
  }
  if (!info.converged()) {
    std::fprintf(stderr, "feran: error: %s (results up to there were kept)\n", printable(info.message, true).c_str());
    return static_cast<int>(numerical_failure);
  }
  return static_cast<int>(ok);
}

std::optional<int> stopped_single_solve() {
  const int signal = interrupt_signal();
  if (signal == 0) return std::nullopt;
  std::fprintf(stderr, "feran: interrupted by %s: nothing written (one solve has no partial results)\n",
               signal_name(signal));
  return interrupted_base + signal;
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads, "Threads for the sweep's points (default 0: all cores; at most 1024)")
      ->check(non_negative_number())
      ->check(CLI::Validator(
          [](std::string& text) {
            return std::strtod(text.c_str(), nullptr) > 1024 ? fmt::format("at most 1024 threads, got {}", text)
                                                              : std::string();
          },
          ""));
}

namespace {

// A check that the option's text is a finite number satisfying @p ok.
CLI::Validator number_check(const char* requirement, bool (*ok)(double)) {
  return CLI::Validator(
      [requirement, ok](std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(v))
          return fmt::format("'{}' is not a finite number", text);
        if (!ok(v)) return fmt::format("must be {}, got {}", requirement, text);
        return {};
      },
      requirement);
}

}  // namespace

CLI::Validator positive_number() {
  return number_check("positive", [](double v) { return v > 0.0; });
}

CLI::Validator non_negative_number() {
  return number_check("non-negative", [](double v) { return v >= 0.0; });
}

}  // namespace feran::app

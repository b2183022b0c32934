#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <feran/analyses/settings.hpp>
#include <feran/core/error.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/output_files.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/core/text.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/units.hpp>

#include "analysis_command.hpp"
#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

CLI::Option* repeatable(CLI::Option* option) { return option->take_all()->expected(1)->allow_extra_args(false); }

void add_model_argument(CLI::App& cmd, ModelArgs& model) {
  cmd.add_option("model", model.path, "Model file (TOML, see docs/model-format.md)")->required();
  repeatable(cmd.add_option("--set", model.assignments,
                            "Set a number of the model by its path, with its unit, e.g.\n"
                            "--set 'springs[bearing 1].ky=2e7 N/m' (repeatable; 'feran params MODEL' lists them)"))
      ->type_name("PATH=VALUE");
}

namespace {

// Models from this many DOFs on (6 per shaft element) are read by a program whose
// malloc asks for transparent huge pages.
constexpr long huge_page_dofs = 30000;
constexpr const char* huge_page_tunable = "glibc.malloc.hugetlb";

// The program again, same arguments, with glibc's malloc told to use transparent huge
// pages (the tunable glibc.malloc.hugetlb=1, read only when a program starts). A
// large model's set-up is mostly first touches of fresh heap pages, each a page
// fault, and on a virtual machine a fault is expensive: at 60 000 DOF the set-up
// takes 0.13 s instead of 0.44 s (docs/performance.md). Returns only if the program
// could not be started again (then it goes on as it is).
void restart_with_huge_pages() {
  std::FILE* f = std::fopen("/proc/self/cmdline", "rb");
  if (f == nullptr) return;
  std::string bytes;
  char buffer[4096];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, f)) > 0;) bytes.append(buffer, got);
  std::fclose(f);
  std::vector<char*> argv;
  for (std::size_t at = 0; at < bytes.size(); at = bytes.find('\0', at) + 1) argv.push_back(bytes.data() + at);
  if (argv.empty()) return;
  argv.push_back(nullptr);
  const char* old = std::getenv("GLIBC_TUNABLES");
  const std::string tunables =
      (old != nullptr && *old != '\0' ? std::string(old) + ":" : std::string{}) + huge_page_tunable + "=1";
  if (::access("/proc/self/exe", X_OK) != 0 || setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  std::fflush(nullptr);
  // The output files a command opened before reading its model are made again by the
  // new program: their temporary files would otherwise stay behind.
  remove_temporary_outputs();
  execv("/proc/self/exe", argv.data());
}

}  // namespace

ModelFile read_model(const ModelArgs& model) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables == nullptr || std::strstr(tunables, huge_page_tunable) == nullptr) {
    // The spec only (its problems are reported as the full read would): its shaft
    // elements tell the model's size before anything large is allocated.
    const ModelSpec spec = read_model_spec(read_text_file(model.path), model.path);
    long elements = 0;
    for (const ShaftSpec& shaft : spec.shafts)
      for (const SectionSpec& section : shaft.sections) elements += std::max(section.elements, 0);
    if (6 * elements >= huge_page_dofs) restart_with_huge_pages();
  }
  return read_model_file(model.path, model.assignments);
}

std::optional<std::pair<double, double>> frequency_span_hz(const std::vector<double>& frequencies_hz) {
  return frequency_span(frequencies_hz);
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
  cmd.add_option("--speed-unit", out.speed_unit,
                 "Speeds in the terminal tables: Hz or rpm (default Hz; api684: rpm), frequencies then in Hz or cpm; "
                 "files keep their units")
      ->check(CLI::IsMember({"Hz", "rpm"}));
}

std::optional<double> optional_speed(const std::string& text, const std::string& option) {
  if (text.empty()) return std::nullopt;
  return parse_speed_text(text, option);
}

CommandOutputs::CommandOutputs(const ModelArgs& model, const OutputOptions& out, bool stream_csv) : files(model.path) {
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

namespace feran::app {

std::string flag_name(std::string_view key) {
  std::string out = "--";
  for (const char c : key) out += c == '_' ? '-' : c;
  return out;
}

std::string flag_help(std::string_view doc, const std::string& default_text,
                      std::span<const std::string_view> choices) {
  std::string out;
  for (const char c : doc)
    if (c != '`') out += c;
  if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  if (!choices.empty()) {
    std::vector<std::string> words(choices.begin(), choices.end());
    out += "; one of " + detail::join_list(words);
  }
  if (!default_text.empty()) {
    std::string shown;  // as the documentation's default, without its Markdown
    for (const char c : default_text)
      if (c != '`') shown += c;
    out += shown.starts_with("— ") ? " " + shown.substr(std::string_view("— ").size()) : " (default " + shown + ")";
  }
  return out;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::fprintf(stderr, "feran: warning: %s\n", printable(w, true).c_str());
}

ProgressLine::ProgressLine(std::string_view analysis)
    : analysis_(analysis), start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressLine::show(double done, const std::string& state) {
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(500)) return;
  last_ = now;
  shown_ = true;
  std::fprintf(stderr, "\r  %s: %s (%3.0f %%)   ", analysis_.c_str(), state.c_str(), 100 * done);
}

void ProgressLine::end() {
  if (shown_) std::fputs("\n", stderr);
  shown_ = false;
}

}  // namespace feran::app

#include <cstdio>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/text.hpp>
#include <feran/io/html_report.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/output_files.hpp>
#include <feran/io/report_config.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

namespace {
struct ReportArgs {
  ModelArgs model;
  std::string config;
  std::string output;
  std::string study;
  std::string speed_unit;
  int threads = 0;
  bool quiet = false;
};

std::string command_line(int argc, char** argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) out += ' ';
    const std::string a = argv[i];
    out += a.find_first_of(" '\"") == std::string::npos ? a : "'" + a + "'";
  }
  return out;
}
}  // namespace

Runner add_report_command(CLI::App& app, int argc, char** argv) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Interactive HTML report: the rotor, Campbell diagram, damping, mode shapes, unbalance response, "
      "API 684 margins and maps, stability, run-up, a study's results");
  cmd->footer(
      "Example:\n  feran report examples/01_internal_damping/model.toml -o report.html\n"
      "  feran report examples/05_api684_bearings/model.toml --config report.toml -o report.html\n\n"
      "One self-contained file: plotly.js is inside it, and it opens without a network.\n"
      "The analyses take their settings from the model's tables and REPORT.toml\n"
      "(docs/report.md); the API 617/684 section appears when [api684] gives the operating range.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--config", args->config, "Report configuration (TOML, docs/report.md)");
  cmd->add_option("-o,--output", args->output, "The HTML file to write")->required();
  cmd->add_option("--study", args->study, "A design study's output directory to show (feran study -o DIR)");
  cmd->add_option("--speed-unit", args->speed_unit, "rpm (default) or Hz")->check(CLI::IsMember({"rpm", "Hz"}));
  add_threads_option(*cmd, args->threads);
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  const std::string command = command_line(argc, argv);

  return [args, command]() {
    OutputFiles files(args->model.path);
    const int html = files.add("--output", args->output);
    const ModelFile file = read_model(args->model);
    ReportOptions options;
    options.command = command;
    options.version = FERAN_VERSION;
    options.n_threads = args->threads;
    files.add_input(args->config, "the report configuration");
    if (!args->config.empty()) read_report_config_file(args->config, file.model, options);
    if (!args->study.empty()) options.study_directory = args->study;
    for (const std::string& input : report_study_files(options)) files.add_input(input, "a file of the study shown");
    if (!args->speed_unit.empty()) options.speed_unit = args->speed_unit;
    options.stop = interrupt_token();
    std::string verdicts;
    const std::string text = html_report(file, options, &verdicts);
    files.write(html, text);
    files.commit();
    if (const int signal = interrupt_signal()) {
      std::fprintf(stderr, "feran: interrupted by %s: the report up to there was written to %s, marked incomplete\n",
                   signal_name(signal), printable(args->output, true).c_str());
      return interrupted_base + signal;
    }
    if (!args->quiet) {
      std::printf("feran report: wrote %s (%.1f MB)\n", args->output.c_str(), static_cast<double>(text.size()) / 1e6);
      std::printf("verdicts:\n%s", printable(verdicts, true).c_str());
    }
    return static_cast<int>(ok);
  };
}

}  // namespace feran::app

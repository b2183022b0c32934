#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include <feran/analyses/modal/campbell.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

#include <feran/analyses/settings.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

namespace {
struct CampbellArgs {
  ModelArgs model;
  std::string start, stop;
  std::optional<int> points;
  int modes = 0;
  std::vector<int> orders;
  std::string solver = "auto";
  int threads = 0;
  OutputOptions out;
};
}  // namespace

Runner add_campbell_command(CLI::App& app) {
  auto args = std::make_shared<CampbellArgs>();
  CLI::App* cmd = app.add_subcommand(
      "campbell", "Campbell diagram: tracked modes over a speed range, critical speeds, stability threshold");
  cmd->footer(
      "Example:\n  feran campbell examples/01_internal_damping/model.toml --start 0Hz --stop 80Hz "
      "--points 161 \\\n      --orders 1 --json campbell.json --csv campbell.csv\n\n"
      "Unset options take their values from the model file's [campbell] table, else\n"
      "start 0, 101 points, 8 modes, order 1; --stop is required if the file has none.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--start", args->start, "First speed with unit: 0Hz, 0rpm, 0rad/s");
  cmd->add_option("--stop", args->stop, "Last speed with unit: 80Hz, 4800rpm, 502.7rad/s");
  cmd->add_option("-p,--points", args->points, "Number of evenly spaced speeds (2 to 1000000)");
  cmd->add_option("-n,--modes", args->modes, "Number of modes to track (the lowest at the first speed)")
      ->check(positive_number());
  cmd->add_option("-k,--orders", args->orders, "Harmonic orders k of the excitation lines f = k x speed, e.g. 1,2")
      ->delimiter(',')
      ->check(positive_number());
  cmd->add_option("--solver", args->solver, "Eigen solver: auto, dense or sparse (see 'feran modal --help')")
      ->check(CLI::IsMember({"auto", "dense", "sparse"}));
  add_threads_option(*cmd, args->threads);
  add_output_options(*cmd, args->out);

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    CampbellRequest request;
    if (!args->start.empty()) request.start = parse_speed_text(args->start, "--start");
    if (!args->stop.empty()) request.stop = parse_speed_text(args->stop, "--stop");
    request.points = args->points;
    if (args->modes > 0) request.modes = args->modes;
    request.orders = args->orders;
    request.solver = parse_solver_name(args->solver, "--solver");
    request.n_threads = args->threads;
    CampbellOptions options = campbell_settings(file.spec.campbell, request);
    options.stop = interrupt_token();

    const CampbellResult result = run_campbell(file.model, options, file.assembler);
    std::vector<double> frequencies;
    for (const TrackedMode& m : result.modes)
      frequencies.insert(frequencies.end(), m.frequency_hz.begin(), m.frequency_hz.end());
    const ResultSource source{
        file.path, file.title,
        speed_range_warnings(file.model, options.speeds.front(), options.speeds.back(), frequency_span_hz(frequencies)),
        args->out.speed_unit};
    outputs.set_json([&] { return campbell_json(result, options, file.model, source); });
    outputs.set_csv([&] { return campbell_csv(result, file.model); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(campbell_report(result, options, file.model, source).c_str(), stdout);
    return finish(result.info);
  };
}

}  // namespace feran::app

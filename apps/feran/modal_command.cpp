#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

#include <feran/analyses/settings.hpp>

#include "commands.hpp"

namespace feran::app {

namespace {
struct ModalArgs {
  ModelArgs model;
  std::string speed;
  int modes = 0;
  std::string solver = "auto";
  bool shapes = false;
  OutputOptions out;
};

}  // namespace

Runner add_modal_command(CLI::App& app) {
  auto args = std::make_shared<ModalArgs>();
  CLI::App* cmd = app.add_subcommand("modal", "Natural frequencies, damping and mode shapes at one speed");
  cmd->footer(
      "Example:\n  feran modal examples/01_internal_damping/model.toml --speed 30Hz --json modes.json\n\n"
      "The speed defaults to [modal] speed in the model file, else 0. Modes are sorted by\n"
      "frequency; rigid-body modes are marked as such.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("-s,--speed", args->speed, "Rotor speed with unit: 30Hz, 1800rpm or 188.5rad/s");
  cmd->add_option("-n,--modes", args->modes, "Number of modes (lowest first); default: all (dense) or 12 (sparse)")
      ->check(positive_number());
  cmd->add_option("--solver", args->solver,
                  "Eigen solver: auto (dense for all modes up to 400 DOF; with --modes, for each decoupled block "
                  "the one a cost model expects to be faster), dense (LAPACK QR) or sparse (lowest modes, "
                  "shift-invert Arnoldi)")
      ->check(CLI::IsMember({"auto", "dense", "sparse"}));
  cmd->add_flag("--shapes", args->shapes, "Include the mode shapes in the JSON output");
  add_output_options(*cmd, args->out);

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    ModalRequest request;
    if (!args->speed.empty()) request.speed = parse_speed_text(args->speed, "--speed");
    if (args->modes > 0) request.modes = args->modes;
    request.solver = parse_solver_name(args->solver, "--solver");
    request.shapes = args->shapes;
    const ModalSettings settings = modal_settings(file.spec.modal, request);
    const ModalResult result = run_modal(file.model, settings.speed, settings.options, file.assembler);
    std::vector<double> frequencies;
    for (const Mode& m : result.modes) frequencies.push_back(m.frequency_hz);
    const ResultSource source{
        file.path, file.title,
        speed_range_warnings(file.model, settings.speed, settings.speed, frequency_span_hz(frequencies)),
        args->out.speed_unit};
    if (const auto stopped = stopped_single_solve()) return *stopped;
    outputs.set_json([&] { return modal_json(result, file.model, source, args->shapes); });
    outputs.set_csv([&] { return modal_csv(result); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(modal_report(result, file.model, source).c_str(), stdout);
    return finish(result.info);
  };
}

}  // namespace feran::app

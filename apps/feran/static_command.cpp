#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include <feran/analyses/static/static_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/text.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/core/units.hpp>

#include <feran/analyses/settings.hpp>

#include <feran/io/option_text.hpp>

#include "commands.hpp"

namespace feran::app {

namespace {
struct StaticArgs {
  ModelArgs model;
  std::string gravity;
  std::string g;
  std::string speed;
  bool no_loads = false;
  bool no_stability = false;
  OutputOptions out;
};
}  // namespace

Runner add_static_command(CLI::App& app) {
  auto args = std::make_shared<StaticArgs>();
  CLI::App* cmd = app.add_subcommand(
      "static", "Static deflection, spring and support forces, shaft stresses under gravity and static loads");
  cmd->footer(
      "Example:\n  feran static examples/02_centrifuge/model.toml --gravity -x --json static.json\n\n"
      "Gravity comes from --gravity, else the model's [static] table, else -y at 9.81 m/s^2.\n"
      "The model's [[static_loads]] act too unless --no-loads is given.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--gravity", args->gravity, "Direction of gravity: +x, -x, +y, -y, +z, -z or none")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z", "x", "y", "z", "none"}));
  cmd->add_option("--g", args->g, "Gravitational acceleration with unit (default 9.81m/s^2)");
  cmd->add_option("-s,--speed", args->speed, "Speed at which speed-dependent coefficients are taken (default 0)");
  cmd->add_flag("--no-loads", args->no_loads, "Leave the model's [[static_loads]] out");
  cmd->add_flag("--no-stability", args->no_stability,
                "Do not judge whether the rotor stays at the equilibrium when disturbed (by default the result "
                "says whether the equilibrium is stable, from the motion linearised about it)");
  add_output_options(*cmd, args->out);

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    StaticRequest request;
    if (!args->g.empty()) request.g = parse_quantity(args->g, Quantity::acceleration);
    if (!args->gravity.empty()) request.gravity = args->gravity;
    if (!args->speed.empty()) request.speed = parse_speed_text(args->speed, "--speed");
    request.loads = !args->no_loads;
    request.stability = !args->no_stability;
    const StaticOptions options = static_settings(file.spec.static_, request);
    const StaticResult result = run_static(file.model, options);
    if (const auto stopped = stopped_single_solve()) return *stopped;
    if (!result.info.converged()) {
      // One solve: nothing was computed before the failure, so nothing is written.
      std::fprintf(stderr, "feran: error: %s\n", printable(result.info.message, true).c_str());
      return static_cast<int>(numerical_failure);
    }
    const ResultSource source{file.path, file.title, speed_range_warnings(file.model, options.speed, options.speed),
                              args->out.speed_unit};
    outputs.set_json([&] { return static_json(result, options, file.model, source); });
    outputs.set_csv([&] { return static_csv(result, file.model); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(static_report(result, options, file.model, source).c_str(), stdout);
    return static_cast<int>(ok);
  };
}

}  // namespace feran::app

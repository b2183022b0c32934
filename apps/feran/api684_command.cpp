#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

#include <feran/analyses/settings.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

namespace {
struct Api684Args {
  ModelArgs model;
  std::string min_speed, max_speed, stop;
  std::optional<int> points, modes;
  std::string unbalance;
  std::optional<double> multiple;
  std::vector<std::string> probes, bearings;
  bool no_map = false, no_stability = false;
  std::optional<double> map_low, map_high, anticipated_q;
  std::optional<int> map_points;
  std::string stability_node;
  int threads = 0;
  OutputOptions out;
};
}  // namespace

Runner add_api684_command(CLI::App& app) {
  auto args = std::make_shared<Api684Args>();
  CLI::App* cmd = app.add_subcommand(
      "api684",
      "API 617 / API 684 lateral analyses: unbalance responses with amplification factors and separation "
      "margins, the undamped critical speed map, level I stability");
  cmd->footer(
      "Example:\n  feran api684 examples/05_api684_bearings/model.toml --min-speed 9000rpm --max-speed 11000rpm \\\n"
      "      --anticipated-q 2e6 --json api684.json\n\n"
      "Unset options come from the model's [api684] table (docs/model-format.md); the\n"
      "journal loads of 4W/N use the gravity of its [static] table (default -y).\n"
      "The formulas and their sources: docs/theory/api684.md.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--min-speed", args->min_speed, "Minimum operating speed with unit (9000rpm)");
  cmd->add_option("--max-speed", args->max_speed, "Maximum continuous speed with unit (11000rpm)");
  cmd->add_option("--stop", args->stop, "Last speed of the unbalance responses (default 2 x max speed)");
  cmd->add_option("-p,--points", args->points, "Speeds of the unbalance responses (default 401)");
  cmd->add_option("-n,--modes", args->modes, "Forward modes excited by the analytical unbalance (default 2)");
  cmd->add_option("--unbalance", args->unbalance, "4W/N (the analytical unbalance, default) or model")
      ->check(CLI::IsMember({"4W/N", "model"}));
  cmd->add_option("--unbalance-multiple", args->multiple, "The analytical unbalance is this many times 4W/N")
      ->check(positive_number());
  repeatable(cmd->add_option("--probe", args->probes, "Node whose response is judged; repeat for several"));
  repeatable(cmd->add_option("--bearing", args->bearings, "A bearing ([[springs]] name); repeat for several"));
  cmd->add_flag("--no-map", args->no_map, "Leave out the undamped critical speed map");
  cmd->add_option("--map-low", args->map_low, "Lowest stiffness of the map [N/m]")->check(positive_number());
  cmd->add_option("--map-high", args->map_high, "Highest stiffness of the map [N/m]")->check(positive_number());
  cmd->add_option("--map-points", args->map_points, "Stiffness values of the map (default 41)");
  cmd->add_flag("--no-stability", args->no_stability, "Leave out the level I stability analysis");
  cmd->add_option("--stability-node", args->stability_node, "Node where the cross-coupling Q acts");
  cmd->add_option("--anticipated-q", args->anticipated_q, "Anticipated cross-coupling q_A [N/m] for the screening")
      ->check(positive_number());
  add_threads_option(*cmd, args->threads);
  add_output_options(*cmd, args->out);
  args->out.speed_unit = "rpm";  // API 617/684's own unit, unless --speed-unit says otherwise

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    const Model& model = file.model;
    Api684Request request;
    request.min_speed = optional_speed(args->min_speed, "--min-speed");
    request.max_speed = optional_speed(args->max_speed, "--max-speed");
    request.stop = optional_speed(args->stop, "--stop");
    request.points = args->points;
    request.modes = args->modes;
    if (!args->unbalance.empty()) request.model_unbalance = args->unbalance == "model";
    request.unbalance_multiple = args->multiple;
    for (const std::string& p : args->probes) request.probes.push_back(find_node_reference(model, p, "--probe"));
    for (const std::string& b : args->bearings) request.bearings.push_back(bearing_element(model, b));
    request.map = !args->no_map;
    request.map_low = args->map_low;
    request.map_high = args->map_high;
    request.map_points = args->map_points;
    request.stability = !args->no_stability;
    if (!args->stability_node.empty())
      request.stability_node = find_node_reference(model, args->stability_node, "--stability-node");
    request.anticipated_q = args->anticipated_q;
    request.n_threads = args->threads;
    Api684Options options = api684_settings(model, file.spec, request);
    options.stop = interrupt_token();

    const Api684Result result = run_api684(model, options);
    const ResultSource source{file.path, file.title,
                              speed_range_warnings(model, options.speeds.front(), options.speeds.back()),
                              args->out.speed_unit};
    outputs.set_json([&] { return api684_json(result, model, source); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(api684_report(result, model, source).c_str(), stdout);
    return finish(result.info);
  };
}

}  // namespace feran::app

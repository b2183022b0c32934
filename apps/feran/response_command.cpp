#include <algorithm>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include <feran/analyses/harmonic/harmonic_response.hpp>
#include <feran/core/error.hpp>
#include <feran/core/text.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/core/units.hpp>

#include <feran/analyses/settings.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

namespace {

struct ResponseArgs {
  ModelArgs model;
  std::string start, stop;
  std::optional<int> points;
  std::string speed;
  std::string freq_start, freq_stop;
  std::optional<int> freq_points;
  std::vector<std::string> probes;
  std::vector<std::string> forces;
  double loss_factor = -1.0;
  bool no_unbalance = false;
  bool no_stability = false;
  std::string stations;
  int threads = 0;
  OutputOptions out;
};

}  // namespace

Runner add_response_command(CLI::App& app) {
  auto args = std::make_shared<ResponseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "response", "Steady-state response to unbalance and harmonic forces: orbits, bearing forces, stresses");
  cmd->footer(
      "Examples:\n"
      "  feran response examples/01_internal_damping/model.toml --start 0Hz --stop 80Hz --points 161 \\\n"
      "      --probe rotor --json response.json --csv response.csv\n"
      "  feran response MODEL --speed 30Hz --freq-start 1Hz --freq-stop 200Hz --freq-points 400 \\\n"
      "      --force rotor:y:1N --no-unbalance --probe rotor        (frequency response function)\n\n"
      "A speed sweep excites at the rotor speed (unbalances and the model's [[forces]]); a\n"
      "frequency sweep (--freq-start/--freq-stop) holds the rotor at --speed and excites\n"
      "with the forces at each frequency. Unset options come from the model's [response]\n"
      "table; probes default to every node carrying an unbalance.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--start", args->start, "Speed sweep: first speed with unit (0Hz, 0rpm)");
  cmd->add_option("--stop", args->stop, "Speed sweep: last speed with unit (80Hz, 4800rpm)");
  cmd->add_option("-p,--points", args->points, "Number of evenly spaced points (1 to 1000000)");
  cmd->add_option("-s,--speed", args->speed,
                  "Rotor speed of a frequency sweep (default 0); alone, the response at that one speed");
  cmd->add_option("--freq-start", args->freq_start, "Frequency sweep: first excitation frequency (1Hz)");
  cmd->add_option("--freq-stop", args->freq_stop, "Frequency sweep: last excitation frequency (200Hz)");
  cmd->add_option("--freq-points", args->freq_points, "Frequency sweep: number of frequencies (default 201)");
  repeatable(cmd->add_option("--probe", args->probes, "Node to report (name or number); repeat for several"));
  repeatable(cmd->add_option("--force", args->forces,
                             "Add a harmonic force NODE:DIRECTION:AMPLITUDE[:PHASE]; DIRECTION x, y, z, rx, ry, rz "
                             "(fixed), rotating or rotating_moment (turning with the shaft), e.g. rotor:y:10N:90deg"));
  cmd->add_option("--loss-factor", args->loss_factor, "Global hysteretic loss factor eta: adds j*eta*K")
      ->check(non_negative_number());
  cmd->add_flag("--no-unbalance", args->no_unbalance, "Leave the model's unbalances out");
  cmd->add_flag("--no-stability", args->no_stability,
                "Do not judge the rotor's stability at each point (by default each point says whether the rotor is "
                "unstable at its speed, where the response is no steady state)");
  cmd->add_option("--stations", args->stations,
                  "Section forces and stresses at the shaft stations: all (every station at every point), "
                  "summary (per point the largest values and their place; default) or none")
      ->check(CLI::IsMember({"all", "summary", "none"}));
  add_threads_option(*cmd, args->threads);
  add_output_options(*cmd, args->out);

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    const Model& model = file.model;
    ResponseRequest request;
    request.unbalance = !args->no_unbalance;
    request.stability = !args->no_stability;
    request.n_threads = args->threads;
    if (args->loss_factor >= 0) request.loss_factor = args->loss_factor;
    for (const std::string& f : args->forces) request.extra_forces.push_back(parse_force_text(model, f, "--force"));
    request.start = optional_speed(args->start, "--start");
    request.stop = optional_speed(args->stop, "--stop");
    request.speed = optional_speed(args->speed, "--speed");
    request.freq_start = optional_speed(args->freq_start, "--freq-start");
    request.freq_stop = optional_speed(args->freq_stop, "--freq-stop");
    request.points = args->points;
    request.freq_points = args->freq_points;
    for (const std::string& p : args->probes) request.probes.push_back(find_node_reference(model, p, "--probe"));
    if (!args->stations.empty()) request.stations = station_output(args->stations);
    HarmonicOptions options = response_settings(model, file.spec.response, request);
    options.stop = interrupt_token();

    const HarmonicResult result = run_harmonic_response(model, options);
    const Real low = options.frequencies.empty() ? options.speeds.front() : options.speed;
    const Real high = options.frequencies.empty() ? options.speeds.back() : options.speed;
    std::optional<std::pair<double, double>> frequencies;  // a speed sweep's are synchronous
    if (!options.frequencies.empty())
      frequencies = std::pair{*std::min_element(options.frequencies.begin(), options.frequencies.end()),
                              *std::max_element(options.frequencies.begin(), options.frequencies.end())};
    ResultSource source{file.path, file.title, speed_range_warnings(model, low, high, frequencies),
                        args->out.speed_unit};
    for (const std::string& w : clearance_warnings(result, model)) {
      std::fprintf(stderr, "feran: warning: %s\n", printable(w, true).c_str());
      source.warnings.push_back(w);
    }
    outputs.set_json([&] { return response_json(result, options, model, source); });
    outputs.set_csv([&] { return response_csv(result, model); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(response_report(result, options, model, source).c_str(), stdout);
    return finish(result.info);
  };
}

}  // namespace feran::app

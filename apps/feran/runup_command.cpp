#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/core/text.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/node_reference.hpp>
#include <feran/io/option_text.hpp>
#include <feran/io/report.hpp>
#include <feran/io/runup_writer.hpp>
#include <feran/core/units.hpp>

#include <feran/analyses/settings.hpp>

#include "commands.hpp"
#include "interrupt.hpp"

namespace feran::app {

namespace {

struct RunupArgs {
  ModelArgs model;
  std::string speed, from, to, ramp_time, table;
  std::string duration;
  std::string integrator;
  std::string dt, output_interval;
  double rtol = 0, atol = 0;
  std::vector<std::string> probes, springs;
  double newton_tol = 0;
  int newton_max_iter = 0;
  bool allow_unstable = false;
  std::string jacobian = "exact";
  int jacobian_interval = IntegratorSettings{}.jacobian_interval;
  std::string blowup;
  int modes = 0;
  bool static_loads = false;
  bool gravity = false;
  std::string start;
  bool drive = false;
  OutputOptions out;
};

}  // namespace

Runner add_runup_command(CLI::App& app) {
  auto args = std::make_shared<RunupArgs>();
  CLI::App* cmd = app.add_subcommand(
      "runup", "Run-up (time integration along a speed profile): time histories, |r| envelope, forces");
  cmd->footer(
      "Examples:\n"
      "  feran runup examples/01_internal_damping/model.toml --from 0Hz --to 80Hz --ramp-time 5s \\\n"
      "      --integrator trapezoidal --dt 1e-4s --probe rotor --csv runup.csv\n"
      "  feran runup MODEL --speed 40Hz --duration 2s --integrator ros34pw2 --rtol 1e-6\n\n"
      "The speed profile is one of: --speed (constant), --from/--to/--ramp-time (linear,\n"
      "then held), --table TIME:SPEED,... (piecewise linear). Unset options come from the\n"
      "model's [runup] table. Integrators: trapezoidal (Newton), rk3 (explicit),\n"
      "wolfbrandt (W-method, order 2), ros34pw2 (W-method, order 3, adaptive).");
  add_model_argument(*cmd, args->model);
  cmd->add_option("-s,--speed", args->speed, "Constant speed with unit (40Hz, 2400rpm)");
  cmd->add_option("--from", args->from, "Ramp: start speed (default 0Hz)");
  cmd->add_option("--to", args->to, "Ramp: end speed (80Hz)");
  cmd->add_option("--ramp-time", args->ramp_time, "Ramp: time to go from --from to --to (5s)");
  cmd->add_option("--table", args->table, "Piecewise-linear profile TIME:SPEED,... (0s:0Hz,2s:50Hz,5s:50Hz)");
  cmd->add_option("-t,--duration", args->duration, "Simulated time (default: the ramp or table time)");
  cmd->add_option("-i,--integrator", args->integrator, "trapezoidal (default), rk3, wolfbrandt or ros34pw2")
      ->check(CLI::IsMember(integrator_names()));
  cmd->add_option("--dt", args->dt, "Time step (fixed-step methods) or first step (ros34pw2), e.g. 1e-4s");
  cmd->add_option("--rtol", args->rtol, "ros34pw2: relative tolerance (default 1e-5)")->check(positive_number());
  cmd->add_option("--atol", args->atol, "ros34pw2: absolute tolerance (default 1e-8)")->check(positive_number());
  cmd->add_option("--output-interval", args->output_interval, "Time between recorded samples (default 1ms)");
  repeatable(cmd->add_option("--probe", args->probes, "Node to record (name or number); repeat for several"));
  repeatable(cmd->add_option("--spring", args->springs, "Spring-damper (by name) whose force is recorded; repeat"));
  cmd->add_option("--newton-tol", args->newton_tol, "trapezoidal: Newton tolerance (default 1e-10)")
      ->check(positive_number());
  cmd->add_option("--newton-max-iter", args->newton_max_iter, "trapezoidal: Newton iteration limit (default 25)")
      ->check(positive_number());
  cmd->add_flag("--allow-unstable", args->allow_unstable,
                "rk3: warn instead of refusing a step above the stability limit");
  cmd->add_option("--jacobian", args->jacobian, "W-methods: exact (with friction tangents) or linear")
      ->check(CLI::IsMember({"exact", "linear"}));
  cmd->add_option("--jacobian-interval", args->jacobian_interval,
                  "W-methods: refresh the Jacobian every N steps (default 10)")
      ->check(positive_number());
  cmd->add_option("--blowup", args->blowup, "Stop when a displacement exceeds this length (default 1m)");
  cmd->add_option("--modes", args->modes,
                  "Integrate in a basis of the N lowest undamped modes (at 5 speeds of the run) instead of the "
                  "full model; lets rk3 take long steps (default: [runup] modes, else the full model)")
      ->check(positive_number());
  cmd->add_flag("--static-loads", args->static_loads,
                "Apply the model's [[static_loads]] as constant forces (default: [runup] static_loads)");
  cmd->add_flag("--gravity", args->gravity,
                "Apply the gravity of [static] as a constant force (default: [runup] gravity)");
  cmd->add_flag("--drive", args->drive,
                "Torque-driven: the speed follows the model's [drive] from the profile's first speed "
                "(default: [runup] drive)");
  cmd->add_option("--start", args->start,
                  "The state at t = 0: rest, equilibrium (static, at the first speed) or steady (with the "
                  "steady unbalance response) (default: [runup] start, else rest)");
  add_output_options(*cmd, args->out);

  return [args]() {
    CommandOutputs outputs(args->model, args->out, true);
    const ModelFile file = read_model(args->model);
    const Model& model = file.model;
    RunupRequest request;
    const auto time = [](const std::string& text, const char* option) -> std::optional<Real> {
      if (text.empty()) return std::nullopt;
      return parse_time_text(text, option);
    };
    request.speed = optional_speed(args->speed, "--speed");
    request.from = optional_speed(args->from, "--from");
    request.to = optional_speed(args->to, "--to");
    request.ramp_time = time(args->ramp_time, "--ramp-time");
    if (!args->table.empty()) request.table = parse_speed_table_text(args->table, "--table");
    request.duration = time(args->duration, "--duration");
    if (!args->integrator.empty()) request.integrator = args->integrator;
    request.dt = time(args->dt, "--dt");
    if (args->rtol > 0) request.rel_tol = args->rtol;
    if (args->atol > 0) request.abs_tol = args->atol;
    if (args->newton_tol > 0) request.newton_tol = args->newton_tol;
    if (args->newton_max_iter > 0) request.newton_max_iterations = args->newton_max_iter;
    request.allow_unstable_step = args->allow_unstable;
    request.exact_jacobian = args->jacobian == "exact";
    request.jacobian_interval = args->jacobian_interval;
    if (args->modes > 0) request.modes = args->modes;
    request.output_interval = time(args->output_interval, "--output-interval");
    if (!args->blowup.empty()) request.blowup_limit = parse_quantity(args->blowup, Quantity::length);
    request.static_loads = args->static_loads;
    request.gravity = args->gravity;
    if (!args->start.empty()) request.start = args->start;
    if (args->drive) request.drive = true;
    for (const std::string& p : args->probes) request.probes.push_back(find_node_reference(model, p, "--probe"));
    for (const std::string& name : args->springs) {
      try {
        request.springs.push_back(spring_element(model, name));
      } catch (const Error&) {
        throw Error(fmt::format("--spring '{}': no spring-damper has that name", name));
      }
    }
    TransientOptions options = runup_settings(model, file.spec.runup, request);
    options.stop = interrupt_token();
    options.assembled = file.assembler;  // the check's assembly of this model
    const auto [low, high] = speed_span(model, options);
    const ResultSource source{file.path, file.title, speed_range_warnings(model, low, high), args->out.speed_unit};

    std::optional<RunupCsvWriter> csv;
    if (outputs.files.wanted(outputs.csv)) csv.emplace(outputs.files, outputs.csv, model, options);
    const auto t0 = std::chrono::steady_clock::now();
    auto last_print = t0;
    bool printed = false;
    const bool show_progress = !args->out.quiet;
    const TransientResult result = run_transient(
        model, options,
        [&](const TransientSample& sample) {
          if (csv) csv->write(sample);
        },
        [&](Real t, Real dt) {
          if (!show_progress) return;
          const auto now = std::chrono::steady_clock::now();
          if (now - t0 < std::chrono::seconds(1) || now - last_print < std::chrono::milliseconds(500)) return;
          last_print = now;
          printed = true;
          if (options.driven)
            std::fprintf(stderr, "\r  %s: t = %.4g / %.4g s (%3.0f %%), step %.3g s   ", options.integrator.c_str(), t,
                         options.duration, 100 * t / options.duration, dt);
          else
            std::fprintf(stderr, "\r  %s: t = %.4g / %.4g s (%3.0f %%), speed %.4g Hz, step %.3g s   ",
                         options.integrator.c_str(), t, options.duration, 100 * t / options.duration,
                         rad_to_hz(options.profile.speed(t)), dt);
        });
    if (printed) std::fputs("\n", stderr);
    // Refused before the first step (e.g. rk3 above its stability limit): a bad
    // option, not a failed run; nothing is written.
    if (result.info.status == SolverStatus::numerical_failure && result.steps == 0) throw Error(result.info.message);
    const Real wall = std::chrono::duration<Real>(std::chrono::steady_clock::now() - t0).count();
    outputs.set_json([&] { return runup_json(result, options, model, source); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(runup_report(result, options, model, source, wall).c_str(), stdout);
    return finish(result.info);
  };
}

}  // namespace feran::app

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include <feran/core/parallel.hpp>
#include <feran/core/units.hpp>
#include <feran/io/study_log.hpp>
#include <feran/io/study_reader.hpp>
#include <feran/study/distributed.hpp>
#include <feran/study/sensitivity.hpp>

#include "commands.hpp"
#include "interrupt.hpp"
#include "mpi_group.hpp"

namespace feran::app {

namespace {

struct StudyArgs {
  std::string path;
  std::string output;
  bool resume = false;
  int threads = 0;
  int batch = 0;
  bool quiet = false;
};

// A value with six significant digits in @p unit (default the SI unit of @p kind).
std::string shown(Real si, const std::optional<Quantity>& kind, const std::string& unit) {
  if (!kind) return fmt::format("{:.6g}", si);
  const std::string u = unit.empty() ? std::string(si_unit(*kind)) : unit;
  const auto one = to_si(*kind, 1.0, u);
  return one ? fmt::format("{:.6g} {}", si / *one, u) : fmt::format("{:.6g} {}", si, si_unit(*kind));
}

std::string design_line(const StudySpec& study, const Evaluation& e) {
  std::string line = fmt::format("  design {}:", e.index);
  for (std::size_t i = 0; i < study.variables.size(); ++i)
    line += fmt::format(" {} = {}", study.variables[i].name,
                        shown(e.values[i], study.variables[i].quantity, study.variables[i].unit));
  line += "\n   ";
  for (std::size_t i = 0; i < study.quantities.size(); ++i) {
    const auto& q = study.quantities[i];
    line += fmt::format(" {} = {}", q.name, shown(e.quantities[i], quantity_unit(q), q.unit));
  }
  return line + "\n";
}

}  // namespace

Runner add_study_command(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "study",
      "Run a design study: designs from a grid, a Latin hypercube or a Sobol' sequence or an optimiser, "
      "evaluated on all cores, or on the processes of an MPI job (mpirun -np N feran study ...)");
  cmd->footer(
      "Example:\n  feran study examples/04_stiffness_schedule/schedule.study.toml -o out/schedule\n\n"
      "The study file (docs/study-format.md) names a base model, design variables (parameter paths\n"
      "with bounds), quantities, objectives and constraints. Every evaluation is appended to\n"
      "DIR/evaluations.jsonl and DIR/evaluations.csv as it completes; an interrupted study\n"
      "continues with --resume without repeating what was done.");
  cmd->add_option("study", args->path, "Study file (TOML)")->required();
  cmd->add_option("-o,--output", args->output,
                  "Directory of the results (default: the study file's name with .results)");
  cmd->add_flag("--resume", args->resume, "Continue the study recorded in the output directory");
  add_threads_option(*cmd, args->threads);
  cmd->add_option("--batch", args->batch,
                  "Designs evaluated between two writes to disk (default: 4 per thread of every process)")
      ->check(CLI::Range(1, 1'000'000));
  cmd->add_flag("-q,--quiet", args->quiet, "Do not print the summary on standard output");

  return [args]() {
    // Under MPI (mpirun -np N feran study ...) every process runs this: each reads the
    // study, evaluates its share of every batch and gets the whole batch back; the
    // first process alone keeps the record, prints and writes.
    const auto group = process_group();
    const bool first = group->rank() == 0;
    // An error every process meets (a bad study file) is reported once, by the first;
    // the others only end.
    const auto agreed = [&](bool ok, const std::string& message) {
      std::string why;
      if (all_agree(*group, ok, message, &why)) return true;
      if (first) throw Error(why);
      return false;
    };
    std::optional<StudyFile> file;
    std::string error;
    try {
      file = read_study_file(args->path);
    } catch (const Error& e) {
      error = e.what();
    }
    if (!agreed(file.has_value(), error)) return static_cast<int>(input_error);
    const StudySpec& study = file->study;
    std::string directory = args->output;
    if (directory.empty()) {
      std::filesystem::path p(args->path);
      directory = (p.parent_path() / (p.stem().string() + ".results")).string();
    }
    std::unique_ptr<StudyLog> log;
    if (first) {
      try {
        log = std::make_unique<StudyLog>(directory, study, args->resume,
                                         std::vector<std::string>{file->path, file->base.path});
      } catch (const Error& e) {
        error = e.what();
      }
    }
    if (!agreed(!first || log != nullptr, error)) return static_cast<int>(input_error);
    const auto done = unpack_evaluations(group->broadcast(first ? pack_evaluations(log->done()) : std::string(), 0));
    const int threads = threads_per_process(args->threads);
    // The first process's batch: the same on all, so that all leave at the same one.
    const Index batch =
        std::stoll(group->broadcast(std::to_string(args->batch > 0 ? args->batch : 4 * threads * group->size()), 0));
    ThreadEvaluator local(threads, interrupt_token());
    DistributedEvaluator evaluator(*group, local, interrupt_token());
    std::vector<Evaluation> all;
    try {
      all = run_exploration(
          study, evaluator, done,
          [&](std::span<const Evaluation> e) {
            if (log) log->append(e);
          },
          batch, evaluator.stop_token());
    } catch (const Error& e) {
      // The others may be waiting for this process: the whole job ends.
      if (group->size() > 1) {
        std::fprintf(stderr, "feran: error: %s%s\n", first ? "" : fmt::format("process {}: ", group->rank()).c_str(),
                     e.what());
        group->abort(input_error);
      }
      throw;
    }
    // A stop asked of another process ends this one as if by SIGTERM.
    const int signal = evaluator.stopped() ? (interrupt_signal() != 0 ? interrupt_signal() : SIGTERM) : 0;
    if (!first) return static_cast<int>(signal != 0 ? interrupted_base + signal : ok);
    const bool optimiser =
        study.explore.method == ExploreMethod::optimise || study.explore.method == ExploreMethod::pareto;
    const Index total = planned_evaluations(study);
    const bool complete = !evaluator.stopped() && (optimiser || static_cast<Index>(all.size()) == total);
    const auto models = log->finish(all, complete);

    if (!args->quiet) {
      Index evaluated = 0, feasible = 0;
      for (const auto& e : all) {
        evaluated += e.evaluated;
        feasible += e.feasible;
      }
      std::string out =
          fmt::format("feran study: {} ({})\n", study.title.empty() ? args->path : study.title, study.model_path);
      if (group->size() > 1)
        out += fmt::format("{} processes, {} thread{} each\n", group->size(), threads, threads == 1 ? "" : "s");
      out += optimiser ? fmt::format("{} designs evaluated ({} resumed)", all.size(), done.size())
                       : fmt::format("{} of {} designs evaluated ({} resumed)", all.size(), total, done.size());
      out += fmt::format(", {} failed, {} feasible\n", static_cast<Index>(all.size()) - evaluated, feasible);
      // A quantity that is only a bound where an analysis' range ended says so.
      for (std::size_t i = 0; i < study.quantities.size(); ++i) {
        Index count = 0;
        const Evaluation* example = nullptr;
        for (const auto& e : all)
          if (i < e.clipped.size() && !e.clipped[i].empty() && ++count == 1) example = &e;
        if (count > 0)
          out +=
              fmt::format("note: '{}' is clipped by the analysed range in {} design{} (design {}: {})\n",
                          study.quantities[i].name, count, count == 1 ? "" : "s", example->index, example->clipped[i]);
      }
      if (study.objectives.size() == 1) {
        if (const auto best = best_design(study, all))
          out += "best:\n" + design_line(study, all[static_cast<std::size_t>(*best)]);
        else
          out += "no feasible design\n";
      } else if (study.objectives.size() > 1) {
        const auto front = pareto_set(study, all);
        const auto shown_ones = spread_along_front(study, all, front, 10);
        out += fmt::format(
            "Pareto set: {} designs{}\n", front.size(),
            shown_ones.size() < front.size() ? fmt::format(", {} of them along the front", shown_ones.size()) : "");
        for (const Index i : shown_ones) out += design_line(study, all[static_cast<std::size_t>(i)]);
      }
      if (!optimiser) {
        const auto table = sensitivities(study, all);
        if (!table.empty() && !table.front().src.empty()) {
          out +=
              "sensitivity: standardised regression coefficients on the variables' unit coordinates (R² of the fit)\n";
          for (const auto& x : table) {
            out += fmt::format("  {:<20}", x.quantity);
            for (std::size_t j = 0; j < study.variables.size(); ++j)
              out += fmt::format(" {} {:+.3f}", study.variables[j].name, x.src[j]);
            out += fmt::format("  (R² {:.3f}; on ranks {:.3f})\n", x.r2, x.r2_ranks);
          }
        }
      }
      out += fmt::format("results in {}/ (evaluations.csv, evaluations.jsonl, summary.json", directory);
      if (models.size() > 3)
        out += fmt::format(", {} model files pareto-*.toml", models.size());
      else
        for (const auto& m : models) out += ", " + std::filesystem::path(m).filename().string();
      out += ")\n";
      std::fputs(out.c_str(), stdout);
    }
    if (signal != 0) {
      std::fprintf(stderr, "feran study: stopped by %s after %zu designs; --resume continues it\n",
                   interrupt_signal() != 0 ? signal_name(signal) : "a signal to another process", all.size());
      return static_cast<int>(interrupted_base) + signal;
    }
    return static_cast<int>(ok);
  };
}

}  // namespace feran::app

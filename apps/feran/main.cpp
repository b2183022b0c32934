// feran: finite-element rotor dynamics from the command line.
#include <cstdio>
#include <algorithm>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <malloc.h>

#include <CLI/CLI.hpp>

#include <fmt/format.h>

#include <feran/core/error.hpp>
#include <feran/core/parallel.hpp>
#include <feran/core/suggestions.hpp>
#include <feran/core/text.hpp>

#include <feran/analyses/list.hpp>

#include "analysis_command.hpp"
#include "commands.hpp"
#include "interrupt.hpp"

#ifdef FERAN_OPENBLAS_LINKED
// OpenBLAS linked into the program (apps/feran/CMakeLists.txt). Weak: a serial
// OpenBLAS build has no thread server, nor these functions.
extern "C" {
void openblas_set_num_threads(int n) __attribute__((weak));
int blas_thread_shutdown_() __attribute__((weak));
}
#endif

namespace {
// feran runs the points of a sweep on all cores itself; a threaded OpenBLAS (when it
// is the LAPACK in use) would start threads of its own inside each small dense solve,
// which only competes with them. Its worker threads are started when the library
// loads, before main, and spin (sched_yield) for about 0.1 s before they sleep: a
// short run lost one of two cores to them. Setting one thread and shutting the
// server down joins them at once. Called directly when OpenBLAS is linked into the
// program, otherwise looked up at run time (other BLAS builds lack these functions).
void single_threaded_blas() {
#ifdef FERAN_OPENBLAS_LINKED
  if (openblas_set_num_threads != nullptr) openblas_set_num_threads(1);
  if (blas_thread_shutdown_ != nullptr) blas_thread_shutdown_();
#else
  feran::single_threaded_blas();
#endif
}

// glibc returns freed memory at the top of a heap to the system once more than
// 128 KiB are free there, and the next growth faults the pages in again; a sweep
// that allocates and frees its per-speed matrices did this at nearly every speed, in
// every thread (a fifth of a 100-speed Campbell diagram of a small rotor). Keeping
// up to 256 MiB for reuse and growing in 32 MiB steps of address space (pages are
// only resident once touched) avoids it. Fixing the trim threshold also fixes the
// size above which blocks are mapped apart (and unmapped when freed): 32 MiB, the
// largest allowed, so that a large model's per-speed sparse matrices stay in the heap.
void keep_freed_memory() {
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_TOP_PAD, 32 << 20);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
}
}  // namespace

// A function-try-block: what the handlers below cannot catch (the options' set-up
// running out of memory) still ends in a message and exit code 4, not in terminate.
int main(int argc, char** argv) try {
  single_threaded_blas();
  keep_freed_memory();
  CLI::App app{
      "feran: finite-element rotor dynamics.\n"
      "Reads a rotor model (TOML, docs/model-format.md) and computes natural frequencies,\n"
      "Campbell diagrams, critical speeds, stability thresholds, steady-state unbalance\n"
      "response and static deflection, with bearing forces and shaft stresses.",
      "feran"};
  app.footer(
      "Examples:\n"
      "  feran modal examples/01_internal_damping/model.toml --speed 30Hz\n"
      "  feran campbell examples/01_internal_damping/model.toml --stop 80Hz --points 161 --json c.json\n"
      "  feran response examples/01_internal_damping/model.toml --stop 80Hz --probe rotor\n"
      "  feran static examples/01_internal_damping/model.toml --gravity -y\n"
      "  feran params examples/02_centrifuge/model.toml\n"
      "  feran api684 examples/05_api684_bearings/model.toml --min-speed 9000rpm --max-speed 11000rpm\n"
      "  feran report examples/01_internal_damping/model.toml -o report.html\n"
      "  feran modal examples/02_centrifuge/model.toml --set 'springs[bearing k12].ky=2e7 N/m'\n\n"
      "Run 'feran <command> --help' for a command's options.");
  app.set_version_flag("--version", "feran " FERAN_VERSION);
  app.require_subcommand(1);

  // The commands, each registered only when it may run: a command line naming one
  // registers that one (building every command's options took about a millisecond
  // of each run, a fifth of a small model's whole analysis), '--version' none, and
  // anything else (help, a mistyped command) all of them, for the help and the error.
  using Adder = feran::app::Runner (*)(CLI::App&, int, char**);
  static constexpr std::pair<const char*, Adder> commands[] = {
      {"params", [](CLI::App& a, int, char**) { return feran::app::add_params_command(a); }},
      {"study", [](CLI::App& a, int, char**) { return feran::app::add_study_command(a); }},
      {"report", [](CLI::App& a, int argc_, char** argv_) { return feran::app::add_report_command(a, argc_, argv_); }},
  };
  std::vector<std::string> names;
  for (const auto& [name, add] : commands) names.emplace_back(name);
  feran::Analyses::for_each([&]<class A>() { names.emplace_back(A::name); });
  const std::string first = argc > 1 ? argv[1] : "";
  const bool named = std::find(names.begin(), names.end(), first) != names.end();
  const bool version_only = argc == 2 && first == "--version";
  std::map<std::string, feran::app::Runner> runners;
  for (const auto& [name, add] : commands)
    if (!version_only && (!named || first == name)) runners[name] = add(app, argc, argv);
  // The analyses of analyses/list.hpp, each a command made from its face.
  feran::Analyses::for_each([&]<class A>() {
    if (!version_only && (!named || first == A::name))
      runners[std::string(A::name)] = feran::app::add_analysis_command<A>(app);
  });
  // An option given an empty value ('--json ""', '--speed ""') is an error, not the
  // option left out.
  const CLI::Validator non_empty(
      [](std::string& text) {
        return text.empty() ? std::string("needs a value, got an empty string") : std::string();
      },
      "");
  for (CLI::App* sub : app.get_subcommands({}))
    for (CLI::Option* option : sub->get_options())
      if (option->get_type_size() > 0 && option->get_expected_min() > 0) option->check(non_empty);

  // A first argument that is neither an option nor a command is a mistyped command
  // (CLI11 would only say that a command is required).
  if (argc > 1 && argv[1][0] != '-' && !named) {
    std::sort(names.begin(), names.end());
    std::string message = fmt::format("unknown command '{}'", feran::printable(argv[1]));
    if (const auto match = feran::detail::closest_match(argv[1], names, 2))
      message += fmt::format("; did you mean '{}'?", *match);
    std::fprintf(stderr, "feran: error: %s (the commands are %s)\n", message.c_str(),
                 feran::detail::join_list(names, "and", '\'').c_str());
    return static_cast<int>(CLI::ExitCodes::ExtrasError);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  feran::app::install_interrupt_handlers();
  try {
    for (const CLI::App* sub : app.get_subcommands()) return runners.at(sub->get_name())();
  } catch (const feran::Error& e) {
    std::fprintf(stderr, "feran: error: %s\n", feran::printable(e.what(), true).c_str());
    return feran::app::input_error;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "feran: internal error: %s\n", feran::printable(e.what(), true).c_str());
    return 4;
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "feran: internal error: %s\n", e.what());
  return 4;
}

#pragma once
// The sub-commands of the feran program. Each registers its options on the CLI11
// app and returns the function that runs it.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include <feran/analyses/common/solver_info.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/output_files.hpp>

namespace feran::app {

/// Exit codes shared by the sub-commands.
enum ExitCode : int {
  ok = 0,
  input_error = 1,        ///< bad model file or option
  numerical_failure = 3,  ///< a solve failed; results so far were written
  /// Stopped by signal N (SIGINT, SIGTERM, SIGHUP): exit code 128 + N, the shell's
  /// convention; sweeps and run-ups wrote their results so far.
  interrupted_base = 128
};

using Runner = std::function<int()>;

Runner add_params_command(CLI::App& app);
Runner add_study_command(CLI::App& app);
/// @p argc, @p argv: the command line, which the report lists among its inputs.
Runner add_report_command(CLI::App& app, int argc, char** argv);

/// The model an analysis reads: its file and the parameters set on the command line.
struct ModelArgs {
  std::string path;
  std::vector<std::string> assignments;  ///< --set PATH=VALUE, in order
};
/// Adds the model file argument and --set to a sub-command.
void add_model_argument(CLI::App& cmd, ModelArgs& model);
/// Reads the model file and applies the --set assignments.
ModelFile read_model(const ModelArgs& model);

/// The warnings of an analysis over speeds [low, high] (rad/s) of @p model
/// (range_warnings()), each printed once to standard error; for ResultSource.
/// @p frequencies: the frequencies of the motion [rad/s] (empty: synchronous).
std::vector<std::string> speed_range_warnings(const Model& model, double low, double high,
                                              std::optional<std::pair<double, double>> frequencies = std::nullopt);
/// The span [rad/s] of the given frequencies [Hz] (empty when there are none), for
/// speed_range_warnings().
std::optional<std::pair<double, double>> frequency_span_hz(const std::vector<double>& frequencies_hz);

/// Options every analysis shares.
struct OutputOptions {
  std::string json_path;
  std::string csv_path;
  bool quiet = false;
  std::string speed_unit = "Hz";  ///< speeds in the terminal tables
};
void add_output_options(CLI::App& cmd, OutputOptions& out);

/// A speed option that may be left out (parse_speed_text(), io/option_text.hpp):
/// std::nullopt for empty @p text.
std::optional<double> optional_speed(const std::string& text, const std::string& option);

/// The --json and --csv files of a command. Made before the model is read, so that
/// every path is checked (OutputFiles::add) before anything runs; nothing is written
/// until commit(), and nothing at all when the command fails before it.
struct CommandOutputs {
  /// With @p stream_csv the CSV is streamed (OutputFiles::append) as the run goes.
  CommandOutputs(const ModelArgs& model, const OutputOptions& out, bool stream_csv = false);
  OutputFiles files;
  int json = -1;
  int csv = -1;
  /// The JSON or CSV text, built only when that file was asked for (a large sweep
  /// makes a large text).
  void set_json(const std::function<std::string()>& make_text);
  void set_csv(const std::function<std::string()>& make_text);
};

/// The exit code of an analysis that ended with @p info, its results written: ok;
/// numerical_failure; for a run stopped by a signal, 128 + the signal's number. The
/// reason is printed on standard error.
int finish(const SolverInfo& info);
/// For an analysis of one solve (modal, static), which has no partial results: when a
/// signal asked to stop while it ran, says so (nothing is written) and gives the
/// exit code, 128 + the signal's number.
std::optional<int> stopped_single_solve();

/// Adds --threads (speed sweeps: 0 = all cores) to a sub-command.
void add_threads_option(CLI::App& cmd, int& threads);

/// Makes @p option repeatable with one value per occurrence ('--probe a --probe b'),
/// so that it never takes the positional model path after it.
CLI::Option* repeatable(CLI::Option* option);

/// Option checks with plain messages ("must be positive, got -1"): CLI11's own
/// PositiveNumber and NonNegativeNumber print their range with the 309 digits of the
/// largest double, and let nan through.
CLI::Validator positive_number();
CLI::Validator non_negative_number();

}  // namespace feran::app

#pragma once
// The sub-commands of the feran program. Each registers its options on the CLI11
// app and returns the function that runs it.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <feran/io/model_reader.hpp>

namespace feran::app {

/// Exit codes shared by the sub-commands.
enum ExitCode : int {
  ok = 0,
  input_error = 1,      ///< bad model file or option
  numerical_failure = 3 ///< a solve failed; results so far were written
};

using Runner = std::function<int()>;

Runner add_modal_command(CLI::App& app);
Runner add_campbell_command(CLI::App& app);
Runner add_response_command(CLI::App& app);
Runner add_static_command(CLI::App& app);
Runner add_runup_command(CLI::App& app);
Runner add_params_command(CLI::App& app);

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
std::vector<std::string> speed_range_warnings(const Model& model, double low, double high);

/// Options every analysis shares.
struct OutputOptions {
  std::string json_path;
  std::string csv_path;
  bool quiet = false;
};
void add_output_options(CLI::App& cmd, OutputOptions& out);

/// Parses a speed with its unit ("30Hz", "1800 rpm", "188.5rad/s") into rad/s;
/// throws feran::Error naming @p option when it is not one.
double parse_speed_option(const std::string& text, const std::string& option);
/// The same for an option that may be left out: std::nullopt for empty @p text.
std::optional<double> optional_speed(const std::string& text, const std::string& option);

/// Writes @p text to @p path (atomically) when the path is not empty.
void write_if_asked(const std::string& path, const std::string& text);
/// Same, building the text only when it is written (large sweeps make large files).
void write_if_asked(const std::string& path, const std::function<std::string()>& make_text);

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

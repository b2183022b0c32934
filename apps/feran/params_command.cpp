#include <cstdio>
#include <memory>

#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/spec/parameters.hpp>

#include "commands.hpp"

namespace feran::app {

namespace {
struct ParamsArgs {
  ModelArgs model;
  OutputOptions out;
};
}  // namespace

Runner add_params_command(CLI::App& app) {
  auto args = std::make_shared<ParamsArgs>();
  CLI::App* cmd =
      app.add_subcommand("params", "List every number of a model that --set can change, with its value and unit");
  cmd->footer(
      "Example:\n  feran params examples/02_centrifuge/model.toml\n"
      "  feran campbell examples/02_centrifuge/model.toml --set 'springs[bearing k12].ky=2e7 N/m'\n\n"
      "Paths name a table, an entry (by index from 0, by name, or by its node's name) and a\n"
      "key: materials[steel].E, shafts[0].sections[2].outer_diameter, springs[mount].ky.f_as.");
  add_model_argument(*cmd, args->model);
  cmd->add_option("--json", args->out.json_path, "Write the list as JSON to this file (docs/output-format.md)");
  cmd->add_flag("-q,--quiet", args->out.quiet, "Do not print the table on standard output");

  return [args]() {
    CommandOutputs outputs(args->model, args->out);
    const ModelFile file = read_model(args->model);
    const std::vector<Parameter> parameters = list_parameters(file.spec);
    const ResultSource source{file.path, file.title};
    outputs.set_json([&] { return parameters_json(parameters, source); });
    outputs.files.commit();
    if (!args->out.quiet) std::fputs(parameters_report(parameters, source).c_str(), stdout);
    return static_cast<int>(ok);
  };
}

}  // namespace feran::app

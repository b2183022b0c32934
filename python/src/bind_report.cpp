// The interactive HTML report (docs/report.md), as feran report writes it.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include <feran/core/error.hpp>
#include <feran/io/html_report.hpp>
#include <feran/io/output_files.hpp>
#include <feran/io/report_config.hpp>

#include "bindings.hpp"

namespace feran::python {

void bind_report(py::module_& m) {
  m.attr("__version__") = FERAN_VERSION;
  m.def(
      "report",
      [](const PyModel& model, std::optional<std::string> path, std::optional<std::string> config,
         std::optional<std::string> study, std::optional<std::string> speed_unit, std::optional<std::string> title,
         int threads) {
        const ModelFile& file = model.built();
        ReportOptions options;
        options.version = FERAN_VERSION;
        options.command = "feran.report(" + (file.path.empty() ? std::string("model") : "'" + file.path + "'") +
                          (config ? ", config='" + *config + "'" : "") + (study ? ", study='" + *study + "'" : "") +
                          ")";
        options.n_threads = threads;
        // The path is checked before the analyses run: never an input of the report.
        OutputFiles files(file.path);
        const int id = path ? files.add("path", *path) : -1;
        if (config) files.add_input(*config, "the report configuration");
        if (config) read_report_config_file(*config, file.model, options);
        if (study) options.study_directory = *study;
        for (const std::string& input : report_study_files(options))
          files.add_input(input, "a file of the study shown");
        if (speed_unit) options.speed_unit = *speed_unit;
        if (title) options.title = *title;
        std::atomic<bool> flag{false};
        options.stop = StopToken(flag);
        std::string html;
        bool interrupted = false;
        run_watched([&] { html = html_report(file, options); }, flag, interrupted);
        if (interrupted) {  // a report cut short is not written
          PyErr_SetNone(PyExc_KeyboardInterrupt);
          throw py::error_already_set();
        }
        if (path) {
          files.write(id, html);
          files.commit();
        }
        return html;
      },
      py::arg("model"), py::arg("path") = py::none(), py::kw_only(), py::arg("config") = py::none(),
      py::arg("study") = py::none(), py::arg("speed_unit") = py::none(), py::arg("title") = py::none(),
      py::arg("threads") = 0,
      "The interactive HTML report of feran report (docs/report.md): one self-contained file,\n"
      "written to path when given; returns its text. config: a REPORT.toml; study: a design\n"
      "study's output directory; speed_unit 'rpm' or 'Hz'.");
}

}  // namespace feran::python

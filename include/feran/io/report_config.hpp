#pragma once
/// @file
/// The report's configuration file (REPORT.toml, docs/report.md): what the report
/// shows and the settings of its analyses, read with located errors.

#include <string>
#include <string_view>

#include <feran/io/html_report.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Reads the configuration text @p toml_text (named @p path in messages; relative
/// paths in it, such as a study directory, are taken from its folder) into @p options
/// for @p model (node names of probes are looked up there). Throws ModelError at the
/// file, line and column of a mistake.
void read_report_config(std::string_view toml_text, const std::string& path, const Model& model,
                        ReportOptions& options);
/// The same from the file @p path.
void read_report_config_file(const std::string& path, const Model& model, ReportOptions& options);

}  // namespace feran

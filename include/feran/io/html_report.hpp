#pragma once
/// @file
/// The interactive report: one self-contained HTML file (plotly.js and the report's
/// own script inlined, no network access when opened) with the model drawn to scale,
/// the Campbell diagram, damping against speed, mode shapes, unbalance responses with
/// the API 684 reading, the critical speed map, level I stability, run-ups, a study's
/// results and a table of every number with its unit and the inputs that made it
/// (docs/report.md).

#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/settings.hpp>
#include <feran/core/stop.hpp>
#include <feran/io/model_reader.hpp>

namespace feran {

/// What a report shows, and the settings of the analyses it runs; each unset value
/// comes from the model's own tables and then from the defaults (docs/report.md).
struct ReportOptions {
  std::string title;               ///< empty: the model's title, else its file name
  std::string speed_unit = "rpm";  ///< "rpm" or "Hz": how speeds are shown
  std::string command;             ///< the command that made the report (its inputs table)
  std::string version;             ///< feran's version (its inputs table)
  CampbellSpec campbell;           ///< stop default: [campbell], else 1.5 × the maximum operating speed
  /// Speeds of the mode shapes [rad/s]; empty: 0 (for a rotor on oil films, which
  /// carry it only while it turns: the minimum operating speed, else the Campbell
  /// diagram's first speed above 0) and the maximum operating speed (or the Campbell
  /// diagram's last speed).
  std::vector<Real> mode_speeds;
  int mode_count = 6;                    ///< lateral modes drawn at each speed
  ResponseSpec response;                 ///< the unbalance response (when the model has unbalances or forces)
  std::optional<Real> deflection_speed;  ///< [rad/s]; default: the largest response peak's speed
  bool static_analysis = true;           ///< the static deflection under [static] gravity
  bool runup = true;                     ///< the run-up of [runup], when the model has one
  bool orbits = true;                    ///< the periodic orbits of [orbits], when the model has one
  OrbitsSpec orbits_request;             ///< over the model's [orbits]
  bool api684 = true;                    ///< the API 617 / 684 analyses, when an operating range is known
  Api684Spec api684_request;             ///< over the model's [api684]
  std::string study_directory;           ///< a design study's output directory (evaluations.jsonl, summary.json)
  int n_threads = 0;
  StopToken stop;
};

/// Runs the analyses of @p options on @p file and returns the report's HTML text.
/// Throws Error for options that are wrong (an unknown unit, a study directory without
/// results, a Campbell diagram without a last speed); a solve that fails is reported in
/// its section, with the results so far. Throws Error when feran was built without
/// plotly.js (report_available() is false). @p summary, when given, receives the
/// verdicts the report opens with as terminal lines (docs/report.md, "Verdicts").
std::string html_report(const ModelFile& file, const ReportOptions& options, std::string* summary = nullptr);

/// The files of options.study_directory the report reads (none without one): a front
/// end keeps its outputs from replacing them (OutputFiles::add_input).
std::vector<std::string> report_study_files(const ReportOptions& options);

/// True when the report's scripts were built in (the front-end packages were installed
/// by scripts/setup.sh when feran was built).
bool report_available();

}  // namespace feran

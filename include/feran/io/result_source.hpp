#pragma once
/// @file
/// Where a result came from, as every result file and report states it.

#include <string>
#include <vector>

namespace feran {

/// What a result file says about where it came from.
struct ResultSource {
  std::string model_path;
  std::string title;
  /// What the analysis should be read with (e.g. a table evaluated beyond its range);
  /// written as the header's "warnings".
  std::vector<std::string> warnings = {};
  /// The unit of speeds in the terminal reports' tables: "Hz" or "rpm" (the files
  /// always hold their documented units).
  std::string speed_unit = "Hz";
};

}  // namespace feran

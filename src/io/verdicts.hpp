#pragma once
// The report's opening verdicts (docs/report.md, "Verdicts"): one per check an
// engineer makes before signing — stability in the operating range, separation
// margins, amplification factors, bearing loads and minimum film thickness — each
// with its number and its reason, read off the report's data (the JSON documents of
// the analyses it ran), so that they say nothing the sections below do not show.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace feran::detail {

struct Verdict {
  std::string check;     ///< what is checked
  std::string status;    ///< "pass", "FAIL" or "not checked"
  nlohmann::json value;  ///< the deciding number, or null
  std::string unit;      ///< of value
  std::string reason;    ///< one sentence: the number's meaning and the criterion
};

/// The verdicts of the report data @p data (html_report()'s "campbell", "response",
/// "static", "api684" and "operating"), speeds named in @p speed_unit ("rpm" or "Hz").
std::vector<Verdict> report_verdicts(const nlohmann::json& data, const std::string& speed_unit);

nlohmann::json verdicts_json(const std::vector<Verdict>& verdicts);

/// The verdicts as terminal lines.
std::string verdicts_text(const std::vector<Verdict>& verdicts);

}  // namespace feran::detail

#pragma once
// What every analysis's writers share: the JSON header, solver and stability records,
// node and station keys; the terminal reports' speeds, cells, names and the table of
// the supports' operating state. Defined in result_text.cpp.

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <feran/analyses/common/shaft_sections.hpp>
#include <feran/analyses/common/solver_info.hpp>
#include <feran/analyses/modal/stability.hpp>
#include <feran/core/types.hpp>
#include <feran/io/result_source.hpp>
#include <feran/model/model.hpp>

#include "csv_text.hpp"
#include "json_text.hpp"
#include "operating_text.hpp"

namespace feran::detail {

// ---- JSON -----------------------------------------------------------------------

/// An array of numbers, null where not finite.
nlohmann::json numbers(const std::vector<Real>& xs);
/// How a solve went (method, converged, status, …).
nlohmann::json solver_json(const SolverInfo& info);
/// The keys every result file starts with: program, format_version, analysis, model,
/// warnings.
nlohmann::json header(const std::string& analysis, const ResultSource& source);
/// A node's number, name and axial position.
nlohmann::json node_json(const Model& model, Index node);
/// A shaft station: its node, element and end.
nlohmann::json station_json(const Model& model, const ShaftStation& st);
/// One point's stability (the static equilibrium's).
nlohmann::json stability_point_json(const StabilityPoint& p);
/// The rotor's stability at each point of a steady-state result (modal/stability.hpp):
/// per point whether it is unstable (null: unknown), the largest growth rate where
/// eigenvalues were computed, and the first unstable speed; null when not judged.
nlohmann::json point_stability_json(const std::vector<StabilityPoint>& points);

/// Masks of a node's DOFs: all six, the lateral pair (v, w).
inline constexpr std::array<bool, dofs_per_node> all_dofs{true, true, true, true, true, true};
inline constexpr std::array<bool, dofs_per_node> lateral_dofs{false, true, true, false, false, false};

/// An element's label, also for the elements of linearised(model) that stand for its
/// journal and rolling bearings (numbered after its own).
std::string element_label(const Model& model, Index element);

// ---- terminal reports -------------------------------------------------------------

/// "feran static: TITLE (PATH)".
std::string source_line(const char* analysis, const ResultSource& source);
/// A speed in the unit the user chose ("Hz" or "rpm"), the other in parentheses.
std::string speed_text(Real speed, const std::string& unit = "Hz");
/// A speed column: its header and the value in the chosen unit.
std::string speed_header(const std::string& unit);
Real speed_value(Real speed, const std::string& unit);
/// A speed alone, in the chosen unit ("105.3 Hz", "6318 rpm").
std::string speed_short(Real speed, const std::string& unit);
/// The same without the unit (under a speed_header()).
std::string speed_number(Real speed, const std::string& unit);
/// Frequencies of the motion follow the speed unit, as in the report: Hz with Hz,
/// cycles per minute with rpm (a synchronous mode's frequency then reads as its speed).
std::string frequency_unit(const std::string& unit);
Real frequency_value(Real hz, const std::string& unit);
std::string frequency_text(Real hz, const std::string& unit);
/// A right-aligned number; "-" when it does not exist. Values that would print as
/// "-0.000" print as "0.000".
std::string cell(Real x, const char* format_spec, int width, int decimals);
/// Names as the model gives them, made printable (core/text.hpp).
std::string node_name(const Model& model, Index node);
/// Also for the elements of linearised(model) that stand for its bearings.
std::string element_name(const Model& model, Index element);
std::string force_name(const Model& model, Index force);

/// One row of operating_block(): a label and the support's named values.
struct OperatingRow {
  std::string label;
  const std::vector<std::string>* names;
  const std::vector<Real>* values;
};
/// A table of the supports' operating state (Force::operating_data()) with units in the
/// headers: a journal bearing's eccentricity ratio, attitude angle, minimum film
/// thickness and where it is, Sommerfeld number, friction torque and power loss, peak
/// film pressure; a rolling bearing's most loaded element. One row per (label, names,
/// values); only the columns some row has.
std::string operating_block(const std::string& title, const std::string& first, const std::vector<OperatingRow>& rows);

/// The supports' state at an analysis' one speed (its first point): one row per support.
std::string operating_at_one_speed(const std::vector<OperatingSeries>& series, const Model& model);

// The supports' state over the points of an analysis: per support, rows at (at most)
// 11 evenly spread points, as the analyses' other tables; @p label names point k.
template <class Label>
std::string operating_tables(const std::vector<OperatingSeries>& series, const Model& model, const std::string& what,
                             const std::string& first, Label label) {
  std::string out;
  for (const OperatingSeries& s : series) {
    const std::size_t n = s.values.size();
    if (n == 0 || s.quantities.empty()) continue;
    const std::size_t count = std::min<std::size_t>(n, 11);
    std::vector<OperatingRow> rows;
    for (std::size_t r = 0; r < count; ++r) {
      const std::size_t k = count == 1 ? 0 : r * (n - 1) / (count - 1);
      rows.push_back({label(k), &s.quantities, &s.values[k]});
    }
    out += operating_block(fmt::format("Operating data of {} {}", force_name(model, s.force), what), first, rows);
  }
  return out;
}

}  // namespace feran::detail

#pragma once
/// @file
/// The API 617 / API 684 analyses' face (analyses/analysis.hpp): their options
/// ([api684]), their result and their writers, as every door uses them.

#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

struct Api684Analysis {
  static constexpr std::string_view name = "api684";
  static constexpr std::string_view summary =
      "API 617 / API 684 lateral analyses: unbalance responses with amplification factors and separation margins, "
      "the undamped critical speed map, level I stability";
  static constexpr std::string_view example =
      "feran api684 examples/05_api684_bearings/model.toml --min-speed 9000rpm --max-speed 11000rpm "
      "--anticipated-q 2e6";
  static constexpr std::string_view footer =
      "Unset options come from the model's [api684] table (docs/model-format.md); the\n"
      "journal loads of 4W/N use the gravity of its [static] table (default -y).\n"
      "The formulas and their sources: docs/theory/api684.md.";
  using Spec = Api684Spec;
  using Options = Api684Options;
  using Result = Api684Result;
  static constexpr bool keeps_partial_results = true;  // the cases solved before a failure or a stop
  static constexpr bool parallel = true;
  static constexpr std::string_view speed_unit = "rpm";  // the standards' own unit, on the terminal

  /// 401 speeds to 2 × the maximum continuous speed, two modes excited by 4W/N, the
  /// map of 41 stiffnesses and 4 critical speeds, the level I stability analysis.
  static const Api684Spec& defaults();
  static const Api684Spec& file_table(const ModelSpec& spec) { return spec.api684; }
  /// The options, with the journal loads' gravity from @p spec's [static] table.
  /// Throws Error without an operating range, with a maximum below the minimum, for
  /// too much work asked for, or an unknown node or bearing.
  static Api684Options settings(const Model& model, const ModelSpec& spec, const Api684Spec& asked,
                                const Api684Spec& resolved, const OptionName& named);
  static Api684Result run(const Model& model, const Api684Options& options, const RunContext& context);
  /// Tables evaluated beyond their range over the unbalance responses' speeds.
  static std::vector<std::string> warnings(const Model& model, const Api684Options& options,
                                           const Api684Result& result);
  /// The documented JSON (docs/output-format.md), the CSV (one row per resonance peak
  /// of every case and probe: its speed, amplitude, amplification factor and margins)
  /// and the terminal report (verdicts, journal loads, the cases' peaks, the map's
  /// intersections, level I stability).
  static std::string json(const Outcome<Api684Analysis>& o);
  static std::string csv(const Outcome<Api684Analysis>& o);
  static std::string terminal(const Outcome<Api684Analysis>& o);
  /// Its study quantities: undamped_critical_speed and level1_q_zero.
  static const std::vector<QuantityRow>& quantities();
};

}  // namespace feran

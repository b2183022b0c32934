#pragma once
/// @file
/// The Campbell diagram's face (analyses/analysis.hpp): its options ([campbell]), its
/// result and its writers, as every door uses them.

#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

struct CampbellAnalysis {
  static constexpr std::string_view name = "campbell";
  static constexpr std::string_view summary =
      "Campbell diagram: tracked modes over a speed range, critical speeds, stability threshold";
  static constexpr std::string_view example =
      "feran campbell examples/01_internal_damping/model.toml --start 0Hz --stop 80Hz --points 161 --orders 1";
  static constexpr std::string_view footer =
      "Unset options take their values from the model file's [campbell] table, else\n"
      "start 0, 101 points, 8 modes, order 1; --stop is required if the file has none.";
  /// The speeds solved before a failure or a stop are kept.
  static constexpr bool keeps_partial_results = true;
  /// Its speeds are solved side by side (RunContext::threads).
  static constexpr bool parallel = true;
  using Spec = CampbellSpec;
  using Options = CampbellOptions;
  using Result = CampbellResult;

  /// Start 0, 101 points, 8 modes, order 1, the automatic solver; no last speed.
  static const CampbellSpec& defaults();
  static const CampbellSpec& file_table(const ModelSpec& spec) { return spec.campbell; }
  /// Throws Error without a last speed or with one not above the first.
  static CampbellOptions settings(const Model& model, const CampbellSpec& asked, const CampbellSpec& resolved,
                                  const OptionName& named);
  static CampbellResult run(const Model& model, const CampbellOptions& options, const RunContext& context);
  /// Tables evaluated beyond their range over the speeds and the modes' frequencies.
  static std::vector<std::string> warnings(const Model& model, const CampbellOptions& options,
                                           const CampbellResult& result);
  /// The documented JSON (with the supports' operating state over the speeds), the CSV
  /// (one row per speed) and the terminal report.
  static std::string json(const Outcome<CampbellAnalysis>& o);
  static std::string csv(const Outcome<CampbellAnalysis>& o);
  static std::string terminal(const Outcome<CampbellAnalysis>& o);
  /// Its study quantities: critical_speed, separation_margin, min_damping_ratio,
  /// min_log_decrement, stability_threshold, min_bearing_value, max_bearing_value.
  static const std::vector<QuantityRow>& quantities();
};

}  // namespace feran

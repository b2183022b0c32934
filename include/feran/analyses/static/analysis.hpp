#pragma once
/// @file
/// The static analysis's face (analyses/analysis.hpp): its options ([static]), its
/// result and its writers, as every door uses them.

#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

struct StaticAnalysis {
  static constexpr std::string_view name = "static";
  static constexpr std::string_view summary =
      "Static deflection, spring and support forces, shaft stresses under gravity and static loads";
  static constexpr std::string_view example = "feran static examples/02_centrifuge/model.toml --gravity -x";
  static constexpr std::string_view footer =
      "Gravity comes from --gravity, else the model's [static] table, else -y at 9.81 m/s^2.\n"
      "The model's [[static_loads]] act too unless --no-loads is given.";
  using Spec = StaticSpec;
  using Options = StaticOptions;
  using Result = StaticResult;

  /// gravity -y at 9.81 m/s², speed 0, the static loads, the stability judged.
  static const StaticSpec& defaults();
  static const StaticSpec& file_table(const ModelSpec& spec) { return spec.static_; }
  /// Throws Error for g given with gravity "none".
  static StaticOptions settings(const Model& model, const StaticSpec& asked, const StaticSpec& resolved,
                                const OptionName& named);
  static StaticResult run(const Model& model, const StaticOptions& options, const RunContext& context);
  /// Tables evaluated beyond their range at the analysis's speed.
  static std::vector<std::string> warnings(const Model& model, const StaticOptions& options,
                                           const StaticResult& result);
  /// The documented JSON (docs/output-format.md), the CSV (one row per shaft station:
  /// the displacements of its node, the section forces and the stresses) and the
  /// terminal report (deflections, spring and support forces, shaft stresses).
  static std::string json(const Outcome<StaticAnalysis>& o);
  static std::string csv(const Outcome<StaticAnalysis>& o);
  static std::string terminal(const Outcome<StaticAnalysis>& o);
  /// Its study quantities: static_deflection, static_stress, static_spring_force,
  /// min_static_bearing_value and max_static_bearing_value (docs/study-format.md). A
  /// design whose equilibrium is unstable has none: the rotor does not stay there.
  static const std::vector<QuantityRow>& quantities();
};

/// The static options of @p file as its own tables give them (no request): what an
/// analysis that applies gravity (API 684's journal loads, a run-up's gravity) takes.
StaticOptions static_options(const ModelFile& file);
/// The same from a spec and its model.
StaticOptions static_options(const ModelSpec& spec, const Model& model);

}  // namespace feran

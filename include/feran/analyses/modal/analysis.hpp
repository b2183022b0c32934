#pragma once
/// @file
/// The modal analysis's face (analyses/analysis.hpp): its options ([modal]), its
/// result and its writers, as every door uses them.

#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

/// What run_modal() takes: the speed and the solver's options.
struct ModalSettings {
  Real speed = 0.0;  ///< [rad/s]
  ModalOptions options;
};

struct ModalAnalysis {
  static constexpr std::string_view name = "modal";
  static constexpr std::string_view summary = "Natural frequencies, damping and mode shapes at one speed";
  static constexpr std::string_view example = "feran modal examples/01_internal_damping/model.toml --speed 30Hz";
  static constexpr std::string_view footer =
      "The speed defaults to [modal] speed in the model file, else 0. Modes are sorted by\n"
      "frequency; rigid-body modes are marked as such.";
  /// The modes that converged are kept when the solver stops short of the number asked.
  static constexpr bool keeps_partial_results = true;
  using Spec = ModalSpec;
  using Options = ModalSettings;
  using Result = ModalResult;

  /// Speed 0, the modes the solver gives, the automatic solver, no shapes.
  static const ModalSpec& defaults();
  static const ModalSpec& file_table(const ModelSpec& spec) { return spec.modal; }
  static ModalSettings settings(const Model& model, const ModalSpec& asked, const ModalSpec& resolved,
                                const OptionName& named);
  static ModalResult run(const Model& model, const ModalSettings& options, const RunContext& context);
  /// Tables evaluated beyond their range at the speed and at the modes' frequencies.
  static std::vector<std::string> warnings(const Model& model, const ModalSettings& options, const ModalResult& result);
  /// The documented JSON (with the shapes when asked for), the CSV (one row per mode;
  /// the supports' state is in the JSON) and the terminal table.
  static std::string json(const Outcome<ModalAnalysis>& o);
  static std::string csv(const Outcome<ModalAnalysis>& o);
  static std::string terminal(const Outcome<ModalAnalysis>& o);
  /// Its study quantities: natural_frequency, damping_ratio and log_decrement of the
  /// n-th lateral mode of a whirl at the quantity's speed.
  static const std::vector<QuantityRow>& quantities();
};

}  // namespace feran

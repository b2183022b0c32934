#pragma once
/// @file
/// The steady-state response's face (analyses/analysis.hpp): its options ([response]),
/// its result and its writers, as every door uses them.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

struct ResponseAnalysis {
  static constexpr std::string_view name = "response";
  static constexpr std::string_view summary =
      "Steady-state response to unbalance and harmonic forces: orbits, bearing forces, stresses";
  static constexpr std::string_view example =
      "feran response examples/01_internal_damping/model.toml --start 0Hz --stop 80Hz --points 161 --probe rotor";
  static constexpr std::string_view footer =
      "A speed sweep (--start, --stop, --points) excites at the rotor speed (unbalances and the\n"
      "model's [[forces]]); a frequency sweep (--freq-start, --freq-stop, --freq-points) holds the\n"
      "rotor at --speed and excites with the forces at each frequency; --speed alone gives the\n"
      "response at that one speed. A frequency response function:\n"
      "  feran response MODEL --speed 30Hz --freq-start 1Hz --freq-stop 200Hz --force rotor:y:1N \\\n"
      "      --no-unbalance --probe rotor\n"
      "Unset options come from the model's [response] table; probes default to every node\n"
      "carrying an unbalance or a force.";
  using Spec = ResponseSpec;
  using Options = HarmonicOptions;
  using Result = HarmonicResult;
  static constexpr bool keeps_partial_results = true;  // the points solved before a failure or a stop
  static constexpr bool parallel = true;

  /// A speed sweep from 0 with 201 points (its last speed required), a frequency sweep
  /// of 201 points at speed 0, no loss factor, station summaries, the unbalances, the
  /// stability judged.
  static const ResponseSpec& defaults();
  static const ResponseSpec& file_table(const ModelSpec& spec) { return spec.response; }
  /// Throws Error for options of both a speed sweep and a fixed speed, a sweep without
  /// its last point or with it not above the first, a frequency sweep without a force,
  /// nothing that excites the rotor, an unknown node or a force text not understood.
  static HarmonicOptions settings(const Model& model, const ResponseSpec& asked, const ResponseSpec& resolved,
                                  const OptionName& named);
  static HarmonicResult run(const Model& model, const HarmonicOptions& options, const RunContext& context);
  /// Tables evaluated beyond their range over the speeds and frequencies solved, and
  /// journals whose linearised orbit leaves the clearance (clearance_warnings()).
  static std::vector<std::string> warnings(const Model& model, const HarmonicOptions& options,
                                           const HarmonicResult& result);
  /// The documented JSON (docs/output-format.md), the CSV (one row per point: per probe
  /// the orbit and the amplitude and phase of v and w, per spring–damper and bearing the
  /// peak lateral force, the largest equivalent stress) and the terminal report (orbit
  /// sizes at selected points, the stability, the peaks).
  static std::string json(const Outcome<ResponseAnalysis>& o);
  static std::string csv(const Outcome<ResponseAnalysis>& o);
  static std::string terminal(const Outcome<ResponseAnalysis>& o);
  /// Its study quantities: peak_response, amplification_factor, required_margin,
  /// margin_surplus, min_margin_surplus, peak_spring_force and peak_stress
  /// (docs/study-format.md).
  static const std::vector<QuantityRow>& quantities();
  /// What a design study asks of it besides the file's table: the probes its
  /// quantities name.
  static ResponseSpec study_request(const Model& model, std::span<const QuantitySpec> quantities);
};

/// The response options of @p file for @p request, options named as the file's keys
/// ("response.stop"): for C++ programs and tests.
HarmonicOptions response_options(const ModelFile& file, const ResponseSpec& request = {});

}  // namespace feran

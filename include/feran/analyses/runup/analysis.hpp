#pragma once
/// @file
/// The run-up's face (analyses/analysis.hpp): its options ([runup]), its result and its
/// writers, as every door uses them. The time integration itself is in
/// analyses/transient/.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

struct RunupAnalysis {
  static constexpr std::string_view name = "runup";
  static constexpr std::string_view summary =
      "Run-up (time integration along a speed profile): time histories, |r| envelope, forces";
  static constexpr std::string_view example =
      "feran runup examples/01_internal_damping/model.toml --from 0Hz --to 80Hz --ramp-time 5s --probe rotor";
  static constexpr std::string_view footer =
      "The speed profile is one of: --speed (constant), --from/--to/--ramp-time (linear,\n"
      "then held), --table TIME:SPEED,... (piecewise linear, e.g. 0s:0Hz,2s:50Hz,5s:50Hz);\n"
      "--drive makes the speed a state driven by the model's [drive] from the profile's first\n"
      "speed. Unset options come from the model's [runup] table. Integrators: trapezoidal\n"
      "(Newton), rk3 (explicit), wolfbrandt (W-method, order 2), ros34pw2 (W-method, order 3,\n"
      "adaptive). The CSV is written sample by sample as the run goes.";
  using Spec = RunupSpec;
  using Options = TransientOptions;
  using Result = TransientResult;
  static constexpr bool keeps_partial_results = true;  // the samples up to a failure or a stop
  static constexpr bool streams_csv = true;

  /// The trapezoidal rule at 1e-4 s, samples every 1 ms, the integrators' tolerances,
  /// from rest, without gravity, static loads or drive.
  static const RunupSpec& defaults();
  static const RunupSpec& file_table(const ModelSpec& spec) { return spec.runup; }
  /// Throws Error for two profile forms, an incomplete ramp, no profile anywhere, no
  /// duration, a table that does not start at 0 or go forward in time, too many steps
  /// or samples, a drive without [drive], an unknown node or spring.
  static TransientOptions settings(const Model& model, const RunupSpec& asked, const RunupSpec& resolved,
                                   const OptionName& named);
  /// Throws Error when the integrator refused to take a step (rk3 above its stability
  /// limit): a bad option, not a failed run.
  static TransientResult run(const Model& model, const TransientOptions& options, const RunContext& context);
  /// Tables evaluated beyond their range over the speeds the run went through.
  static std::vector<std::string> warnings(const Model& model, const TransientOptions& options,
                                           const TransientResult& result);
  /// The documented JSON (docs/output-format.md), the CSV (one row per sample: time,
  /// speed, per probe |r| and its six DOFs, per spring its force, the bearings' state;
  /// streamed by the command line as the run goes, made from the kept samples here) and
  /// the terminal report (the integrator's work, each probe's peak |r|).
  static std::string json(const Outcome<RunupAnalysis>& o);
  static std::string csv(const Outcome<RunupAnalysis>& o);
  static std::string terminal(const Outcome<RunupAnalysis>& o);
  /// Its study quantities: runup_peak and runup_spring_force (docs/study-format.md).
  static const std::vector<QuantityRow>& quantities();
  /// The probes and springs its quantities name (a quantity of every spring: all of
  /// them).
  static RunupSpec study_request(const Model& model, std::span<const QuantitySpec> quantities);
};

/// The CSV header of a run-up with @p options, and one sample's row (each ends with a
/// newline): what RunupAnalysis streams through RunContext::csv.
std::string runup_csv_header(const Model& model, const TransientOptions& options);
std::string runup_csv_row(const TransientSample& sample);

/// The run-up options of @p file for @p request, options named as the file's keys
/// ("runup.dt"): for C++ programs and tests.
TransientOptions runup_options(const ModelFile& file, const RunupSpec& request = {});

}  // namespace feran

#pragma once
/// @file
/// The periodic orbits' face (analyses/analysis.hpp): the command `orbits`, its options
/// ([orbits]), its result (branches of steady states with their stability and
/// bifurcations, and the orbit at each probe) and its writers, as every door uses them.
/// The numerics are the room's other files (orbits.hpp).

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/common/solver_info.hpp>
#include <feran/analyses/periodic/orbits.hpp>
#include <feran/analyses/periodic/settle.hpp>
#include <feran/core/units.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

/// What the orbits analysis does, resolved from [orbits] and the model.
struct OrbitsOptions {
  /// The branch parameter's range: speeds [rad/s], or the path's values in SI units.
  Real from = 0.0, to = 0.0;
  /// Empty: the parameter is the speed. Else a parameter path (spec/parameters.hpp),
  /// continued at the fixed speed `speed`.
  std::string parameter;
  std::optional<Quantity> parameter_quantity;  ///< its kind (none: a number)
  std::string parameter_unit;                  ///< the unit it is shown in ("mPa*s"); empty: SI
  /// The model with the parameter at a value (SI): set only for a parameter branch.
  std::function<Model(Real)> build;
  Real speed = 0.0;  ///< a parameter branch's fixed speed [rad/s]
  /// "auto" (forced when an unbalance or synchronous force acts, else whirl), "forced"
  /// (the orbits at the rotor speed), "whirl" (the equilibrium without the unbalances
  /// and the self-excited orbits leaving each Hopf point) or "equilibrium".
  std::string branch = "auto";
  bool up = true, down = false;  ///< a forced branch's directions (down: a run-down)
  /// The parameter's value (SI) at which a run at constant speed finds the orbit the
  /// rotor settles on; the branches are then the one through it, followed up and down
  /// as `up` and `down` say. None: the branches start from the equilibrium.
  std::optional<Real> start_at;
  Real settle = 0.0;  ///< that run's longest simulated time [s] (0: 2000 revolutions)
  FourierBasis fourier{.harmonics = 8, .samples = 64};
  Index modes = 12;    ///< fixed-interface modes of the condensation
  Index points = 200;  ///< most points of each branch
  std::vector<Index> probes;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< [m/s²]
  bool static_loads = true;
};

/// The orbit of a probe node in the plane y–z: its centre (the mean over a period) and
/// its size.
struct ProbeOrbit {
  Real mean_v = 0.0, mean_w = 0.0;  ///< [m]
  Real amplitude = 0.0;             ///< the largest distance from the centre [m]
  Real largest = 0.0;               ///< the largest distance from the axis √(v² + w²) [m]
  /// The Fourier coefficients of v and w over the orbit's phase θ = ωt:
  /// [c0, a1, b1, …, aH, bH] for c0 + Σ a_k cos kθ + b_k sin kθ [m] (an equilibrium: c0).
  Vector v = Vector(), w = Vector();
};

struct OrbitsBranch {
  std::string name;  ///< "equilibrium", "forced (up)", "forced (down)", "whirl 1", …
  OrbitBranch branch;
  std::vector<std::vector<ProbeOrbit>> probes;       ///< per orbit, per probe
  std::vector<std::vector<ProbeOrbit>> bifurcation;  ///< per bifurcation, per probe
};

struct OrbitsResult {
  /// "forced", "whirl" or "equilibrium": what "auto" resolved to.
  std::string branch;
  std::vector<OrbitsBranch> branches;
  /// With OrbitsOptions::start_at: the run's orbit (before the balance corrected it),
  /// when it settled on one.
  std::optional<SettledOrbit> settled;
  Index dofs = 0;         ///< the model's unconstrained DOFs
  Index coordinates = 0;  ///< the condensed rotor's coordinates
  /// A branch that could not be started, or a stop: the branches so far are kept.
  SolverInfo info;
};

struct OrbitsAnalysis {
  static constexpr std::string_view name = "orbits";
  static constexpr std::string_view summary =
      "Periodic orbits by harmonic balance: branches over speed, Floquet stability, folds, Hopf points, whirl";
  static constexpr std::string_view example =
      "feran orbits examples/06_oil_whip/model.toml --from 3000rpm --to 9000rpm --probe disk";
  static constexpr std::string_view footer =
      "The branch is the unbalance's forced orbits when the model has one, else the static\n"
      "equilibrium and the self-excited whirl leaving each Hopf point (--branch). --direction\n"
      "down or both adds the run-down. --parameter PATH with --parameter-from, --parameter-to\n"
      "and --speed continues in a number of the model at a fixed speed instead. --start-at\n"
      "follows the branch through the orbit a run at that speed (or value) settles on.";
  using Spec = OrbitsSpec;
  using Options = OrbitsOptions;
  using Result = OrbitsResult;
  static constexpr bool keeps_partial_results = true;  // the branches up to a failure or a stop

  /// 8 harmonics on 64 samples, 12 modes, 200 points, branch "auto" upwards, with the
  /// file's gravity and static loads.
  static const OrbitsSpec& defaults();
  static const OrbitsSpec& file_table(const ModelSpec& spec) { return spec.orbits; }
  /// Throws Error for no range, a range the wrong way round, a speed range together
  /// with a parameter, a bad parameter path or value, samples too few for the
  /// harmonics, an unknown probe.
  static OrbitsOptions settings(const Model& model, const ModelSpec& spec, const OrbitsSpec& asked,
                                const OrbitsSpec& resolved, const OptionName& named);
  /// Throws Error for what the periodic analysis cannot take (CondensedRotor says why)
  /// and for a forced branch asked of a rotor without an unbalance.
  static OrbitsResult run(const Model& model, const OrbitsOptions& options, const RunContext& context);
  /// Tables evaluated beyond their range over the speeds, orbits whose truncation
  /// estimate asks for more harmonics, branches that ended before the range's end,
  /// unbalances left out of a whirl branch.
  static std::vector<std::string> warnings(const Model& model, const OrbitsOptions& options,
                                           const OrbitsResult& result);
  /// The documented JSON (docs/output-format.md), the CSV (one row per orbit of every
  /// branch, then the bifurcations) and the terminal report (each branch's stable and
  /// unstable stretches and its bifurcations).
  static std::string json(const Outcome<OrbitsAnalysis>& o);
  static std::string csv(const Outcome<OrbitsAnalysis>& o);
  static std::string terminal(const Outcome<OrbitsAnalysis>& o);
  /// Its study quantities: jump_down_speed and largest_stable_orbit
  /// (docs/study-format.md).
  static const std::vector<QuantityRow>& quantities();
  /// The probe its quantities name.
  static OrbitsSpec study_request(const Model& model, std::span<const QuantitySpec> quantities);
};

/// The orbits options of @p file for @p request, options named as the file's keys
/// ("orbits.from"): for C++ programs and tests.
OrbitsOptions orbits_options(const ModelFile& file, const OrbitsSpec& request = {});

}  // namespace feran

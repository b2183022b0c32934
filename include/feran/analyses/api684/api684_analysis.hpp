#pragma once
/// @file
/// The lateral analyses API 617 (8th ed., §2.6) asks of a rotor, read as API 684
/// (2nd ed.) explains them: the analytical unbalance (4W/N) placed to excite each
/// mode, the unbalance responses with each critical speed's amplification factor and
/// separation margins, the undamped critical speed map and the level I stability
/// sweep (docs/theory/api684.md).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/api684/critical_speed_map.hpp>
#include <feran/analyses/api684/level1_stability.hpp>
#include <feran/analyses/common/solver_info.hpp>
#include <feran/analyses/harmonic/api684.hpp>
#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/core/stop.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// The analytical unbalance of API 617 (8th ed.) §2.6.2.7, U_b = 6350·W/N g·mm (4·W/N
/// oz·in in US units), W the journal load [kg], N the maximum continuous speed [rpm]
/// (at most 25 000 rpm: above it U_b = 0.254·W g·mm), here from @p mass [kg] and
/// @p speed [rad/s], in kg·m.
Real api684_unbalance_amount(Real mass, Real speed);

/// Mass of the rotating parts of @p model [kg], or of those at the nodes @p selected
/// picks: rᵀ·M·r for r the unit lateral translation of those rotating nodes.
Real rotating_mass(const Model& model, const std::function<bool(Index node)>& selected = {});

/// The static load of a bearing: the lateral force it carries under @p gravity.
struct JournalLoad {
  Index element = 0;  ///< the bearing, an element of linearised(model)
  Index node = 0;     ///< its rotating node
  Real force = 0;     ///< |(F_y, F_z)| [N]
  Real mass = 0;      ///< force / g [kg]: W of 4W/N
};

/// The loads of the bearings @p springs (elements of linearised(@p model), each
/// holding a rotating node) under @p model's gravity and static loads, from its static
/// equilibrium. Throws Error without gravity.
std::vector<JournalLoad> journal_loads(const Model& model, const std::vector<Index>& springs,
                                       const StaticOptions& gravity);

/// One analytical unbalance.
struct PlacedUnbalance {
  Index node = 0;
  Real amount = 0;    ///< m·r [kg·m]
  Real phase = 0;     ///< [rad]
  Real mass = 0;      ///< the W it was computed from [kg]
  std::string basis;  ///< "rotor", "overhung" or the bearing's name
};

/// The unbalances API 684 (2nd ed., §2.5.2 and Fig. 2-25) places to excite a mode of
/// shape @p shape: one at the largest amplitude of a mode whose rotor moves in phase
/// between the bearings (W: the sum of the journal loads); one at the largest
/// amplitude of each of the two opposite-phase lobes of a mode that changes sign
/// between them, 180° apart (W: the nearer bearing's load); one at the largest
/// amplitude of an overhang when that is where the mode is largest (W: the overhung
/// mass). Each is @p multiple times 4W/N at @p speed [rad/s].
std::vector<PlacedUnbalance> api684_placement(const Model& model, const ComplexVector& shape,
                                              const std::vector<JournalLoad>& journals, Real speed,
                                              Real multiple = 1.0);

struct Api684Options {
  Real low = 0, high = 0;    ///< the operating speed range [rad/s]; high: the maximum continuous speed
  std::vector<Real> speeds;  ///< the unbalance responses' speeds [rad/s]
  int modes = 2;             ///< modes excited by the analytical unbalance, the lowest forward ones
  /// The model's own unbalances in one response instead of the analytical ones.
  bool model_unbalance = false;
  Real unbalance_multiple = 1.0;
  std::vector<Index> probes;                   ///< empty: each bearing's node and each unbalance's node
  std::vector<Index> bearings;                 ///< elements of linearised(model); empty: bearing_elements() of it
  StaticOptions gravity;                       ///< for the journal loads
  std::optional<CriticalSpeedMapOptions> map;  ///< none: no map (its springs: the bearings)
  std::optional<StabilitySweepOptions> stability;
  int n_threads = 1;
  StopToken stop;
};

/// One unbalance case and its reading.
struct Api684Case {
  std::string name;          ///< "mode 1", … or "model unbalance"
  std::optional<Mode> mode;  ///< the mode it excites (at the maximum continuous speed)
  std::vector<PlacedUnbalance> unbalances;
  HarmonicResult response;
  /// Per probe (in the order of response.probes): its peaks and their margins.
  std::vector<std::vector<SeparationCheck>> checks;
  /// Every peak that can be judged passes (none judged: true).
  bool passes = true;
};

/// The stability verdict over the operating range: the rotor's stability
/// (modal/stability.hpp) at evenly spaced speeds from the minimum to the maximum
/// continuous speed, both included.
struct OperatingStability {
  std::vector<StabilityPoint> points;
  bool passes = true;  ///< every point stable (and decided)
  std::string reason;  ///< why it fails, or "stable at N speeds from … to …"
};

/// The verdict at @p points speeds over [@p low, @p high] [rad/s].
OperatingStability operating_stability(const Model& model, Real low, Real high, int points = 11);

struct Api684Result {
  Real low = 0, high = 0;
  /// Stability in the operating range: fails when any mode there has negative damping.
  OperatingStability stability_verdict;
  std::vector<Index> bearings;
  std::vector<JournalLoad> journals;
  /// Undamped forward critical speeds with the bearings as they are (their
  /// coefficients at each critical speed).
  std::vector<UndampedCritical> undamped;
  std::vector<Api684Case> cases;
  std::optional<CriticalSpeedMapResult> map;
  std::optional<StabilitySweepResult> stability;
  SolverInfo info;
};

/// Runs them all. Throws Error for bad options (a range without 0 < low ≤ high, no
/// speeds, no bearings, no gravity for 4W/N, no unbalance in the model with
/// model_unbalance).
Api684Result run_api684(const Model& model, const Api684Options& options);

}  // namespace feran

#pragma once
/// @file
/// The level I stability analysis of API 617 (8th ed., §2.6.5) and API 684 (2nd ed.,
/// §2.9): the logarithmic decrement of the first forward mode at the maximum continuous
/// speed against a destabilising cross-coupled stiffness Q added at one node, the Q at
/// which it reaches zero, and the screening against the anticipated cross-coupling
/// (docs/theory/api684.md, "Level I stability").

#include <optional>
#include <vector>

#include <feran/analyses/common/solver_info.hpp>
#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// The anticipated cross-coupling of one impeller stage, API 617 (8th ed.) §2.6.5.4:
/// q_A = B_c·C·P_r/(D_c·H_c·N_r)·(ρ_d/ρ_s), where C·P_r/N_r (C = 63 in US units, hp and
/// rpm, giving klbf·in) is the stage's torque. In SI: q_A = B_c·(P/Ω)/(D·H)·(ρ_d/ρ_s)
/// with P [W], Ω [rad/s], D, H [m] and q_A [N/m]; B_c = 3 for centrifugal stages.
struct StageLoading {
  Real power = 0;          ///< rated power of the stage P_r [W]
  Real diameter = 0;       ///< impeller diameter D_c [m]
  Real width = 0;          ///< the smaller of the diffuser or impeller discharge widths H_c [m]
  Real density_ratio = 1;  ///< ρ_d/ρ_s: discharge over suction gas density
  Real factor = 3;         ///< B_c: 3 for centrifugal, 1.5 for axial stages
};
/// q_A of @p stage at the rated speed @p speed [rad/s], in N/m.
Real anticipated_cross_coupling(const StageLoading& stage, Real speed);

struct StabilitySweepOptions {
  Index node = 0;  ///< where the cross-coupling acts (a rotating node)
  Real speed = 0;  ///< the maximum continuous speed [rad/s]
  /// The sweep's Q values run from 0 to q_high [N/m] at @p points; q_high 0: up to
  /// 1.5 times the Q at zero log decrement (or 10 q_A when that is larger).
  Real q_high = 0;
  int points = 41;
  std::optional<Real> anticipated;  ///< q_A [N/m], for the screening criteria
  StopToken stop;
};

struct StabilitySweepResult {
  Index node = 0;
  Real speed = 0;                   ///< [rad/s]
  std::vector<Real> q;              ///< [N/m]
  std::vector<Real> log_decrement;  ///< of the first forward mode at each Q
  std::vector<Real> frequency_hz;   ///< its damped natural frequency
  /// Q₀: the cross-coupling at which that log decrement is zero [N/m]; none when the
  /// mode is unstable without any, or stays stable up to 1e13 N/m.
  std::optional<Real> q_zero;
  std::optional<Real> anticipated;  ///< q_A [N/m]
  std::optional<Real> log_decrement_at_anticipated;
  /// API 617's level I screening: passes when Q₀/q_A ≥ 2 and δ(q_A) ≥ 0.1 (otherwise a
  /// level II analysis is required); none without q_A.
  std::optional<bool> screening_passes;
  SolverInfo info;
};

/// The cross-coupled stiffness Q added at @p node: the spring to ground with
/// k_yz = Q, k_zy = −Q, whose force (−Q·w, +Q·v) points along forward whirl.
Model with_cross_coupling(const Model& model, Index node, Real q);

/// The log decrement of the first (lowest) forward lateral mode of @p model at
/// @p speed, and its frequency [Hz]; throws Error when there is no forward mode.
std::pair<Real, Real> first_forward_log_decrement(const Model& model, Real speed);

/// The rotating node where the first forward lateral mode of @p model at @p speed
/// moves most: where API 617 puts the cross-coupling of a rotor whose stages are
/// not given (mid-span of a between-bearing rotor, the overhung impeller otherwise).
/// Throws Error when there is no forward lateral mode.
Index largest_forward_motion_node(const Model& model, Real speed);

/// Runs the sweep. Throws Error for a node out of range or not rotating, a speed ≤ 0
/// or fewer than 2 points.
StabilitySweepResult run_stability_sweep(const Model& model, const StabilitySweepOptions& options);

}  // namespace feran

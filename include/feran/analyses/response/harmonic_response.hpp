#pragma once
/// @file
/// Steady-state (harmonic) response to unbalance and harmonic forces (paper
/// section 2.3): the complex dynamic stiffness
///   K(jω) = K(Ω) + Ω·K_i − ω²M + jω(C + C_i + Ω·G) + j(Σ η_e K_e + η·K)
/// solved by a sparse complex LU at each point (the LU's symbolic analysis is shared
/// by all points; the points are solved in parallel). In a speed sweep the excitation is
/// synchronous (ω = Ω); in a frequency sweep the rotor speed Ω is fixed and ω runs.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/common/operating_state.hpp>
#include <feran/analyses/common/orbit.hpp>
#include <feran/analyses/common/shaft_sections.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/modal/stability.hpp>
#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// What a response keeps of the shaft's section forces and stresses, computed at both
/// ends of every shaft element.
enum class StationOutput {
  all,      ///< every station at every point (memory and output grow with stations × points)
  summary,  ///< per point the largest values over the stations, with their place
  none,     ///< no section forces or stresses
};

struct HarmonicOptions {
  /// Speed sweep: rotor speeds [rad/s]; the excitation is synchronous. Used when
  /// @p frequencies is empty.
  std::vector<Real> speeds;
  /// Frequency sweep: excitation frequencies [rad/s] at the constant rotor speed @p speed.
  std::vector<Real> frequencies;
  Real speed = 0.0;  ///< rotor speed of a frequency sweep [rad/s]
  /// Include the model's unbalances (speed sweeps only: in a frequency sweep they
  /// act at the rotor speed, not at the swept frequency). Every other force of the
  /// model with a harmonic load (Force::add_harmonic) takes part.
  bool unbalance = true;
  std::vector<HarmonicForce> extra_forces;  ///< forces added for this analysis
  Real loss_factor = 0.0;                   ///< global hysteretic loss factor η (adds jηK)
  std::vector<Index> probes;                ///< nodes whose motion is reported
  StationOutput stations = StationOutput::summary;
  /// Threads for the sweep's points (0: all cores; the library's default is one, the
  /// command line's all cores); results do not depend on it.
  int n_threads = 1;
  /// Asked before each point; the sweep then ends as interrupted, its points up to
  /// the first not solved kept.
  StopToken stop;
  /// Judge the rotor's stability at each point (modal/stability.hpp): a steady state
  /// at a speed where the free motion grows is marked so. false: not judged (the
  /// result's stability is then empty).
  bool stability = true;
};

/// Complex amplitudes of the six DOFs of a node, indexed by Dof.
using NodeAmplitudes = std::array<Complex, dofs_per_node>;

struct ProbeResponse {
  Index node = 0;
  std::vector<NodeAmplitudes> q;  ///< per point: u, v, w, rx, ry, rz
  std::vector<Orbit> orbit;       ///< per point: orbit of (v, w)
};

/// Force a spring–damper transmits to its second node (or ground), per point:
/// (K(1 + jη) + jωC)·(q_a − q_b), six components indexed by Dof.
struct SpringForceResponse {
  Index element = 0;
  std::vector<NodeAmplitudes> force;
  std::vector<Real> peak_lateral;  ///< largest |(F_y, F_z)| over a period [N]
};

/// Force a nonlinear support (a journal bearing) transmits to its housing or the
/// ground, per point, from its coefficients about the equilibrium at each speed:
/// (K_b + jωC_b)·(q_a − q_b), six components indexed by Dof (lateral ones nonzero).
struct SupportForceResponse {
  Index force = 0;  ///< index into Model::forces
  std::vector<NodeAmplitudes> amplitude;
  std::vector<Real> peak_lateral;  ///< largest |(F_y, F_z)| over a period [N]
  /// The major semi-axis of the journal's (v, w) orbit relative to its housing [m].
  std::vector<Real> orbit;
  /// That orbit over the support's radial clearance (Force::clearance()); NaN without
  /// one. Above 1 the linearised response is no motion the bearing allows.
  std::vector<Real> orbit_clearance_ratio;
};

/// Force transmitted to the supports at the fixed DOFs of a node, per point.
struct ReactionResponse {
  Index node = 0;
  std::array<bool, dofs_per_node> fixed{};
  std::vector<NodeAmplitudes> force;
  std::vector<Real> peak_lateral;
};

struct StationResponse {
  ShaftStation station;
  std::vector<SectionForces> forces;
  std::vector<SectionStress> stress;
};

/// The largest value of one quantity over the shaft stations at one point, and where.
struct StationPeak {
  Real value = 0;
  Index station = -1;  ///< index into HarmonicResult::shaft_stations (-1: no station)
};

/// Per point, the largest section values over all stations (StationOutput::all and
/// summary): equivalent stress, bending moment and shear force (their largest
/// magnitude over a period, as in StationResponse).
struct StationPeaks {
  StationPeak von_mises;       ///< [Pa]
  StationPeak bending_moment;  ///< largest |(M_y, M_z)| [N m]
  StationPeak shear_force;     ///< largest |(V_y, V_z)| [N]
};

struct HarmonicResult {
  bool frequency_sweep = false;
  std::vector<Real> speeds;       ///< rotor speed per point [rad/s]
  std::vector<Real> frequencies;  ///< excitation frequency per point [rad/s]
  std::vector<ProbeResponse> probes;
  std::vector<SpringForceResponse> springs;
  std::vector<SupportForceResponse> supports;  ///< journal bearings, in Model::forces order
  /// Per support (in the order of supports), its operating state at the equilibrium at
  /// each point's speed, about which the response is linear.
  std::vector<OperatingSeries> operating;
  std::vector<ReactionResponse> reactions;
  /// Both ends of every shaft element (empty with StationOutput::none).
  std::vector<ShaftStation> shaft_stations;
  /// Per point (StationOutput::all and summary).
  std::vector<StationPeaks> station_peaks;
  /// Every station's values at every point (StationOutput::all only), in the order
  /// of shaft_stations.
  std::vector<StationResponse> stations;
  /// Per point, the rotor's stability at its speed (HarmonicOptions::stability; empty
  /// when not judged). Where it is unstable the response is no steady state that the
  /// rotor reaches: any disturbance grows instead.
  std::vector<StabilityPoint> stability;
  /// converged() is false when the dynamic stiffness was singular at some point (an
  /// undamped resonance hit exactly); the vectors then stop before that point.
  SolverInfo info;
};

/// The first point of @p result at which the rotor is unstable; -1 when none is (or
/// stability was not judged).
Index first_unstable_point(const HarmonicResult& result);
/// How many points of @p result are unstable.
Index unstable_points(const HarmonicResult& result);

/// The largest values of a harmonic result.
struct ResponseSummary {
  struct Peak {
    Real value = 0;    ///< the peak
    Index point = -1;  ///< where in the sweep (-1: nothing to report)
    Index item = -1;   ///< which probe / spring / reaction / station
  };
  std::vector<Peak> probe_peaks;  ///< per probe: largest major semi-axis of the (v, w) orbit
  Peak spring_force;              ///< largest peak lateral spring force
  Peak support_force;             ///< largest peak lateral journal-bearing force (item: index into supports)
  Peak reaction_force;            ///< largest peak lateral support reaction
  Peak stress;                    ///< largest equivalent stress (item: index into shaft_stations)
};

HarmonicResult run_harmonic_response(const Model& model, const HarmonicOptions& options);
/// The names of StationOutput in model files, on the command line and in the JSON
/// output: "all", "summary", "none".
const char* to_string(StationOutput output);
ResponseSummary summarize(const HarmonicResult& result);

/// Warnings for journals whose linearised orbit leaves the clearance (largest
/// SupportForceResponse::orbit_clearance_ratio above 1): one per support, naming it,
/// the ratio and the speed; such a response is no motion the bearing allows (the
/// unbalance is too large for a linear analysis: a run-up shows the real motion).
std::vector<std::string> clearance_warnings(const HarmonicResult& result, const Model& model);

}  // namespace feran

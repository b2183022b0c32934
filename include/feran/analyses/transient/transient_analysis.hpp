#pragma once
/// @file
/// Run-up / run-down simulation (paper section 2.4): time integration of the rotor
/// model along a speed profile, with output sampled at a fixed interval.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/common/operating_state.hpp>
#include <feran/integrators/integrator.hpp>
#include <feran/analyses/transient/speed_profile.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/stop.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Where a run-up starts.
enum class RunupStart {
  rest,          ///< at rest (or from initial_displacement and initial_velocity)
  equilibrium,   ///< at the static equilibrium at the first speed under the run's constant load
  steady_state,  ///< the equilibrium plus the steady unbalance response at the first speed
};

struct TransientOptions {
  SpeedProfile profile = SpeedProfile::constant(0.0);
  Real duration = 1.0;                     ///< [s]
  std::string integrator = "trapezoidal";  ///< see integrator_names()
  IntegratorSettings settings;
  Real output_interval = 1e-3;  ///< sampling interval of the output [s]
  std::vector<Index> probes;    ///< nodes whose motion is recorded
  std::vector<Index> springs;   ///< spring–damper elements whose force is recorded
  bool static_loads = false;    ///< apply the model's static loads as constant forces
  /// Gravitational acceleration applied as a constant force (M·g) [m/s²]; zero: none.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  /// With equilibrium and steady_state, initial_displacement and initial_velocity are
  /// a disturbance added to that state.
  RunupStart start = RunupStart::rest;
  /// Torque-driven: the speed is a state driven by the model's drive (Model::drive,
  /// required), starting at profile.speed(0); the rest of the profile is not used.
  /// The full model is integrated (reduced_modes must be 0).
  bool driven = false;
  /// The run stops when a displacement exceeds this [m] or a rotation this [rad].
  Real blowup_limit = 1.0;
  Index envelope_bins = 400;  ///< speed bins of the |r| envelope
  bool keep_samples = true;   ///< keep the samples in the result
  /// Initial displacements and velocities of all unconstrained DOFs (global_dof
  /// order); empty: at rest. Values at fixed or follower DOFs are ignored.
  Vector initial_displacement, initial_velocity;
  /// 0: integrate the full model. N > 0: integrate in the basis of the N lowest
  /// undamped modes at modal_basis_speeds speeds of the profile (modal_basis.hpp),
  /// which removes the high finite-element modes that limit explicit steps.
  Index reduced_modes = 0;
  /// Asked before each step; the run then ends as interrupted at the last step taken.
  StopToken stop;
  /// The model's assembly when the caller has it (ModelFile::assembler): used instead
  /// of assembling the model again. It must be the assembly of the model run.
  std::shared_ptr<const Assembler> assembled;
};

/// Number of speeds, evenly spaced in time over the run, at which the basis of a
/// reduced run takes its modes.
inline constexpr int modal_basis_speeds = 5;

/// The recorded state at one output time.
struct TransientSample {
  Real t = 0;
  Real speed = 0;                                        ///< [rad/s]
  std::vector<std::array<Real, dofs_per_node>> probes;   ///< per probe node: u, v, w, rx, ry, rz
  std::vector<Real> magnitude;                           ///< per probe: |r| = √(v² + w²)
  std::vector<std::array<Real, dofs_per_node>> springs;  ///< per recorded spring: K·Δq + C·Δq'
  /// Per support (TransientResult::operating), its operating state in this motion.
  std::vector<std::vector<Real>> operating;
};

/// The largest excursion of a support's journal within its clearance over a run
/// (evaluated at every step, not only at the output times).
struct ClearanceUse {
  Index force = 0;     ///< index into Model::forces
  Real clearance = 0;  ///< its radial clearance [m]
  Real largest = 0;    ///< largest |journal − housing| (v, w) over the clearance
  Real time = 0;       ///< when [s]
  Real speed = 0;      ///< at which speed [rad/s]
};

/// Largest |r| of a probe within speed bins (evaluated at every step, not only at
/// the output times).
struct Envelope {
  std::vector<Real> speed;      ///< bin centres [rad/s]
  std::vector<Real> magnitude;  ///< largest |r| in the bin [m]; NaN when never visited
  Real peak = 0;                ///< largest |r| of the run [m]
  Real peak_time = 0;           ///< [s]
  Real peak_speed = 0;          ///< [rad/s]
};

struct TransientResult {
  std::vector<TransientSample> samples;  ///< when keep_samples
  std::vector<Envelope> envelopes;       ///< per probe
  /// Per support (Force::supports()), its operating state at the output times (the
  /// values only when keep_samples; the samples carry them too).
  std::vector<OperatingSeries> operating;
  /// Per support with a clearance (Force::clearance()).
  std::vector<ClearanceUse> clearance_use;
  /// converged() is false when the run stopped early (integrator failure, blow-up,
  /// non-finite values); message says when and where. Results up to then are kept.
  SolverInfo info;
  std::string warning;     ///< e.g. rk3 run above its stability limit on request
  Real t_end = 0;          ///< time reached [s]
  Real speed_end = 0;      ///< speed at t_end [rad/s] (the profile's, or a torque-driven run's result)
  Real wall_seconds = -1;  ///< the run's wall-clock time, when its door measured it (negative: not)
  Index steps = 0, rejected = 0, factorizations = 0, newton_iterations = 0;
  Index basis_size = 0;  ///< columns of the modal basis of a reduced run (0: full model)
};

using SampleSink = std::function<void(const TransientSample&)>;
/// Called every few steps with the time reached and the current step size.
using ProgressSink = std::function<void(Real t, Real dt)>;

/// Integrates from the initial state (rest unless given). Throws feran::Error for a bad option
/// (unknown integrator, non-positive step or interval).
TransientResult run_transient(const Model& model, const TransientOptions& options, const SampleSink& sink = {},
                              const ProgressSink& progress = {});

}  // namespace feran

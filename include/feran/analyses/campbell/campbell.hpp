#pragma once
/// @file
/// Campbell diagram: modes tracked over a speed sweep, critical speeds and the
/// stability threshold.

#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

struct CampbellOptions {
  std::vector<Real> speeds;    ///< increasing speeds [rad/s], at least 2
  Index n_modes = 8;           ///< modes tracked (the lowest at the first speed)
  std::vector<int> orders{1};  ///< harmonic orders k of the excitation lines f = k·Ω/2π
  ModalOptions modal;          ///< eigen solver settings (n_modes and shapes are set internally)
  /// Speed resolution of critical speeds and of the threshold [rad/s].
  Real speed_tolerance = 1e-8;
  /// A damping ratio below −this counts as negative: round-off in the damping
  /// ratio of an undamped mode is ~1e-13, physical ones are ≥ 1e-5.
  Real damping_tolerance = 1e-9;
  /// Threads for the eigen solves (0: all cores). The speeds, and then the
  /// refinements of critical speeds and thresholds, are independent solves; the
  /// results do not depend on the number of threads. The library's default is one
  /// thread, the command line's all cores.
  int n_threads = 1;
  /// Asked before each eigen solve; the sweep then ends as interrupted, its speeds
  /// up to the first not solved kept.
  StopToken stop;
};

/// One mode followed over the sweep. Vectors are indexed like CampbellResult::speeds;
/// NaN where the mode could not be followed.
struct TrackedMode {
  /// "forward bending 1", "backward cylindrical 1", "forward conical 1", "torsional 1",
  /// …: its whirl at most speeds and its shape at the first speed, numbered by
  /// frequency at the first speed within them.
  std::string label;
  /// The sense it whirls in at most speeds: forward, backward or mixed by its
  /// orbits, a nearly straight-line orbit counting by the sign of its directivity;
  /// planar only when it whirls at no speed of the sweep; none for axial and
  /// torsional modes. The label's family.
  Whirl whirl = Whirl::none;
  ModeType type = ModeType::lateral;
  std::vector<Real> frequency_hz;
  std::vector<Real> damping_ratio;
  std::vector<Real> log_decrement;
  std::vector<Real> directivity;
  std::vector<Whirl> whirl_at;
  std::vector<Real> bending;        ///< Mode::bending per speed
  std::vector<ModeShape> shape_at;  ///< Mode::shape_kind per speed
  /// The shape it has at the first speed it was found at (none for axial and
  /// torsional modes).
  ModeShape shape_kind = ModeShape::none;
  std::vector<Real> correlation;  ///< MAC with the same mode at the previous speed
};

/// A speed where a tracked mode's frequency equals order·speed.
struct CriticalSpeed {
  Real speed = 0;         ///< [rad/s]
  Real frequency_hz = 0;  ///< = order·speed/2π
  Index mode = 0;         ///< index into CampbellResult::modes
  int order = 1;
  /// The sense the mode whirls in at the critical speed, as for TrackedMode::whirl
  /// (planar only for a straight-line orbit).
  Whirl whirl = Whirl::none;
};

/// The lowest speed at which a mode's damping ratio turns negative.
struct StabilityThreshold {
  Real speed = 0;                  ///< [rad/s]
  Index mode = 0;                  ///< index into CampbellResult::modes; −1 for a divergence
  Real frequency_hz = 0;           ///< the mode's frequency there (0 for a divergence)
  bool unstable_at_start = false;  ///< already negative at the first speed
  /// A real eigenvalue turns positive (a negative stiffness, a shaft beyond its
  /// buckling load): a divergence, which no tracked (oscillating) mode shows.
  bool divergence = false;
};

struct CampbellResult {
  std::vector<Real> speeds;  ///< speeds solved [rad/s] (fewer than asked if a solve failed)
  std::vector<TrackedMode> modes;
  std::vector<CriticalSpeed> critical_speeds;  ///< sorted by speed
  std::optional<StabilityThreshold> stability_threshold;
  SolverInfo info;     ///< method used; converged() is false if a solve failed (results so far kept)
  Index n_solves = 0;  ///< eigen solves, grid and refinement
  /// Per support (Force::supports()), its operating state at the equilibrium at each
  /// of speeds.
  std::vector<OperatingSeries> operating;
};

/// How the threshold's unstable motion is named: the tracked mode's label, or
/// "divergence (a real eigenvalue)".
std::string threshold_label(const CampbellResult& result, const StabilityThreshold& threshold);

/// Mode @p mode's name by its whirl alone, as the literature numbers whirl modes
/// ("forward 2": the second forward mode by frequency at the first speed), whatever
/// its shape; the type for axial and torsional modes ("torsional 1").
std::string whirl_name(const CampbellResult& result, Index mode);

/// Runs the sweep. Modes are matched from speed to speed by the complex MAC of their
/// shapes with a predicted eigenvalue (linear extrapolation) as second criterion, by
/// optimal assignment; critical speeds and the threshold are bracketed on the grid and
/// refined by Brent's method with a fresh eigen solve at each trial speed.
/// @p assembled: @p model already assembled, or null (see ModalSolver).
CampbellResult run_campbell(const Model& model, const CampbellOptions& options,
                            std::shared_ptr<const Assembler> assembled = nullptr);

}  // namespace feran

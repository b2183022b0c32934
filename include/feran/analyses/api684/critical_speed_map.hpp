#pragma once
/// @file
/// Undamped critical speeds and the undamped critical speed map of API 684 (2nd ed.,
/// §2.3.1): the critical speeds of the rotor against the stiffness of its bearings,
/// with the bearings' own stiffness curves and the intersections of the two
/// (docs/theory/api684.md, "Undamped critical speed map").

#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/common/solver_info.hpp>
#include <feran/core/stop.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// An undamped critical speed: a speed Ω at which the rotor whirls synchronously,
/// K(Ω)·x = Ω²·(M − i·G)·x, damping left out.
struct UndampedCritical {
  Real speed = 0;        ///< [rad/s]
  Real directivity = 0;  ///< of its shape (Mode::directivity): +1 forward circles
  ComplexVector shape;   ///< over all unconstrained DOFs, largest component 1
};

/// The @p n lowest forward undamped critical speeds of @p model: the synchronous
/// forward whirl with the gyroscopic moments (@p gyroscopic), or, without them, the
/// undamped natural frequencies at rest. Only the lateral motion counts; damping and
/// circulatory terms are left out. Coefficients that depend on speed are evaluated at
/// each critical speed itself (a fixed-point iteration; @p info says when it did not
/// converge), starting from the coefficients at @p start [rad/s] (0: at rest; a
/// speed where the supports carry the rotor when they carry it only while it turns,
/// as oil films do). Throws Error when the lateral stiffness is singular (a rotor not
/// held laterally) or the model couples lateral motion with axial or torsional motion.
/// The lateral stiffness is taken as symmetric (its lower triangle): give bearings
/// with cross-coupling through with_direct_bearing_stiffness().
std::vector<UndampedCritical> undamped_critical_speeds(const Model& model, int n, bool gyroscopic = true,
                                                       SolverInfo* info = nullptr, Real start = 0.0);

/// The bearings of @p model: the connecting elements (Element::connection()) that hold
/// a rotating node to the ground or to a node that does not rotate, in model order —
/// spring–dampers, and in a linearised() model the journal and rolling bearings.
std::vector<Index> bearing_elements(const Model& model);

/// The rotating node that bearing @p element holds; throws Error when it is none.
Index journal_node(const Model& model, Index element);

/// @p model with the lateral stiffness of the bearings @p springs replaced by the
/// isotropic constant @p k [N/m] (cross-coupled terms removed; a spring–damper keeps
/// its other directions and damping, another bearing becomes a spring–damper with
/// that lateral stiffness alone).
Model with_bearing_stiffness(const Model& model, const std::vector<Index>& springs, Real k);

/// @p model with each bearing of @p bearings replaced by its direct stiffness alone
/// (k_yy, k_zz at each speed as the bearing gives it; cross-coupled stiffness and
/// damping left out), as API 684's undamped analyses take bearings.
Model with_direct_bearing_stiffness(const Model& model, const std::vector<Index>& bearings);

struct CriticalSpeedMapOptions {
  std::vector<Index> springs;  ///< the bearings varied; empty: bearing_elements()
  Real k_low = 1e5;            ///< [N/m]
  Real k_high = 1e10;          ///< [N/m]
  int points = 61;             ///< stiffness values, evenly spaced in log k
  int criticals = 4;           ///< forward critical speeds per stiffness
  bool gyroscopic = true;      ///< see undamped_critical_speeds()
  /// The bearings' curves are drawn over [0, curve_stop] [rad/s] (their stiffness
  /// may depend on speed), at curve_points speeds; intersections are sought there.
  Real curve_stop = 0;
  int curve_points = 101;
  int n_threads = 1;  ///< 0: all cores; results do not depend on it
  StopToken stop;
};

/// A bearing's stiffness in one direction against speed.
struct BearingCurve {
  Index element = 0;
  std::string direction;        ///< "y" or "z"
  std::vector<Real> speeds;     ///< [rad/s]
  std::vector<Real> stiffness;  ///< [N/m]
};

/// Where a bearing's curve meets the map's n-th critical speed: every varied bearing
/// at this bearing's stiffness k(Ω), and Ω that stiffness's n-th critical speed.
struct MapIntersection {
  Index element = 0;
  std::string direction;
  int critical = 1;    ///< n (1: the lowest)
  Real speed = 0;      ///< [rad/s]
  Real stiffness = 0;  ///< [N/m]
};

struct CriticalSpeedMapResult {
  std::vector<Index> springs;   ///< the bearings varied
  std::vector<Real> stiffness;  ///< [N/m]
  /// criticals[i][n]: the (n+1)-th forward critical speed at stiffness[i] [rad/s]; NaN
  /// where the rotor has fewer.
  std::vector<std::vector<Real>> criticals;
  std::vector<BearingCurve> curves;
  std::vector<MapIntersection> intersections;
  SolverInfo info;
};

/// The undamped critical speed map of @p model. Throws Error for bad options
/// (k_low ≤ 0, k_high ≤ k_low, fewer than 2 points, an element that is not a
/// bearing, no bearings, no curve_stop when the bearings have stiffness).
CriticalSpeedMapResult run_critical_speed_map(const Model& model, const CriticalSpeedMapOptions& options);

}  // namespace feran

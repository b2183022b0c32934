#pragma once
/// @file
/// Plain cylindrical journal bearings on an oil film: the film force from the
/// journal's position and velocity in its housing, with its Jacobian, and the
/// closed forms of the short bearing at its static equilibrium.
/// Theory: docs/theory/fluid_film_bearings.md.

#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include <feran/core/types.hpp>
#include <feran/forces/finite_bearing.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// Geometry and oil of a plain journal bearing.
struct JournalBearingGeometry {
  Real diameter = 0.0;   ///< journal diameter D [m]
  Real length = 0.0;     ///< axial length L [m]
  Real clearance = 0.0;  ///< radial clearance c [m]
  Real viscosity = 0.0;  ///< dynamic viscosity μ of the oil [Pa s]
};

/// How the Reynolds equation of the film is solved.
enum class FilmTheory {
  /// Ocvirk's short bearing (L/D → 0: the circumferential pressure flow neglected),
  /// with the π-film (half-Sommerfeld, Gümbel) cavitation condition: the film
  /// carries pressure only where the closed-form pressure is positive.
  short_bearing,
  /// The infinitely long bearing (Sommerfeld: L/D → ∞, no axial flow) with Gümbel's
  /// cavitation condition: the full-Sommerfeld pressure, zero at the thickest film,
  /// kept only where positive.
  long_bearing,
  /// The bearing of finite length: the Reynolds equation solved numerically over the
  /// bearing surface (finite_bearing.hpp) with Reynolds' or Gümbel's cavitation
  /// condition. No closed forms: film_load() and the others throw for it.
  finite_length,
};

/// The film's force on the journal in the bearing's lateral plane (y, z) and its
/// Jacobian with respect to the journal's position and velocity relative to the
/// housing.
struct FilmForce {
  Eigen::Vector2d f = Eigen::Vector2d::Zero();     ///< [N]
  Eigen::Matrix2d dfdx = Eigen::Matrix2d::Zero();  ///< ∂f/∂(y, z) [N/m]
  Eigen::Matrix2d dfdv = Eigen::Matrix2d::Zero();  ///< ∂f/∂(ẏ, ż) [N s/m]
  /// The largest film pressure [Pa] where the solution gives the pressure field (the
  /// finite bearing: its largest nodal value); NaN else (the closed forms give it in
  /// operating_data()).
  Real peak_pressure = std::numeric_limits<Real>::quiet_NaN();
};

/// The film force on a journal at @p x = (y, z) from the housing's centre, moving at
/// @p v = (ẏ, ż), spinning at @p speed [rad/s] about +x relative to the housing.
/// Throws Error when |x| is not below the clearance. @p grid: the finite-length
/// bearing's grid, cavitation condition and evaluation (ignored by the closed forms);
/// @p trajectory: evaluated along a trajectory (MotionState::trajectory), where the
/// automatic evaluation takes the table.
FilmForce film_force(const JournalBearingGeometry& g, FilmTheory theory, Real speed, const Eigen::Vector2d& x,
                     const Eigen::Vector2d& v, const FiniteBearingGrid& grid = {}, bool trajectory = false);

/// The steady load W [N] the film carries at eccentricity ratio @p eps, in closed
/// form (docs/theory/fluid_film_bearings.md): with W₀ = μΩDL³/(8c²) for the short
/// bearing, W = W₀·ε·√(π²(1 − ε²) + 16ε²)/(1 − ε²)²; with W₀ = 6μΩR³L/c² for the long
/// one, W = W₀·ε·√(π²(1 − ε²) + 4ε²)/((2 + ε²)(1 − ε²)).
Real film_load(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real eps);
/// The attitude angle φ [rad] between the load line and the journal's displacement:
/// tan φ = π√(1 − ε²)/(4ε) (short), π√(1 − ε²)/(2ε) (long). The journal moves away
/// from the load line in the direction of rotation.
Real film_attitude_angle(FilmTheory theory, Real eps);
/// The eccentricity ratio at which the film carries @p load [N] at @p speed.
Real film_eccentricity(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real load);

/// Linearised stiffness and damping of a bearing: the film force changes by
/// −K·δx − C·δẋ for small δx, δẋ about the equilibrium.
struct BearingCoefficients {
  Eigen::Matrix2d K = Eigen::Matrix2d::Zero();  ///< [N/m]
  Eigen::Matrix2d C = Eigen::Matrix2d::Zero();  ///< [N s/m]
};

/// The eight coefficients in closed form at the equilibrium under @p load [N], in
/// the load frame: the first axis along the load on the journal, the second that
/// axis turned by +90° (towards the direction of rotation).
BearingCoefficients film_coefficients(const JournalBearingGeometry& g, FilmTheory theory, Real speed, Real load);

/// A journal bearing between a journal node and the ground or a housing node: a
/// nonlinear force on v and w of each.
struct FluidFilmBearing {
  Index node_a = 0;             ///< the journal
  std::optional<Index> node_b;  ///< the housing; empty: the ground
  JournalBearingGeometry geometry;
  FilmTheory theory = FilmTheory::short_bearing;
  FiniteBearingGrid grid;  ///< for FilmTheory::finite_length

  std::string_view kind() const { return "fluid_film_bearing"; }
  /// The radial clearance c (ability clearance(), model/force.hpp).
  Real clearance() const { return geometry.clearance; }
  std::vector<Index> nodes() const;
  /// v, w of the journal, then of the housing when there is one.
  std::vector<Index> dofs() const;
  NonlinearForceValue force(const MotionState& s, const Vector& x, const Vector& v) const;
  /// It carries the rotor (the ability of model/force.hpp), only while it turns.
  bool supports() const { return true; }
  bool needs_speed() const { return true; }
  /// The film's friction torque on the journal [N m], resisting its rotation:
  /// 2πμR³LΩ/(c√(1 − ε²)) + ½(e × F)_x (Couette shear over the whole film, and the
  /// pressure's share; docs/theory/fluid_film_bearings.md).
  Real drag_torque(const MotionState& s, const Vector& x, const Vector& v) const;
  /// The film's operating state (docs/theory/fluid_film_bearings.md, "Operating
  /// data"): eccentricity_ratio, attitude_angle_deg (from the load line to the journal's
  /// displacement, positive in the direction of rotation), min_film_thickness_m
  /// c(1 − ε) and min_film_angle_deg (where it is, from +y towards +z),
  /// sommerfeld_number μNLD/W·(R/c)² (N in rev/s, W the film force), load_n,
  /// friction_torque_nm, power_loss_w and peak_pressure_pa (the short bearing's closed
  /// form with the squeeze term; the long bearing's at rest in its housing, else NaN;
  /// NaN for the finite bearing), specific_load_pa W/(L·D), and Trumpler's design
  /// limits specific_load_limit_pa and min_film_limit_m (below).
  std::vector<OperatingValue> operating_data(const MotionState& s, const Vector& x, const Vector& v) const;
};

/// Trumpler's design limits for plain journal bearings (P. R. Trumpler, "Design of
/// Film Bearings", Macmillan 1966; quoted in Hamrock, Schmid & Jacobson, "Fundamentals
/// of Fluid Film Lubrication", 2nd ed. 2004, ch. 10): the unit load W/(L·D) at start
/// and stop at most 300 psi, and the minimum film thickness at least
/// 0.0002 in + 0.00004·D.
inline constexpr Real trumpler_specific_load_limit = 2.0684e6;                      ///< [Pa], 300 psi
inline Real trumpler_min_film(Real diameter) { return 5.08e-6 + 4e-5 * diameter; }  ///< [m]

/// The largest film pressure [Pa] of the short bearing (Ocvirk, π film) at journal
/// position @p x and velocity @p v relative to the housing:
/// p(α, 0) = −3μL²/(2h³)·((Ω/2)·∂h/∂α + ∂h/∂t), the largest over α (sampled, then a
/// parabola through the top three samples).
Real short_bearing_peak_pressure(const JournalBearingGeometry& g, Real speed, const Eigen::Vector2d& x,
                                 const Eigen::Vector2d& v);

}  // namespace feran

#pragma once
/// @file
/// The finite-length plain journal bearing: the Reynolds equation of the film solved
/// by finite differences over the bearing's surface, with a cavitation condition,
/// and the film force with its exact Jacobian (for the cavitated region found).
/// Theory: docs/theory/fluid_film_bearings.md, "The finite-length bearing".

#include <Eigen/Core>

#include <feran/core/types.hpp>

namespace feran {

struct JournalBearingGeometry;
struct FilmForce;

/// Where the film cavitates.
enum class Cavitation {
  /// Reynolds' (Swift–Stieber) condition: p ≥ 0 everywhere and, where the film
  /// ruptures, no pressure gradient normal to the boundary — the linear
  /// complementarity problem of the discrete Reynolds equation, solved exactly by a
  /// primal–dual active-set method.
  reynolds,
  /// Gümbel's (half-Sommerfeld) condition: the uncavitated pressure, kept only where
  /// it is positive (the condition of the short and long bearings' closed forms).
  gumbel,
};

/// How an analysis evaluates the finite bearing's film force.
enum class FilmEvaluation {
  /// The table along trajectories (run-ups: MotionState::trajectory), where it pays
  /// for itself; the solver elsewhere (the equilibrium and its linearisation, a few
  /// evaluations per speed).
  automatic,
  /// From the bearing shape's table of the solver's solutions
  /// (finite_bearing_table.hpp), built once on first use: about 1 µs an evaluation.
  /// The solver is called instead beyond the table's eccentricity, and for the whole
  /// bearing should the table's measured error exceed its bound.
  table,
  /// The solver at every evaluation (about 0.3 ms on the default grid).
  exact,
};

/// The finite-difference grid over one half of the bearing (the film is symmetric
/// about its mid-plane), the cavitation condition and the evaluation.
struct FiniteBearingGrid {
  int circumferential = 72;  ///< cells around the circumference
  int axial = 8;             ///< cells from the mid-plane to one end
  Cavitation cavitation = Cavitation::reynolds;
  FilmEvaluation evaluation = FilmEvaluation::automatic;
};

/// The film force on the journal at @p x = (y, z) moving at @p v, spinning at
/// @p speed [rad/s], from the discrete Reynolds equation on @p grid; the Jacobian is
/// that of the discrete force with the cavitated region held. Expects |x| below the
/// clearance (film_force() checks it). Always the solver (@p grid's evaluation is
/// film_force()'s business).
FilmForce finite_bearing_force(const JournalBearingGeometry& g, const FiniteBearingGrid& grid, Real speed,
                               Eigen::Vector2d x, const Eigen::Vector2d& v);

}  // namespace feran

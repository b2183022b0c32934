#pragma once
/// @file
/// A harmonic force or moment at a node.

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// In a speed sweep it acts at the rotor speed (synchronous); in a frequency sweep at
/// the swept frequency; in a run-up at the rotation angle φ (as a synchronous force).
/// A fixed force with a frequency of its own acts at that frequency, in run-ups only:
/// F(t) = A·cos(ωt + phase), whatever the rotor's speed. A fixed force with a time
/// table acts in run-ups only, with the table's value at t.
struct HarmonicForce {
  enum class Kind {
    fixed,           ///< along a fixed DOF direction: F(t) = A·cos(ωt + phase)
    rotating_force,  ///< lateral force rotating with the shaft: F_y + i·F_z = A·e^{i(Ωt + phase)}
    rotating_moment  ///< lateral moment rotating with the shaft: M_y + i·M_z = A·e^{i(Ωt + phase)}
  };
  Index node = 0;
  Kind type = Kind::fixed;
  Dof direction = Dof::v;  ///< for Kind::fixed
  Real amplitude = 0.0;    ///< [N] or [N m]
  Real phase = 0.0;        ///< [rad]
  /// ω [rad/s] of a fixed force acting at its own frequency (run-ups only); empty:
  /// synchronous or swept.
  std::optional<Real> frequency;
  /// (t [s], value [N or N m]) of a fixed force given in time (run-ups only): linear
  /// between the points, held beyond the first and the last; empty: harmonic.
  std::vector<std::pair<Real, Real>> time_table;

  std::string_view kind() const { return "harmonic_force"; }
  std::vector<Index> nodes() const { return {node}; }
  /// A frequency of its own or a time table: it acts in run-ups only.
  bool own_time_law() const { return frequency.has_value() || !time_table.empty(); }
  void add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const;
  void add_transient(const MotionState& s, Vector& f) const;
};

}  // namespace feran

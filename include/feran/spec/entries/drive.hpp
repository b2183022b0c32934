#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/drive.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/model/speed_coefficient.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [drive]: the motor and load torques of torque-driven run-ups; no motor: none.
struct DriveSpec {
  std::string motor;                       ///< "dc", "induction" or "table"; empty: no drive
  Real inertia = 0.0;                      ///< [kg m²]
  std::optional<Real> stall_torque;        ///< [N m] (dc)
  std::optional<Real> no_load_speed;       ///< [rad/s] (dc)
  std::optional<Real> synchronous_speed;   ///< [rad/s] (induction)
  std::optional<Real> breakdown_torque;    ///< [N m] (induction)
  std::optional<Real> breakdown_slip;      ///< (induction)
  std::optional<SpeedCoefficient> torque;  ///< a table over speed [N m] (table)
  Real friction_torque = 0.0;              ///< [N m]
  Real viscous_torque = 0.0;               ///< [N m s/rad]
  Real quadratic_torque = 0.0;             ///< [N m s²/rad²]
  bool operator==(const DriveSpec&) const = default;
};

}  // namespace feran

#pragma once
/// @file
/// Viscous damper acting between rotating parts (paper eq. 10).

#include <optional>
#include <string_view>

#include <feran/core/types.hpp>
#include <feran/model/element.hpp>

namespace feran {

/// Coefficients of a rotating damper.
struct RotatingDamperCoefficients {
  Real translational = 0.0;  ///< c_it, lateral [N s/m]
  Real rotational = 0.0;     ///< c_ir, tilt [N m s/rad]
  Real axial = 0.0;          ///< along x [N s/m]
  Real torsional = 0.0;      ///< about x [N m s/rad]
};

/// A damper whose force opposes the relative velocity seen in the frame rotating
/// with the shaft. Between @p node_a and @p node_b, or between node_a and the
/// rotating frame's axis (e.g. the clamped end of a shaft) when node_b is empty.
/// In inertial coordinates it adds C_i = c and the skew circulatory stiffness
/// Ω·K_i (docs/theory/rotating_damper.md).
class RotatingDamper {
 public:
  RotatingDamper(Index node_a, std::optional<Index> node_b, RotatingDamperCoefficients c);

  LocalMatrices local_matrices(const OperatingPoint& op) const;
  std::string_view kind() const { return "rotating_damper"; }
  bool speed_dependent() const { return false; }

  Index node_a() const { return node_a_; }
  const std::optional<Index>& node_b() const { return node_b_; }
  const RotatingDamperCoefficients& coefficients() const { return c_; }

 private:
  Index node_a_;
  std::optional<Index> node_b_;
  RotatingDamperCoefficients c_;
};

}  // namespace feran

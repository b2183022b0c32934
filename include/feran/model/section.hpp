#pragma once
/// @file
/// Circular cross-sections of shafts.

#include <feran/core/types.hpp>

namespace feran {

/// Solid or hollow circular section.
struct CircularSection {
  Real outer_diameter = 0.0;  ///< [m]
  Real inner_diameter = 0.0;  ///< [m], 0 for a solid section

  Real area() const;           ///< A [m²]
  Real second_moment() const;  ///< I about a diameter [m⁴]
  Real polar_moment() const;   ///< I_p = J = 2I [m⁴]
  /// Cowper's (1966) shear coefficient κ for a hollow circle with Poisson ratio @p nu.
  Real cowper_shear_coefficient(Real nu) const;
  /// Hutchinson's (2001) shear coefficient κ for a hollow circle with Poisson ratio
  /// @p nu: 6(a² + b²)²(1 + ν)² / [7a⁴ + 34a²b² + 7b⁴ + ν(12a⁴ + 48a²b² + 12b⁴)
  /// + ν²(4a⁴ + 16a²b² + 4b⁴)], a and b the outer and inner radii.
  Real hutchinson_shear_coefficient(Real nu) const;
  bool operator==(const CircularSection&) const = default;
};

}  // namespace feran

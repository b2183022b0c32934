#pragma once
/// @file
/// The elliptic orbit traced by a pair of harmonic quantities.

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// Orbit of y(t) = Re(Y·e^{iωt}), z(t) = Re(Z·e^{iωt}), ω > 0, in the y–z plane.
struct Orbit {
  Real major = 0;        ///< largest |(y, z)| over a period (semi-axis)
  Real minor = 0;        ///< smallest |(y, z)| over a period (semi-axis)
  Real inclination = 0;  ///< angle of the major axis from +y towards +z [rad], in (−π/2, π/2]
  Real forward = 0;      ///< radius of the forward circular component |Y + iZ|/2
  Real backward = 0;     ///< radius of the backward circular component |Y − iZ|/2
  /// forward (turning from +y to +z, with the spin), backward, or planar (a line).
  Whirl whirl = Whirl::planar;
};

/// The orbit of the complex amplitudes @p y and @p z.
Orbit orbit(Complex y, Complex z);

}  // namespace feran

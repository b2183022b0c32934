#include <feran/analyses/common/orbit.hpp>

#include <cmath>

namespace feran {

Orbit orbit(Complex y, Complex z) {
  // y + i·z = a·e^{iωt} + b·e^{−iωt}, a = (Y + iZ)/2, b = (conj Y + i·conj Z)/2.
  const Complex i(0, 1);
  const Complex a = (y + i * z) / 2.0;
  const Complex b = (std::conj(y) + i * std::conj(z)) / 2.0;
  Orbit o;
  o.forward = std::abs(a);
  o.backward = std::abs(b);
  o.major = o.forward + o.backward;
  o.minor = std::abs(o.forward - o.backward);
  // |y + iz| is largest when both phasors point the same way.
  Real angle = 0.5 * (std::arg(a) + std::arg(b));
  if (angle <= -pi / 2) angle += pi;
  if (angle > pi / 2) angle -= pi;
  o.inclination = angle;
  // Equal radii to 1e-9 relative: a straight line (round-off level is ~1e-15).
  const Real tol = 1e-9 * o.major;
  o.whirl = o.forward > o.backward + tol   ? Whirl::forward
            : o.backward > o.forward + tol ? Whirl::backward
                                           : Whirl::planar;
  return o;
}

}  // namespace feran

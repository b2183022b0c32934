#include <feran/forces/harmonic_force.hpp>

#include <complex>

namespace feran {

void HarmonicForce::add_harmonic(const HarmonicExcitation&, ComplexVector& f) const {
  if (frequency) return;  // its own frequency: not a steady state of the sweep's
  const Complex I(0.0, 1.0);
  const Complex a = amplitude * std::polar(1.0, phase);
  switch (type) {
    case Kind::fixed: f(global_dof(node, direction)) += a; break;
    case Kind::rotating_force:
      f(global_dof(node, Dof::v)) += a;
      f(global_dof(node, Dof::w)) += -I * a;
      break;
    case Kind::rotating_moment:
      f(global_dof(node, Dof::ry)) += a;
      f(global_dof(node, Dof::rz)) += -I * a;
      break;
  }
}

void HarmonicForce::add_transient(const MotionState& s, Vector& f) const {
  const Complex a = amplitude * std::polar(1.0, (frequency ? *frequency * s.t : s.angle) + phase);
  switch (type) {
    case Kind::fixed: f(global_dof(node, direction)) += a.real(); break;
    case Kind::rotating_force:
      f(global_dof(node, Dof::v)) += a.real();
      f(global_dof(node, Dof::w)) += a.imag();
      break;
    case Kind::rotating_moment:
      f(global_dof(node, Dof::ry)) += a.real();
      f(global_dof(node, Dof::rz)) += a.imag();
      break;
  }
}

}  // namespace feran

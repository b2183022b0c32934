#include <feran/forces/unbalance.hpp>

#include <complex>

namespace feran {

void Unbalance::add_harmonic(const HarmonicExcitation& e, ComplexVector& f) const {
  if (!e.synchronous || !e.unbalance) return;
  // F_y + i·F_z = m r Ω² e^{i(Ωt + φ)}: F_y = m r Ω² e^{iφ}, F_z = −i·m r Ω² e^{iφ}
  // as amplitudes of Re(·e^{iΩt}); the lever l adds M_y = −l·F_z, M_z = l·F_y.
  const Complex I(0.0, 1.0);
  const Complex fy = mass * radius * e.speed * e.speed * std::polar(1.0, phase);
  const Complex fz = -I * fy;
  f(global_dof(node, Dof::v)) += fy;
  f(global_dof(node, Dof::w)) += fz;
  f(global_dof(node, Dof::ry)) += -lever * fz;
  f(global_dof(node, Dof::rz)) += lever * fy;
}

void Unbalance::add_transient(const MotionState& s, Vector& f) const {
  // F_y + j·F_z = m r (Ω² − jΩ') e^{j(φ + phase)}
  const Complex F = mass * radius * Complex(s.speed * s.speed, -s.acceleration) * std::polar(1.0, s.angle + phase);
  f(global_dof(node, Dof::v)) += F.real();
  f(global_dof(node, Dof::w)) += F.imag();
  f(global_dof(node, Dof::ry)) += -lever * F.imag();
  f(global_dof(node, Dof::rz)) += lever * F.real();
}

}  // namespace feran

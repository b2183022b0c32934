#include <feran/forces/harmonic_force.hpp>

#include <algorithm>
#include <complex>

namespace feran {

void HarmonicForce::add_harmonic(const HarmonicExcitation&, ComplexVector& f) const {
  if (own_time_law()) return;  // not a steady state of the sweep's
  const Complex I(0.0, 1.0);
  const Complex a = amplitude * std::polar(1.0, phase);
  switch (type) {
    case Kind::fixed:
      f(global_dof(node, direction)) += a;
      break;
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
  if (!time_table.empty()) {
    const auto after = std::upper_bound(time_table.begin(), time_table.end(), s.t,
                                        [](Real t, const std::pair<Real, Real>& p) { return t < p.first; });
    Real value = 0.0;
    if (after == time_table.begin())
      value = time_table.front().second;
    else if (after == time_table.end())
      value = time_table.back().second;
    else {
      const auto& [t0, v0] = *(after - 1);
      const auto& [t1, v1] = *after;
      value = v0 + (v1 - v0) * (s.t - t0) / (t1 - t0);
    }
    f(global_dof(node, direction)) += value;
    return;
  }
  const Complex a = amplitude * std::polar(1.0, (frequency ? *frequency * s.t : s.angle) + phase);
  switch (type) {
    case Kind::fixed:
      f(global_dof(node, direction)) += a.real();
      break;
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

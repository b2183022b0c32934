#include <feran/integrators/integrator.hpp>

#include <fmt/format.h>

namespace feran::detail {

StepReport initial_acceleration(std::string_view method, SecondOrderSystem& sys, State& s, Vector& r) {
  StepReport report;
  const Index n = sys.size();
  if (s.x.size() != n || s.v.size() != n) {
    report.ok = false;
    report.message = fmt::format("{}: state has {} displacements and {} velocities, the system {} unknowns", method,
                                 s.x.size(), s.v.size(), n);
    return report;
  }
  r.resize(n);
  sys.rhs(s.t, s.x, s.v, r);
  s.a.resize(n);
  sys.solve_mass(r, s.a);
  return report;
}

}  // namespace feran::detail

namespace feran {

void interpolate(const State& a, const State& b, Real t, Vector& x, Vector& v) {
  const Real h = b.t - a.t, s = (t - a.t) / h;
  const Real h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const Real h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  const Real d00 = 6 * s * s - 6 * s, d10 = 3 * s * s - 4 * s + 1, d01 = -6 * s * s + 6 * s, d11 = 3 * s * s - 2 * s;
  x = h00 * a.x + (h10 * h) * a.v + h01 * b.x + (h11 * h) * b.v;
  v = (d00 / h) * a.x + d10 * a.v + (d01 / h) * b.x + d11 * b.v;
}

}  // namespace feran

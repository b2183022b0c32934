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

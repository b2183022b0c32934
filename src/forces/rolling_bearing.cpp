#include <feran/forces/rolling_bearing.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lateral_pair.hpp"

namespace feran {

Real RollingBearingGeometry::cage_ratio() const {
  return 0.5 * (1.0 - element_diameter / pitch_diameter * std::cos(contact_angle));
}

Real element_angle(const RollingBearingGeometry& g, int j, Real shaft_angle) {
  return g.cage_ratio() * shaft_angle + 2.0 * pi * j / g.elements;
}

std::vector<Real> element_loads(const RollingBearingGeometry& g, const Eigen::Vector2d& x, Real shaft_angle) {
  std::vector<Real> q(static_cast<std::size_t>(g.elements), 0.0);
  const Real ca = std::cos(g.contact_angle);
  for (int j = 0; j < g.elements; ++j) {
    const Real th = element_angle(g, j, shaft_angle);
    const Real delta = (x(0) * std::cos(th) + x(1) * std::sin(th)) * ca - g.clearance;
    if (delta > 0) q[static_cast<std::size_t>(j)] = g.hertz_constant * std::pow(delta, g.exponent());
  }
  return q;
}

std::vector<Index> RollingBearing::nodes() const { return detail::lateral_nodes(node_a, node_b); }

std::vector<Index> RollingBearing::dofs() const { return detail::lateral_dofs(node_a, node_b); }

NonlinearForceValue RollingBearing::force(const MotionState& s, const Vector& x, const Vector& /*v*/) const {
  const Eigen::Vector2d dx = detail::relative(x, node_b.has_value());
  const RollingBearingGeometry& g = geometry;
  const Real ca = std::cos(g.contact_angle), p = g.exponent();
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int j = 0; j < g.elements; ++j) {
    const Real th = element_angle(g, j, s.angle);
    const Eigen::Vector2d e(std::cos(th), std::sin(th));
    const Real delta = dx.dot(e) * ca - g.clearance;
    if (!(delta > 0)) continue;
    const Real q = g.hertz_constant * std::pow(delta, p);
    f -= q * ca * e;
    J -= p * q / delta * ca * ca * e * e.transpose();
  }
  return detail::pair_force(f, J, Eigen::Matrix2d::Zero(), node_b.has_value());
}

std::vector<OperatingValue> RollingBearing::operating_data(const MotionState& s, const Vector& x, const Vector&) const {
  const std::vector<Real> Q = element_loads(geometry, detail::relative(x, node_b.has_value()), s.angle);
  Real q_max = 0;
  int loaded = 0;
  for (const Real q : Q) {
    q_max = std::max(q_max, q);
    loaded += q > 0 ? 1 : 0;
  }
  Real stress = std::numeric_limits<Real>::quiet_NaN();
  if (!geometry.roller) {
    // Sphere on a plane, both steel: E* = E/(2(1 − ν²)); K = (4/3)E*√R gives R, then
    // a = (3QR/(4E*))^(1/3) and p_max = 3Q/(2πa²) (Johnson, Contact Mechanics, §4.2).
    const Real E_star = 210e9 / (2 * (1 - 0.3 * 0.3));
    const Real radius = std::pow(3 * geometry.hertz_constant / (4 * E_star), 2);
    const Real a = std::cbrt(3 * q_max * radius / (4 * E_star));
    stress = q_max > 0 ? 3 * q_max / (2 * pi * a * a) : 0.0;
  }
  // ISO 76's static load rating is the load giving 4200 MPa at the most loaded ball's
  // contact (4000 MPa for rollers): beyond it the raceways dent permanently.
  return {{"max_element_load_n", q_max},
          {"loaded_elements", static_cast<Real>(loaded)},
          {"max_contact_stress_pa", stress},
          {"contact_stress_limit_pa", geometry.roller ? std::numeric_limits<Real>::quiet_NaN() : 4.2e9}};
}

}  // namespace feran

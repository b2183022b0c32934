#include <feran/forces/rolling_bearing.hpp>

#include <cmath>

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

}  // namespace feran

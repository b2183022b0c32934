#include <feran/model/section.hpp>

#include <cmath>

namespace feran {

Real CircularSection::area() const {
  return pi / 4.0 * (outer_diameter * outer_diameter - inner_diameter * inner_diameter);
}

Real CircularSection::second_moment() const {
  return pi / 64.0 * (std::pow(outer_diameter, 4) - std::pow(inner_diameter, 4));
}

Real CircularSection::polar_moment() const { return 2.0 * second_moment(); }

Real CircularSection::cowper_shear_coefficient(Real nu) const {
  const Real m = inner_diameter / outer_diameter;
  const Real m2 = m * m;
  const Real a = (1.0 + m2) * (1.0 + m2);
  return 6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2);
}

}  // namespace feran

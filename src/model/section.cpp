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

Real CircularSection::hutchinson_shear_coefficient(Real nu) const {
  const Real a2 = outer_diameter * outer_diameter / 4.0, b2 = inner_diameter * inner_diameter / 4.0;
  const Real a4 = a2 * a2, b4 = b2 * b2, ab = a2 * b2;
  const Real s = a2 + b2;
  return 6.0 * s * s * (1.0 + nu) * (1.0 + nu) /
         (7.0 * a4 + 34.0 * ab + 7.0 * b4 + nu * (12.0 * a4 + 48.0 * ab + 12.0 * b4) +
          nu * nu * (4.0 * a4 + 16.0 * ab + 4.0 * b4));
}

}  // namespace feran

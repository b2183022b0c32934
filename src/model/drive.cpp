#include <feran/model/drive.hpp>

#include <algorithm>
#include <cmath>

namespace feran {

namespace {
constexpr Real sign_smoothing = 1e-3;  // Ω_ε [rad/s]
}

Real MotorLaw::torque(Real speed) const {
  switch (kind) {
    case Kind::dc:
      return stall_torque * (1.0 - speed / no_load_speed);
    case Kind::induction: {
      const Real s = (synchronous_speed - speed) / synchronous_speed;
      // T = 2T_b·s·s_b/(s² + s_b²): 0 at synchronous speed, odd in s (braking above it).
      return 2.0 * breakdown_torque * s * breakdown_slip / (s * s + breakdown_slip * breakdown_slip);
    }
    case Kind::table: {
      if (speed <= table.front().first) return table.front().second;
      if (speed >= table.back().first) return table.back().second;
      const auto after = std::upper_bound(table.begin(), table.end(), speed,
                                          [](Real w, const std::pair<Real, Real>& p) { return w < p.first; });
      const auto& [w0, t0] = *(after - 1);
      const auto& [w1, t1] = *after;
      return t0 + (t1 - t0) * (speed - w0) / (w1 - w0);
    }
  }
  return 0.0;
}

Real MotorLaw::slope(Real speed) const {
  switch (kind) {
    case Kind::dc:
      return -stall_torque / no_load_speed;
    case Kind::induction: {
      const Real s = (synchronous_speed - speed) / synchronous_speed, b = breakdown_slip;
      const Real d = s * s + b * b;
      // dT/ds = 2T_b·b(b² − s²)/d², ds/dΩ = −1/Ω_s.
      return -2.0 * breakdown_torque * b * (b * b - s * s) / (d * d) / synchronous_speed;
    }
    case Kind::table: {
      if (speed <= table.front().first || speed >= table.back().first) return 0.0;
      const auto after = std::upper_bound(table.begin(), table.end(), speed,
                                          [](Real w, const std::pair<Real, Real>& p) { return w < p.first; });
      return (after->second - (after - 1)->second) / (after->first - (after - 1)->first);
    }
  }
  return 0.0;
}

Real MotorLaw::free_speed() const {
  switch (kind) {
    case Kind::dc:
      return no_load_speed;
    case Kind::induction:
      return synchronous_speed;
    case Kind::table:
      for (std::size_t i = 1; i < table.size(); ++i) {
        const auto& [w0, t0] = table[i - 1];
        const auto& [w1, t1] = table[i];
        if (t0 > 0 && t1 <= 0) return w0 + (w1 - w0) * t0 / (t0 - t1);
      }
      return table.back().first;
  }
  return 0.0;
}

Real Drive::net_torque(Real speed) const {
  const Real sigma = speed / std::sqrt(speed * speed + sign_smoothing * sign_smoothing);
  return motor.torque(speed) - friction_torque * sigma - viscous_torque * speed -
         quadratic_torque * speed * std::abs(speed);
}

Real Drive::net_slope(Real speed) const {
  const Real e2 = sign_smoothing * sign_smoothing;
  const Real dsigma = e2 / std::pow(speed * speed + e2, 1.5);
  return motor.slope(speed) - friction_torque * dsigma - viscous_torque - 2.0 * quadratic_torque * std::abs(speed);
}

}  // namespace feran

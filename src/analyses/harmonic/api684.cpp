#include <feran/analyses/harmonic/api684.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// The speed where the curve crosses @p level between points k and k + 1.
Real crossing(std::span<const Real> s, std::span<const Real> a, std::size_t k, Real level) {
  return s[k] + (level - a[k]) / (a[k + 1] - a[k]) * (s[k + 1] - s[k]);
}

}  // namespace

std::vector<ResponsePeak> response_peaks(std::span<const Real> speeds, std::span<const Real> amplitude) {
  if (speeds.size() != amplitude.size())
    throw Error(fmt::format("{} speeds but {} amplitudes", speeds.size(), amplitude.size()));
  for (std::size_t k = 1; k < speeds.size(); ++k)
    if (!(speeds[k] > speeds[k - 1])) throw Error("the speeds of a response curve must increase");
  const auto& s = speeds;
  const auto& a = amplitude;
  const std::size_t n = s.size();
  std::vector<ResponsePeak> peaks;
  for (std::size_t k = 0; k < n; ++k) {
    // The first point is a peak when the curve falls from it, the last when it rose
    // to it; neither has a half-power point beyond the sweep.
    const bool peak = k == 0 ? n > 1 && a[0] > a[1] : a[k] > a[k - 1] && (k + 1 == n || a[k] >= a[k + 1]);
    if (!peak) continue;
    ResponsePeak p;
    p.speed = s[k];
    p.amplitude = a[k];
    if (k > 0 && k + 1 < n && a[k] > a[k + 1]) {
      // The parabola through the three points: its top (a Lagrange form, for
      // unevenly spaced speeds).
      const Real x0 = s[k - 1] - s[k], x2 = s[k + 1] - s[k];
      const Real d0 = a[k - 1] - a[k], d2 = a[k + 1] - a[k];
      const Real c2 = (d0 / x0 - d2 / x2) / (x0 - x2);  // the quadratic coefficient (< 0 here)
      const Real c1 = d0 / x0 - c2 * x0;
      if (c2 < 0) {
        const Real x = std::clamp(-c1 / (2 * c2), x0, x2);
        p.speed = s[k] + x;
        p.amplitude = a[k] + c1 * x + c2 * x * x;
      }
    }
    const Real level = p.amplitude / std::sqrt(Real(2));
    for (std::size_t j = k; j-- > 0;) {
      if (a[j] > p.amplitude) break;  // a higher point first: no half-power point on this side
      if (a[j] <= level) {
        p.lower_half_power = crossing(s, a, j, level);
        break;
      }
    }
    for (std::size_t j = k + 1; j < n; ++j) {
      if (a[j] > p.amplitude) break;
      if (a[j] <= level) {
        p.upper_half_power = crossing(s, a, j - 1, level);
        break;
      }
    }
    p.amplification_factor =
        p.resolved() ? p.speed / (*p.upper_half_power - *p.lower_half_power) : std::numeric_limits<Real>::quiet_NaN();
    peaks.push_back(p);
  }
  return peaks;
}

Real required_separation_margin(Real af, Real critical, Real low, Real high) {
  if (!(af >= 2.5)) return 0;
  const Real base = 0.17 * (1 - 1 / (af - 1.5));
  const bool above = critical > high || (critical >= low && critical - low > high - critical);
  return above ? std::min(0.26, 0.10 + base) : std::min(0.16, base);
}

Real separation_margin(Real critical, Real low, Real high) {
  if (critical < low) return (low - critical) / low;
  if (critical > high) return (critical - high) / high;
  return -std::min((critical - low) / low, (high - critical) / high);
}

std::vector<SeparationCheck> separation_checks(std::span<const Real> speeds, std::span<const Real> amplitude, Real low,
                                               Real high) {
  std::vector<SeparationCheck> out;
  for (const ResponsePeak& p : response_peaks(speeds, amplitude)) {
    SeparationCheck c;
    c.peak = p;
    c.actual_margin = separation_margin(p.speed, low, high);
    if (p.resolved()) {
      c.required_margin = required_separation_margin(p.amplification_factor, p.speed, low, high);
      c.passes = c.actual_margin >= c.required_margin;
    }
    out.push_back(c);
  }
  return out;
}

std::vector<SeparationCheck> separation_checks(const HarmonicResult& response, std::size_t probe, Real low, Real high) {
  std::vector<Real> amplitude;
  for (const Orbit& o : response.probes.at(probe).orbit) amplitude.push_back(o.major);
  const std::vector<Real>& at = response.speeds;
  std::vector<SeparationCheck> checks =
      separation_checks(std::span<const Real>(at.data(), amplitude.size()), amplitude, low, high);
  if (response.stability.empty()) return checks;
  for (SeparationCheck& check : checks) {
    const auto k = static_cast<std::size_t>(std::lower_bound(at.begin(), at.end(), check.peak.speed) - at.begin());
    if ((k < response.stability.size() && response.stability[k].unstable) ||
        (k > 0 && k - 1 < response.stability.size() && response.stability[k - 1].unstable)) {
      check.unstable = true;
      check.passes = false;
    }
  }
  return checks;
}

}  // namespace feran

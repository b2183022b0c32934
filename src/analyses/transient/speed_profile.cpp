#include <feran/analyses/transient/speed_profile.hpp>

#include <algorithm>

#include <feran/core/error.hpp>

namespace feran {

SpeedProfile::SpeedProfile(std::vector<std::pair<Real, Real>> points) : points_(std::move(points)) {
  if (points_.empty()) throw Error("a speed profile needs at least one point");
  for (std::size_t i = 1; i < points_.size(); ++i)
    if (!(points_[i].first > points_[i - 1].first)) throw Error("speed profile times must increase");
  angle_at_.resize(points_.size());
  // φ(t_0) counts the constant speed held from t = 0 to the first point.
  angle_at_[0] = points_[0].second * points_[0].first;
  for (std::size_t i = 1; i < points_.size(); ++i)
    angle_at_[i] = angle_at_[i - 1] +
                   0.5 * (points_[i - 1].second + points_[i].second) * (points_[i].first - points_[i - 1].first);
}

namespace {
// Index i of the segment [t_i, t_{i+1}) holding t, or -1 before the first point.
std::ptrdiff_t segment(const std::vector<std::pair<Real, Real>>& p, Real t) {
  const auto it = std::upper_bound(p.begin(), p.end(), t, [](Real x, const auto& q) { return x < q.first; });
  return (it - p.begin()) - 1;
}
}  // namespace

Real SpeedProfile::speed(Real t) const {
  const std::ptrdiff_t i = segment(points_, t);
  if (i < 0) return points_.front().second;
  const auto k = static_cast<std::size_t>(i);
  if (k + 1 >= points_.size()) return points_.back().second;
  const auto& [t0, w0] = points_[k];
  const auto& [t1, w1] = points_[k + 1];
  return w0 + (w1 - w0) * (t - t0) / (t1 - t0);
}

Real SpeedProfile::acceleration(Real t) const {
  const std::ptrdiff_t i = segment(points_, t);
  if (i < 0) return 0.0;
  const auto k = static_cast<std::size_t>(i);
  if (k + 1 >= points_.size()) return 0.0;
  return (points_[k + 1].second - points_[k].second) / (points_[k + 1].first - points_[k].first);
}

Real SpeedProfile::angle(Real t) const {
  const std::ptrdiff_t i = segment(points_, t);
  if (i < 0) return points_.front().second * t;
  const auto k = static_cast<std::size_t>(i);
  const Real dt = t - points_[k].first;
  return angle_at_[k] + 0.5 * (points_[k].second + speed(t)) * dt;
}

}  // namespace feran

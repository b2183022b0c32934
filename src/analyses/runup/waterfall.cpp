#include <feran/analyses/runup/waterfall.hpp>

#include <algorithm>
#include <cmath>
#include <complex>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <feran/core/error.hpp>

namespace feran {

Waterfall waterfall(const TransientResult& result, std::size_t probe, Dof dof, std::optional<Real> window,
                    Real overlap) {
  const std::vector<TransientSample>& s = result.samples;
  if (s.size() < 8) throw Error(fmt::format("a waterfall needs at least 8 samples of the run-up, it has {}", s.size()));
  if (probe >= s.front().probes.size())
    throw Error(fmt::format("probe {} of a run-up with {} probes (counted from 0)", probe, s.front().probes.size()));
  if (!(overlap >= 0.0 && overlap < 1.0))
    throw Error(fmt::format("a waterfall's overlap must be in [0, 1), got {}", overlap));
  if (window && !(*window > 0.0)) throw Error(fmt::format("a waterfall's window must be positive, got {} s", *window));
  std::vector<Real> intervals(s.size() - 1);
  for (std::size_t k = 0; k + 1 < s.size(); ++k) intervals[k] = s[k + 1].t - s[k].t;
  std::nth_element(intervals.begin(), intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2),
                   intervals.end());
  Waterfall w;
  w.sample_interval = intervals[intervals.size() / 2];
  if (!(w.sample_interval > 0.0))
    throw Error("a waterfall needs samples at increasing times: the median interval between them is not positive");
  const Real length = window.value_or((s.back().t - s.front().t) / 20.0);
  const auto total = static_cast<Index>(s.size());
  w.window_samples = std::clamp<Index>(std::llround(length / w.sample_interval), 8, total);
  const Index n = w.window_samples;
  const Index hop = std::max<Index>(1, static_cast<Index>(static_cast<Real>(n) * (1.0 - overlap)));
  Vector taper(n);
  for (Index j = 0; j < n; ++j)
    taper(j) = 0.5 - 0.5 * std::cos(2.0 * pi * static_cast<Real>(j) / static_cast<Real>(n - 1));
  const Real scale = 2.0 / taper.sum();
  const Index bins = n / 2 + 1;
  for (Index k = 0; k < bins; ++k)
    w.frequencies.push_back(static_cast<Real>(k) / (static_cast<Real>(n) * w.sample_interval));
  const auto d = static_cast<std::size_t>(dof);
  Eigen::FFT<Real> fft;
  fft.SetFlag(Eigen::FFT<Real>::HalfSpectrum);
  std::vector<Real> segment(static_cast<std::size_t>(n));
  std::vector<Complex> spectrum;
  std::vector<Vector> rows;
  for (Index start = 0; start + n <= total; start += hop) {
    Real mean = 0.0;
    for (Index j = 0; j < n; ++j) mean += s[static_cast<std::size_t>(start + j)].probes[probe][d];
    mean /= static_cast<Real>(n);
    for (Index j = 0; j < n; ++j)
      segment[static_cast<std::size_t>(j)] =
          (s[static_cast<std::size_t>(start + j)].probes[probe][d] - mean) * taper(j);
    fft.fwd(spectrum, segment);
    Vector row(bins);
    for (Index k = 0; k < bins; ++k) row(k) = scale * std::abs(spectrum[static_cast<std::size_t>(k)]);
    rows.push_back(std::move(row));
    w.speeds.push_back(s[static_cast<std::size_t>(start + n / 2)].speed);
  }
  w.amplitude.resize(static_cast<Index>(rows.size()), bins);
  for (std::size_t r = 0; r < rows.size(); ++r) w.amplitude.row(static_cast<Index>(r)) = rows[r].transpose();
  return w;
}

}  // namespace feran

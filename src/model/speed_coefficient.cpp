#include <feran/model/speed_coefficient.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include <feran/core/error.hpp>

namespace feran {

namespace {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// Where x lies in the strictly increasing @p grid: the interval i (grid[i], grid[i+1])
// and the weight s of grid[i+1], held at the ends (s = 0 or 1).
std::pair<std::size_t, Real> locate(const std::vector<Real>& grid, Real x) {
  if (grid.size() < 2 || x <= grid.front()) return {0, 0.0};
  if (x >= grid.back()) return {grid.size() - 2, 1.0};
  const auto it = std::upper_bound(grid.begin(), grid.end(), x);
  const auto i = static_cast<std::size_t>(it - grid.begin()) - 1;
  return {i, (x - grid[i]) / (grid[i + 1] - grid[i])};
}

Real bilinear(const SpeedCoefficient::FrequencyTable& t, Real speed, Real frequency) {
  const std::size_t nf = t.frequencies.size();
  const std::size_t ns = t.speeds.empty() ? 1 : t.speeds.size();
  if (nf == 0 || t.values.size() != ns * nf)
    throw Error("a frequency table needs one value per speed and frequency, and at least one frequency");
  const std::pair<std::size_t, Real> at_frequency = locate(t.frequencies, std::abs(frequency));
  const std::size_t j = at_frequency.first;
  const Real sf = at_frequency.second;
  const auto row = [&](std::size_t i) {
    const Real* v = t.values.data() + i * nf;
    return nf == 1 ? v[0] : (1.0 - sf) * v[j] + sf * v[j + 1];
  };
  if (ns == 1) return row(0);
  const auto [i, ss] = locate(t.speeds, speed);
  return (1.0 - ss) * row(i) + ss * row(i + 1);
}
}  // namespace

Real SpeedCoefficient::at(Real speed, Real frequency) const {
  return std::visit(Overloaded{
                        [](const Constant& c) { return c.value; },
                        [speed](const Table& t) {
                          if (t.speeds.empty() || t.speeds.size() != t.values.size())
                            throw Error("a speed table needs as many values as speeds, and at least one");
                          if (t.speeds.size() == 1 || speed <= t.speeds.front()) return t.values.front();
                          if (speed >= t.speeds.back()) return t.values.back();
                          const auto it = std::upper_bound(t.speeds.begin(), t.speeds.end(), speed);
                          const auto i = static_cast<std::size_t>(it - t.speeds.begin());
                          const Real s = (speed - t.speeds[i - 1]) / (t.speeds[i] - t.speeds[i - 1]);
                          return (1.0 - s) * t.values[i - 1] + s * t.values[i];
                        },
                        [speed](const Step& s) { return speed < s.at ? s.below : s.above; },
                        [speed](const Arctan& a) {
                          const Real f = rad_to_hz(speed);
                          return a.value * (a.c0 - a.c1 / pi * std::atan(a.c2 * (f - a.f_as)));
                        },
                        [speed, frequency](const FrequencyTable& t) { return bilinear(t, speed, frequency); },
                    },
                    law_);
}

bool SpeedCoefficient::is_zero() const {
  return std::visit(
      Overloaded{
          [](const Constant& c) { return c.value == 0.0; },
          [](const Table& t) { return std::all_of(t.values.begin(), t.values.end(), [](Real v) { return v == 0.0; }); },
          [](const Step& s) { return s.below == 0.0 && s.above == 0.0; },
          [](const Arctan& a) { return a.value == 0.0; },
          [](const FrequencyTable& t) {
            return std::all_of(t.values.begin(), t.values.end(), [](Real v) { return v == 0.0; });
          },
      },
      law_);
}

}  // namespace feran

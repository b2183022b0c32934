#include <feran/model/speed_coefficient.hpp>

#include <algorithm>
#include <cmath>

#include <feran/core/error.hpp>

namespace feran {

namespace {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;
}  // namespace

Real SpeedCoefficient::at(Real speed) const {
  return std::visit(
      Overloaded{
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
      },
      law_);
}

bool SpeedCoefficient::is_zero() const {
  return std::visit(
      Overloaded{
          [](const Constant& c) { return c.value == 0.0; },
          [](const Table& t) {
            return std::all_of(t.values.begin(), t.values.end(), [](Real v) { return v == 0.0; });
          },
          [](const Step& s) { return s.below == 0.0 && s.above == 0.0; },
          [](const Arctan& a) { return a.value == 0.0; },
      },
      law_);
}

}  // namespace feran

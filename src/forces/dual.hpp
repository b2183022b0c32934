#pragma once
// Forward-mode automatic differentiation: a value with its gradient with respect to
// N inputs, for the film forces whose closed-form pressures are differentiated
// exactly instead of by finite differences.

#include <array>
#include <cmath>

#include <feran/core/types.hpp>

namespace feran::detail {

template <int N>
struct Dual {
  Real v = 0.0;
  std::array<Real, N> d{};

  Dual() = default;
  Dual(Real value) : v(value) {}  // NOLINT(google-explicit-constructor): constants mix freely
  /// Input @p i of the N, with value @p value.
  static Dual input(Real value, int i) {
    Dual x(value);
    x.d[static_cast<std::size_t>(i)] = 1.0;
    return x;
  }
  /// f(x) from f's value and slope at x.
  Dual chain(Real value, Real slope) const {
    Dual r(value);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = slope * d[i];
    return r;
  }

  Dual& operator+=(const Dual& o) {
    v += o.v;
    for (std::size_t i = 0; i < N; ++i) d[i] += o.d[i];
    return *this;
  }
  Dual& operator-=(const Dual& o) {
    v -= o.v;
    for (std::size_t i = 0; i < N; ++i) d[i] -= o.d[i];
    return *this;
  }
  Dual& operator*=(const Dual& o) {
    for (std::size_t i = 0; i < N; ++i) d[i] = d[i] * o.v + v * o.d[i];
    v *= o.v;
    return *this;
  }
  Dual& operator/=(const Dual& o) {
    const Real inv = 1.0 / o.v;
    for (std::size_t i = 0; i < N; ++i) d[i] = (d[i] - v * inv * o.d[i]) * inv;
    v *= inv;
    return *this;
  }
};

template <int N>
Dual<N> operator+(Dual<N> a, const Dual<N>& b) {
  return a += b;
}
template <int N>
Dual<N> operator-(Dual<N> a, const Dual<N>& b) {
  return a -= b;
}
template <int N>
Dual<N> operator*(Dual<N> a, const Dual<N>& b) {
  return a *= b;
}
template <int N>
Dual<N> operator/(Dual<N> a, const Dual<N>& b) {
  return a /= b;
}
template <int N>
Dual<N> operator+(Dual<N> a, Real b) {
  return a += Dual<N>(b);
}
template <int N>
Dual<N> operator+(Real a, Dual<N> b) {
  return b += Dual<N>(a);
}
template <int N>
Dual<N> operator-(Dual<N> a, Real b) {
  return a -= Dual<N>(b);
}
template <int N>
Dual<N> operator-(Real a, const Dual<N>& b) {
  return Dual<N>(a) -= b;
}
template <int N>
Dual<N> operator*(Dual<N> a, Real b) {
  return a *= Dual<N>(b);
}
template <int N>
Dual<N> operator*(Real a, Dual<N> b) {
  return b *= Dual<N>(a);
}
template <int N>
Dual<N> operator/(Dual<N> a, Real b) {
  return a /= Dual<N>(b);
}
template <int N>
Dual<N> operator/(Real a, const Dual<N>& b) {
  return Dual<N>(a) /= b;
}
template <int N>
Dual<N> operator-(const Dual<N>& a) {
  return Dual<N>(0.0) -= a;
}

template <int N>
Dual<N> sin(const Dual<N>& x) {
  return x.chain(std::sin(x.v), std::cos(x.v));
}
template <int N>
Dual<N> cos(const Dual<N>& x) {
  return x.chain(std::cos(x.v), -std::sin(x.v));
}
template <int N>
Dual<N> sqrt(const Dual<N>& x) {
  const Real s = std::sqrt(x.v);
  return x.chain(s, 0.5 / s);
}
template <int N>
Dual<N> pow(const Dual<N>& x, Real p) {
  return x.chain(std::pow(x.v, p), p * std::pow(x.v, p - 1.0));
}
/// atan2(y, x) with ∂/∂y = x/(x² + y²), ∂/∂x = −y/(x² + y²).
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
  const Real r2 = x.v * x.v + y.v * y.v;
  Dual<N> out(std::atan2(y.v, x.v));
  for (std::size_t i = 0; i < N; ++i) out.d[i] = (x.v * y.d[i] - y.v * x.d[i]) / r2;
  return out;
}

// The plain versions, so that templated code reads the same for Real.
using std::atan2;
using std::cos;
using std::pow;
using std::sin;
using std::sqrt;

}  // namespace feran::detail

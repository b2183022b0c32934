#pragma once
/// @file
/// Gauss–Legendre quadrature.

#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// The nodes and weights of the @p n-point Gauss–Legendre rule on [−1, 1] (exact for
/// polynomials of degree 2n − 1), from Newton's method on the Legendre polynomial
/// P_n started at Tricomi's approximation of its roots; nodes ascending, each to
/// about one unit in the last place.
struct GaussLegendre {
  std::vector<Real> nodes;
  std::vector<Real> weights;
};
GaussLegendre gauss_legendre(int n);

}  // namespace feran

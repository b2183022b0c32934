#include <feran/elements/annular_seal.hpp>

#include <array>
#include <cmath>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

void check(const AnnularSealGeometry& g) {
  const auto positive = [](Real v) { return std::isfinite(v) && v > 0; };
  if (!positive(g.radius) || !positive(g.length) || !positive(g.clearance) || !positive(g.pressure_drop) ||
      !positive(g.density) || !positive(g.viscosity) || !positive(g.friction_n))
    throw Error(
        "annular seal: its radius, length, clearance, pressure drop, density, viscosity and friction "
        "coefficient n must be positive and finite");
  if (!(std::isfinite(g.entrance_loss) && g.entrance_loss >= 0))
    throw Error("annular seal: its entrance loss coefficient must be at least 0");
  if (!(g.friction_m > -1 && g.friction_m <= 0))
    throw Error("annular seal: its friction exponent m must be in (−1, 0]");
}

// λ(V): the friction loss per unit L/C in velocity heads ρV², for axial velocity V and
// swirl Rω/2 relative to both walls: λ = n·(2CV/ν)^m·(1 + (Rω/(2V))²)^((1+m)/2).
Real friction(const AnnularSealGeometry& g, Real V, Real speed) {
  const Real nu = g.viscosity / g.density;
  const Real swirl = g.radius * speed / (2 * V);
  return g.friction_n * std::pow(2 * g.clearance * V / nu, g.friction_m) *
         std::pow(1 + swirl * swirl, (1 + g.friction_m) / 2);
}

// ΔP(V) = (1 + ξ + 2σ(V))·ρV²/2 − ΔP: increasing in V for m > −1 (its friction part is
// ∝ V·(V² + (Rω/2)²)^((1+m)/2)), negative at 0 and not negative where the friction is
// left out. Bisection on that bracket to the last bits of V.
Real axial_velocity(const AnnularSealGeometry& g, Real speed) {
  const auto residual = [&](Real V) {
    const Real sigma = friction(g, V, speed) * g.length / g.clearance;
    return (1 + g.entrance_loss + 2 * sigma) * g.density * V * V / 2 - g.pressure_drop;
  };
  Real low = 0.0;
  Real high = std::sqrt(2 * g.pressure_drop / (g.density * (1 + g.entrance_loss)));
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
    const Real mid = 0.5 * (low + high);
    (residual(mid) < 0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace

AnnularSealCoefficients annular_seal_coefficients(const AnnularSealGeometry& g, Real speed) {
  check(g);
  const Real w = std::abs(speed);
  AnnularSealCoefficients out;
  const Real V = axial_velocity(g, w);
  const Real lambda = friction(g, V, w);
  const Real sigma = lambda * g.length / g.clearance;
  const Real xi = g.entrance_loss, m = g.friction_m;
  // β: the share of the swirl in the squared speed relative to each wall; a: the
  // change of the axial wall shear with the axial velocity, in units ρλV.
  const Real b = V / (g.radius * w);
  const Real beta = w > 0 ? 1 / (1 + 4 * b * b) : 0.0;
  const Real a = 1 + (1 + m) * (1 - beta);
  const Real D = 1 + xi + 2 * sigma, A = 1 + xi + a * sigma;
  const Real mu0 = sigma * sigma * (1 - m) * (1 + xi) / (D * A);
  const Real mu1 = sigma * (a * a * sigma * sigma + 4 * a * sigma * (1 + xi) + 6 * (1 + xi)) / (6 * D * A);
  const Real mu2 = sigma * (a * sigma + 4 * (1 + xi)) / (6 * D * A);
  const Real mu3 = pi * g.radius * g.pressure_drop / lambda;
  const Real T = g.length / V;  // the fluid's transit time
  const Real wT = speed * T;    // signed: the cross-coupling follows the direction of rotation
  out.K = mu3 * (mu0 - mu2 * wT * wT / 4);
  out.k = mu3 * mu1 * wT / 2;
  out.C = mu3 * mu1 * T;
  out.c = mu3 * mu2 * wT * T;
  out.M = mu3 * mu2 * T * T;
  out.axial_velocity = V;
  out.leakage = 2 * pi * g.radius * g.clearance * V;
  out.reynolds = 2 * g.clearance * V * g.density / g.viscosity;
  out.friction = lambda;
  out.sigma = sigma;
  return out;
}

AnnularSeal::AnnularSeal(Index node_a, std::optional<Index> node_b, AnnularSealGeometry geometry)
    : node_a_(node_a), node_b_(node_b), geometry_(geometry) {
  check(geometry_);
}

std::vector<Index> AnnularSeal::dofs() const {
  std::vector<Index> out;
  const std::array<std::optional<Index>, 2> nodes = {node_a_, node_b_};
  for (const std::optional<Index>& node : nodes)
    if (node)
      for (const Dof d : {Dof::v, Dof::w}) out.push_back(dofs_per_node * *node + static_cast<Index>(d));
  return out;
}

namespace {
// The 2×2 block [[d, x], [−x, d]] on (v, w), for the relative motion of the nodes.
Matrix isotropic(Real d, Real x, bool two_nodes) {
  Matrix a(2, 2);
  a << d, x, -x, d;
  if (!two_nodes) return a;
  Matrix m(4, 4);
  m << a, -a, -a, a;
  return m;
}
}  // namespace

LocalMatrices AnnularSeal::local_matrices(const OperatingPoint& op) const {
  const AnnularSealCoefficients s = annular_seal_coefficients(geometry_, op.speed);
  const bool two = node_b_.has_value();
  return {.dofs = dofs(),
          .M = isotropic(s.M, 0.0, two),
          .C = isotropic(s.C, s.c, two),
          .K = isotropic(s.K, s.k, two),
          .G = {},
          .Ci = {},
          .Ki = {},
          .loss_factor = 0.0};
}

Transmission AnnularSeal::transmission(Real speed) const {
  const AnnularSealCoefficients s = annular_seal_coefficients(geometry_, speed);
  Transmission t{.node_a = node_a_,
                 .node_b = node_b_,
                 .K = Matrix::Zero(dofs_per_node, dofs_per_node),
                 .C = Matrix::Zero(dofs_per_node, dofs_per_node),
                 .loss_factor = 0.0,
                 .M = Matrix::Zero(dofs_per_node, dofs_per_node)};
  const auto v = static_cast<Index>(Dof::v), w = static_cast<Index>(Dof::w);
  t.K(v, v) = t.K(w, w) = s.K;
  t.K(v, w) = s.k;
  t.K(w, v) = -s.k;
  t.C(v, v) = t.C(w, w) = s.C;
  t.C(v, w) = s.c;
  t.C(w, v) = -s.c;
  t.M(v, v) = t.M(w, w) = s.M;
  return t;
}

}  // namespace feran

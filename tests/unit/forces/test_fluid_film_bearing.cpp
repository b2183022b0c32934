// Journal bearings, short (Ocvirk, π film) and long (Sommerfeld, Gümbel): the force
// integrated over the film against the closed forms of the load capacity and attitude
// angle, its Jacobian against finite differences, the eight coefficients against
// their closed forms, and Friswell et al., Dynamics of Rotating Machines (2010),
// Example 5.5.1.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <random>

#include <feran/core/error.hpp>
#include <feran/core/quadrature.hpp>
#include <feran/forces/fluid_film_bearing.hpp>

namespace feran::test_fluid_film_bearing {
namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// Friswell et al. (2010), Example 5.5.1.
JournalBearingGeometry friswell_5_5_1() {
  return {.diameter = 0.1, .length = 0.03, .clearance = 1e-4, .viscosity = 0.1};
}

Vec2 direction(Real angle) { return {std::cos(angle), std::sin(angle)}; }

// The rotation taking the load frame (first axis along the load on the journal,
// second turned by +90°) to (y, z).
Mat2 load_frame(Real load_angle) {
  Mat2 T;
  T << std::cos(load_angle), -std::sin(load_angle), std::sin(load_angle), std::cos(load_angle);
  return T;
}

TEST(GaussLegendre, ThreePointsAndExactnessToDegree2nMinus1) {
  const GaussLegendre r3 = gauss_legendre(3);
  EXPECT_NEAR(r3.nodes[0], -std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(r3.nodes[1], 0.0, 1e-15);
  EXPECT_NEAR(r3.weights[0], 5.0 / 9.0, 1e-15);
  EXPECT_NEAR(r3.weights[1], 8.0 / 9.0, 1e-15);
  for (int n : {1, 2, 7, 20, 32, 64}) {
    const GaussLegendre r = gauss_legendre(n);
    // ∫_{-1}^{1} x^k dx = 2/(k + 1) for even k, 0 for odd k, exact up to k = 2n − 1.
    for (int k = 0; k <= 2 * n - 1; ++k) {
      Real sum = 0.0;
      for (std::size_t i = 0; i < r.nodes.size(); ++i) sum += r.weights[i] * std::pow(r.nodes[i], k);
      EXPECT_NEAR(sum, k % 2 == 0 ? 2.0 / (k + 1) : 0.0, 1e-14) << "n = " << n << ", k = " << k;
    }
  }
}

constexpr FilmTheory theories[] = {FilmTheory::short_bearing, FilmTheory::long_bearing};
const char* name(FilmTheory t) { return t == FilmTheory::short_bearing ? "short" : "long"; }

// A journal held still at eccentricity ratio ε in any direction ψ: the film force
// has the closed-form magnitude W(ε), and the load it balances (−f) lies at the
// attitude angle φ(ε) behind ψ. The short bearing's quadrature is exact to rounding
// in its variable: 1e-12 even at ε = 0.97 (where W is 5·10⁴ times that at ε = 0.05).
// The long bearing's pressure is integrated between roots found to 1e-14 rad: 1e-11.
TEST(FilmForce, StaticForceIsTheClosedFormLoadAtTheAttitudeAngle) {
  const JournalBearingGeometry g = friswell_5_5_1();
  const Real speed = hz_to_rad(25.0);
  for (FilmTheory theory : theories) {
    const Real tol = theory == FilmTheory::short_bearing ? 1e-12 : 1e-11;
    for (Real eps : {0.01, 0.05, 0.3, 0.6, 0.9, 0.97}) {
      for (Real psi : {0.0, 1.0, -2.5, 3.0}) {
        const FilmForce F = film_force(g, theory, speed, eps * g.clearance * direction(psi), Vec2::Zero());
        EXPECT_NEAR(F.f.norm() / film_load(g, theory, speed, eps), 1.0, tol) << name(theory) << ", eps = " << eps;
        const Vec2 load = -F.f;
        const Real lag = std::remainder(psi - std::atan2(load(1), load(0)), 2.0 * pi);
        EXPECT_NEAR(lag, film_attitude_angle(theory, eps), tol) << name(theory) << ", eps = " << eps;
      }
    }
  }
}

// Jacobian blocks against central differences at random positions and velocities
// (also whirling and squeezing ones, where the loaded part of the film moves with the
// velocity). Steps 1e-6 of the clearance and of cΩ: the long bearing's pressure is a
// sum of terms of up to (1 − ε²)^{-5/2} that cancel, whose rounding makes smaller
// steps noisy (measured: 4e-8 of the Jacobian at 1e-7, 3e-9 at 1e-6); truncation is
// below 1e-6 down to ε = 0.003. Tolerance 1e-6 of the Jacobian block's norm.
TEST(FilmForce, JacobianMatchesFiniteDifferences) {
  const JournalBearingGeometry g = friswell_5_5_1();
  const Real speed = 200.0, c = g.clearance;
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int trial = 0; trial < 80; ++trial) {
    const FilmTheory theory = theories[trial % 2];
    Vec2 x(u(rng), u(rng));
    x *= 0.9 * c * std::abs(u(rng)) / x.norm();
    const Vec2 v = 0.5 * c * speed * Vec2(u(rng), u(rng));
    const FilmForce F = film_force(g, theory, speed, x, v);
    for (int j = 0; j < 2; ++j) {
      const Real hx = 1e-6 * c, hv = 1e-6 * c * speed;
      Vec2 xp = x, xm = x, vp = v, vm = v;
      xp(j) += hx, xm(j) -= hx, vp(j) += hv, vm(j) -= hv;
      const Vec2 dfx = (film_force(g, theory, speed, xp, v).f - film_force(g, theory, speed, xm, v).f) / (2 * hx);
      const Vec2 dfv = (film_force(g, theory, speed, x, vp).f - film_force(g, theory, speed, x, vm).f) / (2 * hv);
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(F.dfdx(i, j), dfx(i), 1e-6 * F.dfdx.norm()) << name(theory) << " trial " << trial;
        EXPECT_NEAR(F.dfdv(i, j), dfv(i), 1e-6 * F.dfdv.norm()) << name(theory) << " trial " << trial;
      }
    }
  }
}

// The Jacobian at the static equilibrium, turned into the load frame, equals the
// closed-form coefficients (an independent derivation) for any load direction.
TEST(FilmForce, LinearisedForceEqualsTheClosedFormCoefficients) {
  const JournalBearingGeometry g = friswell_5_5_1();
  for (FilmTheory theory : theories) {
    for (Real speed : {1500.0 * 2.0 * pi / 60.0, 2000.0 * 2.0 * pi / 60.0, 700.0}) {
      for (Real load : {50.0, 525.0, 3000.0, 20000.0}) {
        for (Real load_angle : {-pi / 2, 0.3, 2.0}) {
          const Real eps = film_eccentricity(g, theory, speed, load);
          const Vec2 x = eps * g.clearance * direction(load_angle + film_attitude_angle(theory, eps));
          const FilmForce F = film_force(g, theory, speed, x, Vec2::Zero());
          EXPECT_NEAR((F.f + load * direction(load_angle)).norm() / load, 0.0, 1e-10);
          const Mat2 T = load_frame(load_angle);
          const Mat2 K = -T.transpose() * F.dfdx * T, C = -T.transpose() * F.dfdv * T;
          const BearingCoefficients closed = film_coefficients(g, theory, speed, load);
          EXPECT_LT((K - closed.K).norm() / closed.K.norm(), 1e-9) << name(theory) << ", W = " << load << "\n"
                                                                   << K << "\n"
                                                                   << closed.K;
          EXPECT_LT((C - closed.C).norm() / closed.C.norm(), 1e-9) << name(theory) << ", W = " << load << "\n"
                                                                   << C << "\n"
                                                                   << closed.C;
        }
      }
    }
  }
}

// A housing node: the film pushes it with the opposite force, and only the relative
// motion counts.
TEST(ShortBearing, HousingCarriesTheOppositeForce) {
  FluidFilmBearing b;
  b.node_a = 2;
  b.node_b = 5;
  b.geometry = friswell_5_5_1();
  ASSERT_EQ(b.dofs().size(), 4u);
  EXPECT_EQ(b.dofs()[2], global_dof(5, Dof::v));
  Vector x(4), v(4);
  x << 3e-5, -2e-5, 1e-5, 1e-5;
  v << 1e-3, 2e-3, -1e-3, 0.0;
  const MotionState s{0.0, 150.0};
  const NonlinearForceValue two = b.force(s, x, v);
  const FilmForce rel = film_force(b.geometry, b.theory, 150.0, x.head<2>() - x.tail<2>(), v.head<2>() - v.tail<2>());
  EXPECT_LT((two.f.head<2>() - rel.f).norm(), 1e-12 * rel.f.norm());
  EXPECT_LT((two.f.tail<2>() + rel.f).norm(), 1e-12 * rel.f.norm());
  // Moving both together changes nothing.
  const Vector shift = (Vector(4) << 1e-5, 2e-5, 1e-5, 2e-5).finished();
  EXPECT_LT((b.force(s, x + shift, v).f - two.f).norm(), 1e-9 * rel.f.norm());
  EXPECT_LT((two.dfdx.leftCols<2>() + two.dfdx.rightCols<2>()).norm(), 1e-12 * two.dfdx.norm());
}

TEST(FilmForce, JournalAtTheBearingWallIsAnError) {
  const JournalBearingGeometry g = friswell_5_5_1();
  for (FilmTheory theory : theories) {
    EXPECT_THROW(film_force(g, theory, 100.0, Vec2(0.0, g.clearance), Vec2::Zero()), Error);
    EXPECT_THROW(film_eccentricity(g, theory, 0.0, 100.0), Error);
  }
}

// Friswell et al. (2010), Example 5.5.1 (p. 200): D = 100 mm, L = 30 mm, c = 0.1 mm,
// μ = 0.1 Pa s, W = 525 N at 1500 rpm. The book's axes are x horizontal and y up,
// with the load downwards: x is the load frame's second axis and y minus its first.
// Its coefficients are printed to four digits: each entry to half a unit of its last
// digit. (The example's second speed, 2000 rpm, is among those of the tests above.)
TEST(ShortBearing, Friswell551) {
  const JournalBearingGeometry g = friswell_5_5_1();
  const Real w1500 = 1500.0 * 2.0 * pi / 60.0;
  EXPECT_NEAR(film_eccentricity(g, FilmTheory::short_bearing, w1500, 525.0), 0.2663, 0.00005);
  const BearingCoefficients load_frame = film_coefficients(g, FilmTheory::short_bearing, w1500, 525.0);
  Mat2 P;  // (x, y) from the load frame
  P << 0, 1, -1, 0;
  const BearingCoefficients c{P * load_frame.K * P.transpose(), P * load_frame.C * P.transpose()};
  EXPECT_NEAR(c.K(0, 0), 12.81e6, 0.005e6);
  EXPECT_NEAR(c.K(0, 1), 16.39e6, 0.005e6);
  EXPECT_NEAR(c.K(1, 0), -25.06e6, 0.005e6);
  EXPECT_NEAR(c.K(1, 1), 8.815e6, 0.0005e6);
  EXPECT_NEAR(c.C(0, 0), 232.9e3, 0.05e3);
  EXPECT_NEAR(c.C(0, 1), -81.92e3, 0.005e3);
  EXPECT_NEAR(c.C(1, 0), -81.92e3, 0.005e3);
  EXPECT_NEAR(c.C(1, 1), 294.9e3, 0.05e3);
}

// The operating data an engineer checks first, against their definitions and closed
// forms: the short bearing at eccentricity ε has h_min = c(1 − ε), the attitude angle
// tan φ = π√(1 − ε²)/(4ε) (its closed form, film_attitude_angle), the Sommerfeld number
// μNLD/W·(R/c)² with W its closed-form load, the power loss torque × Ω with Petroff's
// torque 2πμR³LΩ/c at the centre, and the peak pressure
// 3μΩL²/(4c²)·ε sin θ*/(1 + ε cos θ*)³ at cos θ* = (1 − √(1 + 24ε²))/(4ε).
TEST(JournalOperatingData, ShortBearingAgreesWithItsClosedForms) {
  const JournalBearingGeometry g = friswell_5_5_1();
  const Real speed = 1500 * pi / 30;
  FluidFilmBearing b{.node_a = 0, .node_b = {}, .geometry = g, .theory = FilmTheory::short_bearing, .grid = {}};
  for (const Real eps : {0.1, 0.4, 0.8}) {
    Vector x(2);
    x << eps * g.clearance * std::cos(0.7), eps * g.clearance * std::sin(0.7);
    std::map<std::string, Real> d;
    for (const OperatingValue& o : b.operating_data({.speed = speed}, x, Vector::Zero(2))) d[o.name] = o.value;
    const Real R = g.diameter / 2, W = film_load(g, FilmTheory::short_bearing, speed, eps);
    EXPECT_NEAR(d["eccentricity_ratio"], eps, 1e-15);
    EXPECT_NEAR(d["min_film_thickness_m"], g.clearance * (1 - eps), 1e-18);
    EXPECT_NEAR(d["min_film_angle_deg"], 0.7 * 180 / pi, 1e-9);
    // The force integrated by quadrature against the closed forms: 1e-9.
    EXPECT_NEAR(d["load_n"], W, 1e-9 * W);
    EXPECT_NEAR(d["attitude_angle_deg"], film_attitude_angle(FilmTheory::short_bearing, eps) * 180 / pi, 1e-7);
    const Real S = g.viscosity * speed / (2 * pi) * g.length * g.diameter / W * (R / g.clearance) * (R / g.clearance);
    EXPECT_NEAR(d["sommerfeld_number"], S, 1e-9 * S);
    EXPECT_NEAR(d["power_loss_w"], d["friction_torque_nm"] * speed, 1e-12 * d["power_loss_w"]);
    const Real ct = (1 - std::sqrt(1 + 24 * eps * eps)) / (4 * eps), st = std::sqrt(1 - ct * ct);
    const Real p_max = 3 * g.viscosity * speed * g.length * g.length / (4 * g.clearance * g.clearance) * eps * st /
                       std::pow(1 + eps * ct, 3);
    // 180 samples and golden-section search to 1e-10 rad: 1e-11 (round-off).
    EXPECT_NEAR(d["peak_pressure_pa"], p_max, 1e-11 * p_max) << eps;
  }
  // Petroff at the centre: no load, the whole film shears, T = 2πμR³LΩ/c.
  std::map<std::string, Real> d;
  for (const OperatingValue& o : b.operating_data({.speed = speed}, Vector::Zero(2), Vector::Zero(2)))
    d[o.name] = o.value;
  const Real R = g.diameter / 2;
  EXPECT_NEAR(d["friction_torque_nm"], 2 * pi * g.viscosity * R * R * R * g.length * speed / g.clearance, 1e-15);
  EXPECT_EQ(d["min_film_thickness_m"], g.clearance);
}

}  // namespace
}  // namespace feran::test_fluid_film_bearing

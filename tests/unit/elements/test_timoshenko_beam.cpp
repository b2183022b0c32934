// Unit tests of the two-node Timoshenko shaft element (docs/theory/shaft_element.md).
//
// Reference values come from outside the element code: the published Euler–Bernoulli
// matrices (Przemieniecki 1968, ch. 5 and 11; Friswell, Penny, Garvey & Lees 2010,
// ch. 5), Gauss quadrature of the Timoshenko shape functions, rigid-body invariants,
// the closed-form Timoshenko cantilever and Cowper's (1966) shear coefficients.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <feran/elements/timoshenko_beam.hpp>

namespace feran::test_timoshenko_beam {
namespace {

// Steel-like material with Poisson ratio nu: the element reads nu back as E/(2G) − 1.
constexpr Real E = 2.1e11, nu = 0.3, rho = 7800.0;
const Material mat{"steel", E, E / (2.0 * (1.0 + nu)), rho};

constexpr Index idx(Index node, Dof d) { return global_dof(node, d); }

TimoshenkoBeam make_beam(Real length, CircularSection section, bool shear,
                         GyroscopicForm gyro = GyroscopicForm::consistent, Real beta = 0.0, bool rotating = true) {
  return TimoshenkoBeam(0, 1, length, section, mat, BeamOptions{shear, gyro, rotating, beta});
}

// The 4×4 submatrix of a 12×12 element matrix on rows (r1, r2 at node a, r1, r2 at
// node b) and the corresponding columns.
Matrix plane_block(const Matrix& a, Dof r1, Dof r2, Dof c1, Dof c2) {
  const std::array<Index, 4> rows{idx(0, r1), idx(0, r2), idx(1, r1), idx(1, r2)};
  const std::array<Index, 4> cols{idx(0, c1), idx(0, c2), idx(1, c1), idx(1, c2)};
  Matrix out(4, 4);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) out(static_cast<Index>(i), static_cast<Index>(j)) = a(rows[i], cols[j]);
  return out;
}
Matrix xy_block(const Matrix& a) { return plane_block(a, Dof::v, Dof::rz, Dof::v, Dof::rz); }
Matrix xz_block(const Matrix& a) { return plane_block(a, Dof::w, Dof::ry, Dof::w, Dof::ry); }

// S = diag(1, −1, 1, −1): the x–z plane's slope DOF ry = −dw/dx.
Matrix slope_flip() { return Eigen::Vector4d(1.0, -1.0, 1.0, -1.0).asDiagonal(); }

Real max_abs(const Matrix& a) { return a.cwiseAbs().maxCoeff(); }

// Published Euler–Bernoulli matrices in one plane, DOFs (d1, s1, d2, s2), s = dd/dx.
Matrix published_stiffness(Real EI, Real L) {
  Matrix k(4, 4);
  k << 12, 6 * L, -12, 6 * L,               //
      6 * L, 4 * L * L, -6 * L, 2 * L * L,  //
      -12, -6 * L, 12, -6 * L,              //
      6 * L, 2 * L * L, -6 * L, 4 * L * L;
  return EI / (L * L * L) * k;
}
Matrix published_translational_mass(Real rhoA, Real L) {
  Matrix m(4, 4);
  m << 156, 22 * L, 54, -13 * L,              //
      22 * L, 4 * L * L, 13 * L, -3 * L * L,  //
      54, 13 * L, 156, -22 * L,               //
      -13 * L, -3 * L * L, -22 * L, 4 * L * L;
  return rhoA * L / 420.0 * m;
}
Matrix published_rotary_mass(Real rhoI, Real L) {
  Matrix m(4, 4);
  m << 36, 3 * L, -36, 3 * L,            //
      3 * L, 4 * L * L, -3 * L, -L * L,  //
      -36, -3 * L, 36, -3 * L,           //
      3 * L, -L * L, -3 * L, 4 * L * L;
  return rhoI / (30.0 * L) * m;
}

// Shear parameter from the independent closed form of Cowper's κ for a solid circle.
Real solid_phi(Real d, Real L) {
  const Real kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
  const Real I = pi * std::pow(d, 4) / 64.0, A = pi * d * d / 4.0;
  return 12.0 * E * I / (kappa * mat.G * A * L * L);
}

// (a) Without shear the element is the classic Euler–Bernoulli element with rotary
// inertia. Tolerance 1e-14 of the largest entry: the same few products in another
// order, so round-off only.
TEST(TimoshenkoBeam, ShearOffEqualsPublishedEulerBernoulliMatrices) {
  const Real L = 0.3, d = 0.04;
  const TimoshenkoBeam beam = make_beam(L, {d, 0.0}, false);
  EXPECT_EQ(beam.shear_parameter(), 0.0);
  const Real A = pi * d * d / 4.0, I = pi * std::pow(d, 4) / 64.0;
  const Matrix K = published_stiffness(E * I, L);
  const Matrix MT = published_translational_mass(rho * A, L);
  const Matrix MR = published_rotary_mass(rho * I, L);

  EXPECT_LE(max_abs(beam.bending_stiffness() - K), 1e-14 * max_abs(K));
  EXPECT_LE(max_abs(beam.bending_translational_mass() - MT), 1e-14 * max_abs(MT));
  EXPECT_LE(max_abs(beam.bending_rotary_mass() - MR), 1e-14 * max_abs(MR));

  const LocalMatrices lm = beam.local_matrices({});
  const Matrix S = slope_flip();
  EXPECT_LE(max_abs(xy_block(lm.K) - K), 1e-14 * max_abs(K));
  EXPECT_LE(max_abs(xz_block(lm.K) - S * K * S), 1e-14 * max_abs(K));
  EXPECT_LE(max_abs(xy_block(lm.M) - (MT + MR)), 1e-14 * max_abs(MT));
  EXPECT_LE(max_abs(xz_block(lm.M) - S * (MT + MR) * S), 1e-14 * max_abs(MT));

  // The two planes are uncoupled in K and M.
  EXPECT_EQ(max_abs(plane_block(lm.K, Dof::v, Dof::rz, Dof::w, Dof::ry)), 0.0);
  EXPECT_EQ(max_abs(plane_block(lm.M, Dof::v, Dof::rz, Dof::w, Dof::ry)), 0.0);

  // Axial and torsion bars (Przemieniecki ch. 5): EA/L, GJ/L; ρAL/6·[2 1; 1 2].
  EXPECT_NEAR(lm.K(idx(0, Dof::u), idx(1, Dof::u)), -E * A / L, 1e-14 * E * A / L);
  EXPECT_NEAR(lm.K(idx(0, Dof::rx), idx(0, Dof::rx)), mat.G * 2 * I / L, 1e-14 * mat.G * 2 * I / L);
  EXPECT_NEAR(lm.M(idx(0, Dof::u), idx(0, Dof::u)), rho * A * L / 3.0, 1e-14 * rho * A * L);
  EXPECT_NEAR(lm.M(idx(0, Dof::rx), idx(1, Dof::rx)), rho * 2 * I * L / 6.0, 1e-14 * rho * I * L);
}

// (a) The slope-sign flip of the x–z plane, shown on single entries with shear on:
// K(v1, rz1) = +6EI/(L²(1+Φ)) and K(w1, ry1) = −6EI/(L²(1+Φ)) (rz = +dv/dx,
// ry = −dw/dx). Tolerance 1e-13: Φ is computed along another route (closed-form κ).
TEST(TimoshenkoBeam, XzPlaneCarriesTheSlopeSignFlip) {
  const Real L = 0.1, d = 0.05;
  const TimoshenkoBeam beam = make_beam(L, {d, 0.0}, true);
  const Real phi = solid_phi(d, L);
  EXPECT_NEAR(beam.shear_parameter(), phi, 1e-13 * phi);
  const Real I = pi * std::pow(d, 4) / 64.0;
  const Real k6 = 6.0 * E * I / (L * L * (1.0 + phi));
  const Matrix K = beam.local_matrices({}).K;
  EXPECT_NEAR(K(idx(0, Dof::v), idx(0, Dof::rz)), k6, 1e-13 * k6);
  EXPECT_NEAR(K(idx(0, Dof::w), idx(0, Dof::ry)), -k6, 1e-13 * k6);
  EXPECT_NEAR(K(idx(1, Dof::v), idx(0, Dof::rz)), -k6, 1e-13 * k6);
  EXPECT_NEAR(K(idx(1, Dof::w), idx(0, Dof::ry)), k6, 1e-13 * k6);
  // Rotation–rotation terms keep their sign in both planes: (2 − Φ)EI/(L(1+Φ)).
  const Real k22 = (2.0 - phi) * E * I / (L * (1.0 + phi));
  EXPECT_NEAR(K(idx(0, Dof::rz), idx(1, Dof::rz)), k22, 1e-13 * std::abs(k22));
  EXPECT_NEAR(K(idx(0, Dof::ry), idx(1, Dof::ry)), k22, 1e-13 * std::abs(k22));
}

// (a, with shear) The Timoshenko matrices against Gauss quadrature of the
// interdependent shape functions (Friswell et al. 2010, ch. 5; Nelson 1980: the
// static solution of a Timoshenko beam under end loads): M_T = ρA∫N_tᵀN_t,
// M_R = ρI∫N_rᵀN_r, K = EI∫N_r'ᵀN_r' + κGA∫γᵀγ with γ = N_t' − N_r. Four Gauss
// points integrate the degree-6 products exactly; tolerance 1e-13 of the largest
// entry (round-off of the quadrature sums).
TEST(TimoshenkoBeam, ShearOnMatchesQuadratureOfShapeFunctions) {
  const Real L = 0.08, d = 0.05, di = 0.02;
  const TimoshenkoBeam beam = make_beam(L, {d, di}, true);
  const Real A = pi / 4.0 * (d * d - di * di), I = pi / 64.0 * (std::pow(d, 4) - std::pow(di, 4));
  const Real kappa = CircularSection{d, di}.cowper_shear_coefficient(nu);
  const Real phi = 12.0 * E * I / (kappa * mat.G * A * L * L);
  ASSERT_GT(phi, 0.5);  // shear matters for this stubby element

  const std::array<Real, 4> gx{-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const std::array<Real, 4> gw{0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  Matrix MT = Matrix::Zero(4, 4), MR = Matrix::Zero(4, 4), K = Matrix::Zero(4, 4);
  const Real c = 1.0 / (1.0 + phi);
  for (std::size_t g = 0; g < 4; ++g) {
    const Real x = 0.5 * (gx[g] + 1.0), wgt = 0.5 * L * gw[g];  // x = ξ in [0, 1]
    Eigen::RowVector4d nt, ntx, nr, nrx;
    nt << c * (1 - 3 * x * x + 2 * x * x * x + phi * (1 - x)),
        c * L * (x - 2 * x * x + x * x * x + phi * (x - x * x) / 2), c * (3 * x * x - 2 * x * x * x + phi * x),
        c * L * (-x * x + x * x * x - phi * (x - x * x) / 2);
    ntx << c * (-6 * x + 6 * x * x - phi) / L, c * (1 - 4 * x + 3 * x * x + phi * (1 - 2 * x) / 2),
        c * (6 * x - 6 * x * x + phi) / L, c * (-2 * x + 3 * x * x - phi * (1 - 2 * x) / 2);
    nr << c * 6 * (x * x - x) / L, c * (1 - 4 * x + 3 * x * x + phi * (1 - x)), c * 6 * (x - x * x) / L,
        c * (-2 * x + 3 * x * x + phi * x);
    nrx << c * 6 * (2 * x - 1) / (L * L), c * (-4 + 6 * x - phi) / L, c * 6 * (1 - 2 * x) / (L * L),
        c * (-2 + 6 * x + phi) / L;
    const Eigen::RowVector4d gamma = ntx - nr;
    MT += wgt * rho * A * nt.transpose() * nt;
    MR += wgt * rho * I * nr.transpose() * nr;
    K += wgt * (E * I * nrx.transpose() * nrx + kappa * mat.G * A * gamma.transpose() * gamma);
  }
  EXPECT_LE(max_abs(beam.bending_translational_mass() - MT), 1e-13 * max_abs(MT));
  EXPECT_LE(max_abs(beam.bending_rotary_mass() - MR), 1e-13 * max_abs(MR));
  EXPECT_LE(max_abs(beam.bending_stiffness() - K), 1e-13 * max_abs(K));
}

// (b) Structure. Symmetry holds to the round-off of a few products (1e-14 of the
// largest entry); skew-symmetry of G likewise; M positive definite by Cholesky.
TEST(TimoshenkoBeam, SymmetryAndDefiniteness) {
  for (const GyroscopicForm gyro : {GyroscopicForm::consistent, GyroscopicForm::lumped})
    for (const bool shear : {false, true}) {
      const LocalMatrices lm = make_beam(0.12, {0.06, 0.03}, shear, gyro, 1e-4).local_matrices({});
      ASSERT_EQ(lm.K.rows(), 12);
      ASSERT_EQ(lm.G.rows(), 12);
      EXPECT_LE(max_abs(lm.K - lm.K.transpose()), 1e-14 * max_abs(lm.K));
      EXPECT_LE(max_abs(lm.M - lm.M.transpose()), 1e-14 * max_abs(lm.M));
      EXPECT_LE(max_abs(lm.G + lm.G.transpose()), 1e-14 * max_abs(lm.G));
      EXPECT_LE(max_abs(lm.Ci - lm.Ci.transpose()), 1e-14 * max_abs(lm.Ci));
      EXPECT_LE(max_abs(lm.Ki + lm.Ki.transpose()), 1e-14 * max_abs(lm.Ki));
      EXPECT_GT(max_abs(lm.G), 0.0);
      const Eigen::LLT<Matrix> llt(lm.M);
      EXPECT_EQ(llt.info(), Eigen::Success) << "shear " << shear;
      EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix>(lm.M).eigenvalues().minCoeff(), 0.0);
    }
}

// Rigid-body motions of a free element, node a at x = 0 and node b at x = L.
struct RigidMotions {
  Vector axial = Vector::Zero(12), torsion = Vector::Zero(12), y = Vector::Zero(12), z = Vector::Zero(12),
         about_z = Vector::Zero(12), about_y = Vector::Zero(12);
  explicit RigidMotions(Real L) {
    for (Index n = 0; n < 2; ++n) {
      const Real x = static_cast<Real>(n) * L;
      axial(idx(n, Dof::u)) = 1;
      torsion(idx(n, Dof::rx)) = 1;
      y(idx(n, Dof::v)) = 1;
      z(idx(n, Dof::w)) = 1;
      about_z(idx(n, Dof::v)) = x;  // rotation about +z: v = x, rz = dv/dx = 1
      about_z(idx(n, Dof::rz)) = 1;
      about_y(idx(n, Dof::w)) = -x;  // rotation about +y: w = −x, ry = −dw/dx = 1
      about_y(idx(n, Dof::ry)) = 1;
    }
  }
};

// (c) Rigid-body motions cost no strain energy and carry the element's mass and
// inertia. K·r is a cancellation of terms as large as ‖K‖·‖r‖, so it is zero to
// round-off: 1e-13·‖K‖·‖r‖ (a few ulps per entry, far below any wrong coefficient,
// which would give O(1) relative). Kinetic-energy sums: 1e-13 relative.
TEST(TimoshenkoBeam, RigidBodyMotionsAreStrainFreeAndCarryTheMass) {
  const Real L = 0.15, d = 0.05, di = 0.02;
  const Real A = pi / 4.0 * (d * d - di * di), I = pi / 64.0 * (std::pow(d, 4) - std::pow(di, 4));
  const RigidMotions r(L);
  for (const bool shear : {false, true}) {
    const LocalMatrices lm = make_beam(L, {d, di}, shear).local_matrices({});
    const Real kn = max_abs(lm.K);
    for (const Vector* q : {&r.axial, &r.torsion, &r.y, &r.z, &r.about_z, &r.about_y})
      EXPECT_LE((lm.K * *q).cwiseAbs().maxCoeff(), 1e-13 * kn * q->cwiseAbs().maxCoeff()) << "shear " << shear;
    const Real m = rho * A * L;
    EXPECT_NEAR(r.y.dot(lm.M * r.y), m, 1e-13 * m);
    EXPECT_NEAR(r.z.dot(lm.M * r.z), m, 1e-13 * m);
    EXPECT_NEAR(r.axial.dot(lm.M * r.axial), m, 1e-13 * m);
    EXPECT_NEAR(r.torsion.dot(lm.M * r.torsion), rho * 2 * I * L, 1e-13 * rho * I * L);
    // Rotation about an end: ∫ρA x² dx + ρI·L (translation plus rotary inertia).
    const Real j_end = rho * A * L * L * L / 3.0 + rho * I * L;
    EXPECT_NEAR(r.about_z.dot(lm.M * r.about_z), j_end, 1e-13 * j_end);
    EXPECT_NEAR(r.about_y.dot(lm.M * r.about_y), j_end, 1e-13 * j_end);
  }
}

// (d) One element is exact for a cantilever with an end load: the Timoshenko tip
// deflection PL³/(3EI) + PL/(κGA) and rotation PL²/(2EI). The element is stubby
// (L/d = 2, Φ ≈ 0.55) so the shear part is about 14 % of the deflection. Tolerance
// 1e-12 relative: a 6×6 solve, condition number ~1e3.
TEST(TimoshenkoBeam, CantileverTipLoadIsExact) {
  const Real L = 0.1, d = 0.05, P = 1000.0;
  const TimoshenkoBeam beam = make_beam(L, {d, 0.0}, true);
  const Real I = pi * std::pow(d, 4) / 64.0, A = pi * d * d / 4.0;
  const Real kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
  const Real tip = P * L * L * L / (3.0 * E * I) + P * L / (kappa * mat.G * A);
  const Real slope = P * L * L / (2.0 * E * I);
  ASSERT_GT(P * L / (kappa * mat.G * A), 0.1 * tip);

  const Matrix Kbb = beam.local_matrices({}).K.bottomRightCorner(6, 6);  // node a clamped
  const Eigen::PartialPivLU<Matrix> lu(Kbb);
  Vector f = Vector::Zero(6);
  f(static_cast<Index>(Dof::v)) = P;
  Vector q = lu.solve(f);
  EXPECT_NEAR(q(static_cast<Index>(Dof::v)), tip, 1e-12 * tip);
  EXPECT_NEAR(q(static_cast<Index>(Dof::rz)), slope, 1e-12 * slope);  // rz = +dv/dx
  EXPECT_NEAR(q(static_cast<Index>(Dof::w)), 0.0, 1e-12 * tip);
  EXPECT_NEAR(q(static_cast<Index>(Dof::ry)), 0.0, 1e-12 * slope);

  f.setZero();
  f(static_cast<Index>(Dof::w)) = P;
  q = lu.solve(f);
  EXPECT_NEAR(q(static_cast<Index>(Dof::w)), tip, 1e-12 * tip);
  EXPECT_NEAR(q(static_cast<Index>(Dof::ry)), -slope, 1e-12 * slope);  // ry = −dw/dx
  EXPECT_NEAR(q(static_cast<Index>(Dof::v)), 0.0, 1e-12 * tip);
  EXPECT_NEAR(q(static_cast<Index>(Dof::rz)), 0.0, 1e-12 * slope);

  // And without shear, the Euler–Bernoulli value PL³/(3EI).
  const Matrix Keb = make_beam(L, {d, 0.0}, false).local_matrices({}).K.bottomRightCorner(6, 6);
  f.setZero();
  f(static_cast<Index>(Dof::v)) = P;
  q = Eigen::PartialPivLU<Matrix>(Keb).solve(f);
  const Real tip_eb = P * L * L * L / (3.0 * E * I);
  EXPECT_NEAR(q(static_cast<Index>(Dof::v)), tip_eb, 1e-12 * tip_eb);
}

// (e) The element spinning in a rigid tilt behaves like a disk of polar inertia
// ρI_pL: a rigid disk has G(rz, ry) = −J_P, so q_xyᵀ·G·q_xz = −ρI_pL for the rigid
// tilt q_xy (v = x, rz = 1) and q_xz (w = −x, ry = 1). True for the consistent G
// (the shape functions reproduce a uniform rotation) and, by construction, for the
// lumped one. Tolerance 1e-13 relative (sum of a few products).
TEST(TimoshenkoBeam, RigidTiltGyroscopicCouplingIsPolarInertia) {
  const Real L = 0.2, d = 0.05, di = 0.03;
  const Real Ip = pi / 32.0 * (std::pow(d, 4) - std::pow(di, 4));
  const RigidMotions r(L);
  for (const GyroscopicForm gyro : {GyroscopicForm::consistent, GyroscopicForm::lumped})
    for (const bool shear : {false, true}) {
      const Matrix G = make_beam(L, {d, di}, shear, gyro).local_matrices({}).G;
      const Real jp = rho * Ip * L;
      EXPECT_NEAR(r.about_z.dot(G * r.about_y), -jp, 1e-13 * jp) << "shear " << shear;
      EXPECT_NEAR(r.about_y.dot(G * r.about_z), jp, 1e-13 * jp) << "shear " << shear;
      // No gyroscopic coupling for translations or within one plane.
      EXPECT_NEAR(r.y.dot(G * r.z), 0.0, 1e-13 * jp);
      EXPECT_NEAR(r.about_z.dot(G * r.about_z), 0.0, 1e-13 * jp);
    }
  // The lumped form puts ρI_pL/2 on each node: G(rz_a, ry_a) = −ρI_pL/2.
  const Matrix G = make_beam(L, {d, di}, true, GyroscopicForm::lumped).local_matrices({}).G;
  EXPECT_NEAR(G(idx(0, Dof::rz), idx(0, Dof::ry)), -rho * Ip * L / 2, 1e-14 * rho * Ip * L);
  EXPECT_NEAR(G(idx(1, Dof::ry), idx(1, Dof::rz)), rho * Ip * L / 2, 1e-14 * rho * Ip * L);
  EXPECT_EQ(G(idx(0, Dof::rz), idx(1, Dof::ry)), 0.0);
  EXPECT_EQ(G(idx(0, Dof::v), idx(0, Dof::w)), 0.0);

  // A non-rotating beam has no gyroscopic matrix and no rotating damping.
  const LocalMatrices still = make_beam(L, {d, di}, true, GyroscopicForm::consistent, 1e-4, false).local_matrices({});
  EXPECT_TRUE(still.G.size() == 0 || still.G.isZero(0.0));
  EXPECT_TRUE(still.Ci.size() == 0 || still.Ci.isZero(0.0));
  EXPECT_TRUE(still.Ki.size() == 0 || still.Ki.isZero(0.0));
}

// (f) Cowper (1966), Table 1, hollow circle: κ = 6(1+ν)(1+m²)²/((7+6ν)(1+m²)² +
// (20+12ν)m²), m = d_i/d_o. Solid: 6(1+ν)/(7+6ν) (0.8864 for ν = 0.3); thin tube:
// 2(1+ν)/(4+3ν) (0.5306). κ(m) = κ(1/m), so κ is flat at m = 1 and m = 0.9999 is
// within ~1e-8 of the limit; tolerance 1e-7.
TEST(TimoshenkoBeam, CowperShearCoefficient) {
  for (const Real n : {0.0, 0.25, 0.3, 0.45}) {
    EXPECT_NEAR(CircularSection({0.05, 0.0}).cowper_shear_coefficient(n), 6 * (1 + n) / (7 + 6 * n), 1e-15);
    EXPECT_NEAR(CircularSection({0.05, 0.9999 * 0.05}).cowper_shear_coefficient(n), 2 * (1 + n) / (4 + 3 * n), 1e-7);
  }
  // Four-digit hand values, so half a unit in the last digit.
  EXPECT_NEAR(CircularSection({0.05, 0.0}).cowper_shear_coefficient(0.3), 0.8864, 5e-5);
  EXPECT_NEAR(CircularSection({0.05, 0.04999}).cowper_shear_coefficient(0.3), 0.5306, 5e-5);
  // Section properties: a hollow section is the solid minus its bore.
  const CircularSection s{0.05, 0.03};
  EXPECT_NEAR(s.area(), pi * (0.05 * 0.05 - 0.03 * 0.03) / 4, 1e-18);
  EXPECT_NEAR(s.second_moment(), pi * (std::pow(0.05, 4) - std::pow(0.03, 4)) / 64, 1e-22);
  EXPECT_NEAR(s.polar_moment(), 2 * s.second_moment(), 1e-22);
}

// (g) Stiffness-proportional material damping β: C_i = β·K, and the circulatory
// stiffness couples the planes as K_i(xy, xz) = β·K_b·S, K_i(xz, xy) = −β·S·K_b.
// Check against the published Timoshenko bending stiffness and the physical
// property that a deflected shape whirling forward with the shaft (frozen in the
// rotating frame) feels no rotating damping. Tolerances 1e-13 relative (round-off).
TEST(TimoshenkoBeam, MaterialDampingIsStiffnessProportional) {
  const Real L = 0.1, d = 0.05, beta = 2e-4, W = 300.0;
  const TimoshenkoBeam beam = make_beam(L, {d, 0.0}, true, GyroscopicForm::consistent, beta);
  const LocalMatrices lm = beam.local_matrices({});
  ASSERT_EQ(lm.Ci.rows(), 12);
  ASSERT_EQ(lm.Ki.rows(), 12);
  EXPECT_LE(max_abs(lm.Ci - beta * lm.K), 1e-15 * max_abs(beta * lm.K));

  const Real phi = solid_phi(d, L), I = pi * std::pow(d, 4) / 64.0;
  Matrix kb(4, 4);
  kb << 12, 6 * L, -12, 6 * L,                              //
      6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,  //
      -12, -6 * L, 12, -6 * L,                              //
      6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L;
  kb *= E * I / ((1 + phi) * L * L * L);
  const Matrix S = slope_flip();
  const Matrix xy_xz = plane_block(lm.Ki, Dof::v, Dof::rz, Dof::w, Dof::ry);
  const Matrix xz_xy = plane_block(lm.Ki, Dof::w, Dof::ry, Dof::v, Dof::rz);
  EXPECT_LE(max_abs(xy_xz - beta * kb * S), 1e-13 * beta * max_abs(kb));
  EXPECT_LE(max_abs(xz_xy + beta * S * kb), 1e-13 * beta * max_abs(kb));
  EXPECT_NEAR(lm.Ki(idx(0, Dof::v), idx(0, Dof::w)), beta * 12 * E * I / ((1 + phi) * L * L * L),
              1e-13 * beta * kb(0, 0));
  // No circulatory terms within a plane, nor in axial or torsion.
  EXPECT_EQ(max_abs(xy_block(lm.Ki)), 0.0);
  EXPECT_EQ(max_abs(xz_block(lm.Ki)), 0.0);
  EXPECT_EQ(lm.Ki.row(idx(0, Dof::u)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(lm.Ki.row(idx(1, Dof::rx)).cwiseAbs().maxCoeff(), 0.0);

  // A deflection shape a(x) in the x–y plane whirling forward at the spin speed:
  // r = v + i·w = a(x)·e^{iΩt}, i.e. complex amplitudes V = a, W = −i·a, and for the
  // slopes rz = a', ry = −dw/dx = i·a'. Force (iΩ·C_i + Ω·K_i)·Q must vanish.
  ComplexVector Q = ComplexVector::Zero(12);
  const Complex i1(0, 1);
  const std::array<Real, 4> a{0.0, 0.01, 1e-3, -0.02};  // (v_a, rz_a, v_b, rz_b), any shape
  for (Index n = 0; n < 2; ++n) {
    const Real disp = a[static_cast<std::size_t>(2 * n)];
    const Real rot = a[static_cast<std::size_t>(2 * n + 1)];
    Q(idx(n, Dof::v)) = disp;
    Q(idx(n, Dof::w)) = -i1 * disp;
    Q(idx(n, Dof::rz)) = rot;
    Q(idx(n, Dof::ry)) = i1 * rot;
  }
  const ComplexVector force = (i1 * W * lm.Ci.cast<Complex>() + W * lm.Ki.cast<Complex>()) * Q;
  const Real scale = W * beta * max_abs(lm.K) * Q.cwiseAbs().maxCoeff();
  EXPECT_LE(force.cwiseAbs().maxCoeff(), 1e-13 * scale);
  // The same shape whirling backward is damped: the force is of the order of the scale.
  const ComplexVector Qb = Q.conjugate();  // V, rz real: W → +i·a, ry → −i·a'
  const ComplexVector fb = (i1 * W * lm.Ci.cast<Complex>() + W * lm.Ki.cast<Complex>()) * Qb;
  EXPECT_GT(fb.cwiseAbs().maxCoeff(), 1e-3 * scale);

  // β = 0: no rotating damping matrices at all.
  const LocalMatrices none = make_beam(L, {d, 0.0}, true).local_matrices({});
  EXPECT_TRUE(none.Ci.size() == 0 || none.Ci.isZero(0.0));
  EXPECT_TRUE(none.Ki.size() == 0 || none.Ki.isZero(0.0));
}

}  // namespace
}  // namespace feran::test_timoshenko_beam

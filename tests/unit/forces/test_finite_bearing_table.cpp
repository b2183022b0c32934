// The finite-length bearing's table: the two facts of the Reynolds equation it rests
// on (the force turns with the journal and scales with the film's drive), checked on
// the solver itself; the table against the solver where both solve the same discrete
// problem, against a four times finer grid where they do not, its Jacobian against
// its own differences, and the fall-back to the solver beyond it.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <feran/forces/finite_bearing.hpp>
#include <feran/forces/finite_bearing_table.hpp>
#include <feran/forces/fluid_film_bearing.hpp>

namespace feran::test_finite_bearing_table {
namespace {

constexpr Real D = 0.04, c = 40e-6, mu = 0.02;
const JournalBearingGeometry half{.diameter = D, .length = 0.5 * D, .clearance = c, .viscosity = mu};

Eigen::Matrix2d rotation(Real a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

FiniteBearingGrid exact(FiniteBearingGrid grid) {
  grid.evaluation = FilmEvaluation::exact;
  return grid;
}

TEST(FiniteBearingTable, TheSolversForceTurnsWithTheJournalAndScalesWithTheDrive) {
  // The table's reduction: the discrete Reynolds equation's right-hand side is
  // |u|·sin(θ − angle u) with u = Ω·x/c + 2·J·v/c, and the film thickness depends on x
  // alone. Turning x and v by a whole number of cells turns the force with them; scaling
  // u by s > 0 (Ω and v together) scales P and the force by s, the cavitated region
  // unchanged. Both exactly, up to round-off (1e-12 of |f|).
  const FiniteBearingGrid grid{.circumferential = 48, .axial = 6};
  const Eigen::Vector2d x(0.55 * c, -0.3 * c), v(0.08 * c * 300, -0.05 * c * 300);
  const FilmForce f = finite_bearing_force(half, grid, 300.0, x, v);
  for (const int cells : {1, 7, 30}) {
    const Eigen::Matrix2d R = rotation(2 * pi * cells / grid.circumferential);
    const FilmForce g = finite_bearing_force(half, grid, 300.0, R * x, R * v);
    EXPECT_LT((g.f - R * f.f).norm(), 1e-12 * f.f.norm()) << cells;
    EXPECT_LT((g.dfdx - R * f.dfdx * R.transpose()).norm(), 1e-11 * f.dfdx.norm()) << cells;
  }
  for (const Real s : {0.01, 3.7}) {
    const FilmForce g = finite_bearing_force(half, grid, 300.0 * s, x, v * s);
    EXPECT_LT((g.f - s * f.f).norm(), 1e-12 * s * f.f.norm()) << s;
  }
}

TEST(FiniteBearingTable, EqualsTheSolverWithinItsMeasuredErrorWhereBothSolveTheSameProblem) {
  // Where the drive u points along a grid line, the solver's discrete problem is the
  // table's (which solves it in the frame of u): the table's error there is its
  // interpolation error alone, which the table measures at its cells' centres (where
  // a Hermite interpolant's error is largest) when built. At 400 random states within
  // the table, both conditions and two lengths: the force within 1.5 × that measure
  // (it is measured at the centres, not everywhere), and that measure below 0.6 %
  // (measured for the default layout: 0.23–0.33 % with Reynolds' condition, 0.52–0.55 %
  // with Gümbel's, whose positive part has a kink where the pressure changes sign).
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> U(0.0, 1.0);
  for (const Real ld : {0.5, 1.0})
    for (const Cavitation cav : {Cavitation::reynolds, Cavitation::gumbel}) {
      const FiniteBearingGrid grid{.circumferential = 72, .axial = 8, .cavitation = cav};
      const auto table = FiniteBearingTable::shared(ld, grid);
      SCOPED_TRACE(testing::Message() << "L/D " << ld << ", cavitation " << static_cast<int>(cav));
      EXPECT_TRUE(table->usable());
      EXPECT_LT(table->error().force, 6e-3);
      const JournalBearingGeometry g{.diameter = D, .length = ld * D, .clearance = c, .viscosity = mu};
      Real worst = 0;
      for (int k = 0; k < 100; ++k) {
        // Ω = 0 and a squeeze velocity v = c·J⁻¹u/2 with u along grid line k.
        const Real drive = 2 * pi * (k % 72) / 72, speed = 0.0, size = 50.0 + 400 * U(random);
        const Eigen::Vector2d u = size * Eigen::Vector2d(std::cos(drive), std::sin(drive));
        const Eigen::Vector2d v = 0.5 * c * Eigen::Vector2d(u(1), -u(0));
        const Real eps = 0.95 * std::sqrt(U(random)), a = 2 * pi * U(random);
        const Eigen::Vector2d x = eps * c * Eigen::Vector2d(std::cos(a), std::sin(a));
        FilmForce t;
        ASSERT_TRUE(table->force(g, speed, x, v, t));
        const FilmForce s = finite_bearing_force(g, grid, speed, x, v);
        worst = std::max(worst, (t.f - s.f).norm() / s.f.norm());
      }
      EXPECT_LT(worst, 1.5 * table->error().force);
    }
}

TEST(FiniteBearingTable, IsAsCloseToAFinerGridAsTheSolverItself) {
  // Where the drive does not point along a grid line, the solver's and the table's
  // grids differ by a turn of less than a cell: both are second-order discretisations
  // of the same Reynolds equation, and the solver on 288 × 16 cells stands for the
  // continuous one. At states of a whirling, squeezing journal up to ε = 0.85, the
  // table (from 72 × 8 cells) is within 1.2 × the 72 × 8 solver's own distance to it,
  // plus 2e-4 for the table's interpolation (measured: the table is the closer one at
  // most states, its Jacobian by a factor 3 to 6).
  const FiniteBearingGrid coarse{.circumferential = 72, .axial = 8, .evaluation = FilmEvaluation::table},
      fine{.circumferential = 288, .axial = 16};
  const Real speed = 500.0;
  Real table_force = 0, solver_force = 0, table_jacobian = 0, solver_jacobian = 0;
  for (const Real eps : {0.2, 0.5, 0.85})
    for (const Real a : {0.3, 2.0, 4.4}) {
      const Eigen::Vector2d x = eps * c * Eigen::Vector2d(std::cos(a), std::sin(a));
      const Eigen::Vector2d v = 0.2 * c * speed * Eigen::Vector2d(std::cos(3 * a), std::sin(2 * a));
      const FilmForce reference = finite_bearing_force(half, fine, speed, x, v);
      const FilmForce solver = finite_bearing_force(half, coarse, speed, x, v);
      const FilmForce table = film_force(half, FilmTheory::finite_length, speed, x, v, coarse);
      table_force = std::max(table_force, (table.f - reference.f).norm() / reference.f.norm());
      solver_force = std::max(solver_force, (solver.f - reference.f).norm() / reference.f.norm());
      table_jacobian = std::max(table_jacobian, (table.dfdx - reference.dfdx).norm() / reference.dfdx.norm());
      solver_jacobian = std::max(solver_jacobian, (solver.dfdx - reference.dfdx).norm() / reference.dfdx.norm());
    }
  EXPECT_LT(table_force, 1.2 * solver_force + 2e-4);
  EXPECT_LT(table_jacobian, 1.2 * solver_jacobian + 2e-4);
}

TEST(FiniteBearingTable, JacobianIsTheDerivativeOfTheTabulatedForce) {
  // The Jacobian is the interpolant's own derivative, carried through the turn into
  // the drive's frame and the scaling by |u|: central differences of the tabulated
  // force (steps 1e-7 c and 1e-7 cΩ, inside a cell) agree to 1e-6 of the block's norm.
  const FiniteBearingGrid grid{.circumferential = 72, .axial = 8, .evaluation = FilmEvaluation::table};
  const Real speed = 400.0, h = 1e-7 * c, hv = 1e-7 * c * speed;
  const auto force = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& v) {
    return film_force(half, FilmTheory::finite_length, speed, x, v, grid);
  };
  for (const auto& [x, v] :
       {std::pair{Eigen::Vector2d(0.3 * c, -0.2 * c), Eigen::Vector2d(0.05 * c * speed, 0.02 * c * speed)},
        std::pair{Eigen::Vector2d(-0.6 * c, 0.5 * c), Eigen::Vector2d(-0.1 * c * speed, 0.0)},
        std::pair{Eigen::Vector2d(1e-3 * c, 0.0), Eigen::Vector2d(0.0, 0.0)}}) {
    const FilmForce f = force(x, v);
    Eigen::Matrix2d dx, dv;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      e(k) = h;
      dx.col(k) = (force(x + e, v).f - force(x - e, v).f) / (2 * h);
      e(k) = hv;
      dv.col(k) = (force(x, v + e).f - force(x, v - e).f) / (2 * hv);
    }
    EXPECT_LT((f.dfdx - dx).norm(), 1e-6 * f.dfdx.norm());
    EXPECT_LT((f.dfdv - dv).norm(), 1e-6 * f.dfdv.norm());
  }
}

TEST(FiniteBearingTable, BeyondItsEccentricityTheSolverAnswersAndTablesAreShared) {
  const FiniteBearingGrid grid{.circumferential = 48, .axial = 6, .evaluation = FilmEvaluation::table};
  const Eigen::Vector2d x(0.0, 0.97 * c), v(0.01 * c * 300, 0.0);
  const FilmForce t = film_force(half, FilmTheory::finite_length, 300.0, x, v, grid);
  const FilmForce s = finite_bearing_force(half, grid, 300.0, x, v);
  EXPECT_EQ(t.f, s.f);
  EXPECT_EQ(t.dfdx, s.dfdx);
  // Inside, the table answers, its largest pressure within the table's measure of it.
  const FilmForce inside = film_force(half, FilmTheory::finite_length, 300.0, 0.5 * x, v, grid);
  const FilmForce solved = film_force(half, FilmTheory::finite_length, 300.0, 0.5 * x, v, exact(grid));
  EXPECT_NE(inside.f, solved.f);
  const auto table = FiniteBearingTable::shared(0.5, grid);
  EXPECT_LT(std::abs(inside.peak_pressure - solved.peak_pressure),
            1.5 * table->error().peak_pressure * solved.peak_pressure);
  // The automatic evaluation: the table along trajectories only.
  FiniteBearingGrid automatic = grid;
  automatic.evaluation = FilmEvaluation::automatic;
  EXPECT_EQ(film_force(half, FilmTheory::finite_length, 300.0, 0.5 * x, v, automatic, true).f, inside.f);
  EXPECT_EQ(film_force(half, FilmTheory::finite_length, 300.0, 0.5 * x, v, automatic, false).f, solved.f);
  // One table per shape: L/D, grid and cavitation, not the size, clearance or oil.
  EXPECT_EQ(FiniteBearingTable::shared(0.5, grid), FiniteBearingTable::shared(0.5, grid));
  EXPECT_NE(FiniteBearingTable::shared(0.5, grid), FiniteBearingTable::shared(0.6, grid));
  // A layout too coarse for the bound is not used.
  const FiniteBearingTable rough(0.5, grid, {.eccentricities = 3, .angles = 4, .max_eccentricity = 0.95});
  EXPECT_FALSE(rough.usable());
}

}  // namespace
}  // namespace feran::test_finite_bearing_table

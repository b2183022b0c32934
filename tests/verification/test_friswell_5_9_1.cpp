// Friswell, Penny, Garvey & Lees (2010), "Dynamics of Rotating Machines", Example
// 5.9.1 (model in tests/support/test_models.hpp): lateral natural frequencies at rest
// and at 4000 rpm, as published. The book rounds to 5 significant digits and ROSS
// checks the same values to 1e-3; we require 0.1 % as the issue asks (observed
// deviations are below 0.01 %).
#include <gtest/gtest.h>

#include <feran/analyses/modal/modal.hpp>

#include "test_models.hpp"

namespace feran::test_friswell_5_9_1 {
namespace {

std::vector<const Mode*> lateral(const ModalResult& r) {
  std::vector<const Mode*> out;
  for (const Mode& m : r.modes)
    if (m.type == ModeType::lateral) out.push_back(&m);
  return out;
}

TEST(Friswell591, FrequenciesAtRest) {
  const ModalResult r = run_modal(test::friswell_5_9_1(), 0.0);
  const auto modes = lateral(r);
  ASSERT_GE(modes.size(), 6u);
  const Real expected[] = {13.792, 43.661, 114.082};
  for (int i = 0; i < 3; ++i) {
    // At rest each frequency is a forward/backward pair.
    for (int j = 0; j < 2; ++j)
      EXPECT_NEAR(modes[static_cast<std::size_t>(2 * i + j)]->frequency_hz, expected[i], 1e-3 * expected[i]);
  }
}

TEST(Friswell591, FrequenciesAt4000rpm) {
  const ModalResult r = run_modal(test::friswell_5_9_1(), 4000.0 * 2 * pi / 60);
  const auto modes = lateral(r);
  ASSERT_GE(modes.size(), 6u);
  const Real expected[] = {13.591, 13.974, 40.075, 46.909, 95.524, 131.637};
  const Whirl whirl[] = {Whirl::backward, Whirl::forward};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(modes[static_cast<std::size_t>(i)]->frequency_hz, expected[i], 1e-3 * expected[i]);
    EXPECT_EQ(modes[static_cast<std::size_t>(i)]->whirl, whirl[i % 2]) << "mode " << i;
  }
}

// Invariant: each eigenpair satisfies (p²M + pD + K)φ = 0. The residual is measured
// against the size of the terms, ‖p²Mφ‖ + ‖pDφ‖ + ‖Kφ‖; backward-stable QR gives
// ~1e-13 here, 1e-9 allows for the condition of the state matrix.
TEST(Friswell591, EigenpairResidual) {
  const Model model = test::friswell_5_9_1();
  const Real speed = 4000.0 * 2 * pi / 60;
  const ModalSolver solver(model);
  const ModalResult r = solver.solve(speed);
  const SystemMatrices sys = solver.assembler().at(speed);
  const Eigen::SparseMatrix<Complex> M = sys.M.cast<Complex>(), D = sys.damping(speed).cast<Complex>(),
                                     K = sys.stiffness(speed).cast<Complex>();
  for (const Mode& mode : r.modes) {
    const Complex p = mode.eigenvalue;
    const ComplexVector& x = mode.reduced_shape;
    const ComplexVector res = (p * p) * (M * x) + p * (D * x) + K * x;
    const Real scale = std::abs(p * p) * (M * x).norm() + std::abs(p) * (D * x).norm() + (K * x).norm();
    EXPECT_LT(res.norm(), 1e-9 * scale) << mode.frequency_hz << " Hz";
  }
}

// The sparse shift-invert solver finds the same lowest modes as the dense QR.
TEST(Friswell591, SparseSolverAgreesWithDense) {
  const Model model = test::friswell_5_9_1(48);
  const Real speed = 4000.0 * 2 * pi / 60;
  ModalOptions dense, sparse;
  dense.solver = EigenSolver::dense;
  sparse.solver = EigenSolver::sparse;
  sparse.n_modes = 10;
  const ModalResult a = run_modal(model, speed, dense), b = run_modal(model, speed, sparse);
  ASSERT_TRUE(b.info.converged()) << b.info.message;
  ASSERT_EQ(b.modes.size(), 10u);
  for (std::size_t i = 0; i < b.modes.size(); ++i) {
    // Arnoldi tolerance 1e-10 on the shift-inverted values: eigenvalues to ~1e-9 relative.
    EXPECT_NEAR(b.modes[i].frequency_hz, a.modes[i].frequency_hz, 1e-8 * a.modes[i].frequency_hz);
    EXPECT_EQ(b.modes[i].whirl, a.modes[i].whirl);
  }
}

}  // namespace
}  // namespace feran::test_friswell_5_9_1

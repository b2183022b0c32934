// A free rigid disk spinning at Ω: its nutation is a forward whirl at (J_P/J_A)·Ω,
// its other motions are rigid-body modes at zero frequency.
#include <gtest/gtest.h>

#include <feran/analyses/modal/modal.hpp>

#include "test_models.hpp"

namespace feran::test_free_disk {
namespace {

TEST(FreeDisk, NutatesForwardAtPolarOverTransverseRatio) {
  Model model;
  model.free_motions = {FreeMotion::axial, FreeMotion::torsion, FreeMotion::lateral};
  const Index n = test::add_node(model, 0.0);
  const Real mass = 2.0, Ja = 0.01, Jp = 0.018;
  test::add_body(model, n, mass, Ja, Jp);
  for (Real speed : {10.0, 100.0, 1000.0}) {
    const ModalResult r = run_modal(model, speed);
    int nutation = 0, rigid_zero = 0;
    for (const Mode& mode : r.modes) {
      EXPECT_TRUE(mode.rigid_body);  // no spring: nothing deforms
      if (mode.eigenvalue == Complex(0.0)) {
        ++rigid_zero;
        continue;
      }
      ++nutation;
      // 1e-10 relative: the 12×12 state matrix is exact; round-off only.
      EXPECT_NEAR(mode.eigenvalue.imag(), Jp / Ja * speed, 1e-10 * Jp / Ja * speed);
      EXPECT_NEAR(mode.eigenvalue.real(), 0.0, 1e-10 * speed);
      EXPECT_EQ(mode.whirl, Whirl::forward);
      EXPECT_NEAR(mode.directivity, 1.0, 1e-9);
    }
    EXPECT_EQ(nutation, 1);
    // u, v, w, rx and the precession of the tilt: 5 zero modes (one per Im p ≥ 0 root
    // of each Jordan pair), all reported as rigid at exactly zero frequency.
    EXPECT_GE(rigid_zero, 5);
  }
}

}  // namespace
}  // namespace feran::test_free_disk

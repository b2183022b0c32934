#include <gtest/gtest.h>

#include <feran/analyses/modal/modal.hpp>

#include "test_models.hpp"

namespace feran {
namespace {

// Lateral natural frequencies of Friswell et al. (2010), Example 5.9.1 [Hz].
TEST(Friswell591, PrintFrequencies) {
  const Model m = test::friswell_5_9_1();
  for (Real rpm : {0.0, 4000.0}) {
    const ModalResult r = run_modal(m, rpm * 2 * pi / 60);
    for (const Mode& mode : r.modes) {
      if (mode.frequency_hz > 200) break;
      printf("%6.0f rpm %10.4f Hz D=%.2e %s %s %.3f rigid=%d\n", rpm, mode.frequency_hz,
             mode.damping_ratio, to_string(mode.whirl), to_string(mode.type), mode.directivity,
             mode.rigid_body);
    }
  }
}

}  // namespace
}  // namespace feran

// Linked into every test executable: OpenBLAS on one thread before any test runs, as
// in the command line and the Python module (feran/core/parallel.hpp says why).
#include <feran/core/parallel.hpp>

namespace {
const bool blas_single_threaded = [] {
  feran::single_threaded_blas();
  return true;
}();
}  // namespace

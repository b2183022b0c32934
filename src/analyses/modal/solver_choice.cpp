#include "solver_choice.hpp"

#include <algorithm>

namespace feran::detail {

// Constants fitted to single-threaded solve times of the lateral block of the
// Friswell et al. (2010) Example 5.9.1 rotor meshed with 6 to 99 elements (28 to 400
// DOF), asked for 4 to 40 modes, in its four forms: isotropic undamped (complex,
// Hermitian), isotropic damped (complex, general), anisotropic undamped (real,
// Hermitian) and anisotropic damped (real, general): 384 cases, each timed as the
// median of 21 solves. The fit (nonnegative, relative least squares) has a further
// term shared by both solvers, a constant and one proportional to DOF × modes (the
// matrices at the speed, the modes' classification), which cancels in the choice
// and is left out here. On those cases the choice is within 1.2 times the faster
// solver in 377 of 384 and at worst 1.48 times (a few tenths of a millisecond, where
// Arnoldi needed more than its first check): Arnoldi's convergence is not known in
// advance, the dense work is.

Real dense_cost(Index n, BlockForm form) {
  // a·n³ + b·n²: the reduction and QR (or the Hermitian eigensolver), and the
  // quadratic work of forming the dense matrices and the selected eigenvectors.
  struct Coefficients {
    Real a, b;
  };
  const Coefficients c = form.complex ? (form.hermitian ? Coefficients{1.16e-9, 4.1e-8} : Coefficients{2.06e-9, 2.5e-7})
                                      : (form.hermitian ? Coefficients{8.2e-9, 1.4e-7} : Coefficients{4.8e-9, 5.3e-7});
  const auto x = static_cast<Real>(n);
  return (c.a * x + c.b) * x * x;
}

Real arnoldi_cost(Index n, Index n_wanted, BlockForm form) {
  // State order N and the size m of the Krylov basis at the first convergence check
  // (sparse_state_eigen.cpp, sparse_complex_eigen.cpp, arnoldi.hpp); a complex
  // operation counts four real ones.
  const Index N = form.complex ? n : 2 * n;
  const Index nev = form.complex ? std::min<Index>(n - 1, n_wanted + 2) : std::min<Index>(2 * n - 2, 2 * n_wanted + 3);
  const auto m = static_cast<Real>(std::min<Index>(N, std::max<Index>(2 * nev + 1, 20)));
  const Real w = form.complex ? 4.0 : 1.0;
  const auto x = static_cast<Real>(N);
  // Gram–Schmidt against the basis, the Ritz values of the m×m Hessenberg matrix,
  // and the sparse LU with the operator's solves.
  return w * (9.7e-10 * x * m * m + 1.85e-9 * m * m * m + 5.2e-7 * x);
}

}  // namespace feran::detail

#pragma once
/// @file
/// Sensitivity of a study's quantities to its variables, from the sampled designs:
/// standardised regression coefficients (SRC) and their rank version (SRRC).
///
/// For a quantity y and the variables' unit coordinates t_j (so a log-scaled variable
/// counts by decades), the least-squares fit y ≈ b_0 + Σ b_j t_j gives
/// SRC_j = b_j σ(t_j) / σ(y): the change of y, in its standard deviations, for one
/// standard deviation of t_j. When R² of the fit is near 1 the SRC² add up to it and
/// rank the variables as variance shares would; a low R² says the quantity is not
/// linear in the variables. SRRC is the same fit on the ranks of y and t_j, for
/// quantities that change monotonically but not linearly (Saltelli et al. 2008,
/// sec. 1.2.3; Helton & Davis 2003).

#include <span>
#include <string>
#include <vector>

#include <feran/study/study.hpp>

namespace feran {

struct Sensitivity {
  std::string quantity;
  std::vector<Real> src;   ///< per variable
  Real r2 = 0;             ///< of the linear fit
  std::vector<Real> srrc;  ///< per variable, on ranks
  Real r2_ranks = 0;
  Index samples = 0;  ///< evaluated designs used
};

/// One entry per quantity, from the evaluated designs of @p evaluations; empty
/// vectors when there are fewer designs than variables + 2.
std::vector<Sensitivity> sensitivities(const StudySpec& study, std::span<const Evaluation> evaluations);

}  // namespace feran

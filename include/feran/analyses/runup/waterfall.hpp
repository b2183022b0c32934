#pragma once
/// @file
/// The waterfall of a run-up: the amplitude spectra of one DOF of a probe over
/// successive windows of its samples, against the speed at each window's middle. The
/// one definition the report and feran.plot draw (docs/report.md, "Run-up"; docs/python.md, feran.plot).

#include <cstddef>
#include <optional>
#include <vector>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/core/types.hpp>

namespace feran {

struct Waterfall {
  std::vector<Real> speeds;       ///< speed at each window's middle sample [rad/s]
  std::vector<Real> frequencies;  ///< k/(n·Δt), k = 0 … n/2 [Hz]
  /// Windows × frequencies: the amplitude of a sine at each frequency, in the DOF's
  /// unit (m or rad).
  Matrix amplitude;
  Index window_samples = 0;  ///< n
  Real sample_interval = 0;  ///< Δt, the median interval between samples [s]
};

/// The spectra of DOF @p dof of probe @p probe of @p result's samples: windows of
/// @p window seconds (default a twentieth of the run; at least 8 samples, at most all),
/// successive windows overlapping by the fraction @p overlap (0 ≤ overlap < 1); each
/// window's mean is removed and a Hann taper w_j = ½ − ½cos(2πj/(n−1)) applied, and
/// the amplitude at frequency k/(nΔt) is 2·|Σ_j w_j q_j e^(−2πijk/n)| / Σ_j w_j, so
/// that a sine of amplitude A on a frequency of the grid shows as A. Throws Error for a
/// run of fewer than 8 samples, a probe out of range or an overlap outside [0, 1).
Waterfall waterfall(const TransientResult& result, std::size_t probe, Dof dof, std::optional<Real> window = {},
                    Real overlap = 0.5);

}  // namespace feran

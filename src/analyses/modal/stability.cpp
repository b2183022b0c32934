#include <feran/analyses/modal/stability.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

// Symmetric to round-off and positive semidefinite (the smallest eigenvalue not below
// −1e-10 of the largest magnitude: rigid-body and free motions give zeros).
bool symmetric_semidefinite(const Matrix& A) {
  if (A.size() == 0) return true;
  const Real scale = A.cwiseAbs().maxCoeff();
  if (scale == 0) return true;
  if ((A - A.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) return false;
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(A, Eigen::EigenvaluesOnly);
  if (eig.info() != Eigen::Success) return false;
  const Vector& lambda = eig.eigenvalues();
  return lambda.minCoeff() >= -1e-10 * lambda.cwiseAbs().maxCoeff();
}

}  // namespace

bool energy_stable(const Model& linear, Real speed) {
  for (const Element& element : linear.elements) {
    if (element.frequency_dependent()) return false;
    const LocalMatrices lm = element.local_matrices(OperatingPoint(speed, speed));
    if (speed != 0 && lm.Ki.size() != 0 && lm.Ki.cwiseAbs().maxCoeff() > 0) return false;
    if (!symmetric_semidefinite(lm.K) || !symmetric_semidefinite(lm.C) || !symmetric_semidefinite(lm.Ci))
      return false;
  }
  return true;
}

StabilityPoint stability_at(const Model& model, Real speed) {
  StabilityPoint out;
  out.speed = speed;
  const bool supported = has_supports(model);
  if (!(speed > 0) && needs_speed(model)) {
    out.known = false;
    out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
    out.message = "at rest an oil film carries nothing";
    return out;
  }
  try {
    const Model linear_copy = supported ? linearised(model) : Model{};
    const Model& linear = supported ? linear_copy : model;
    if (energy_stable(linear, speed)) {
      out.by_energy = true;
      out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
      return out;
    }
    ModalOptions options;
    options.shapes = false;
    const ModalResult r = run_modal(model, speed, options);
    if (!r.info.converged()) {
      out.known = false;
      out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
      out.message = fmt::format("the modal analysis failed: {}", r.info.message);
      return out;
    }
    Real largest = 0;
    for (const Mode& m : r.modes) largest = std::max(largest, std::abs(m.eigenvalue));
    out.growth_rate = -std::numeric_limits<Real>::infinity();
    for (const Mode& m : r.modes) {
      if (m.rigid_body) continue;
      if (m.eigenvalue.real() > out.growth_rate) {
        out.growth_rate = m.eigenvalue.real();
        out.frequency_hz = m.oscillatory ? m.frequency_hz : 0.0;
        out.divergence = !m.oscillatory;
      }
    }
    if (!std::isfinite(out.growth_rate)) out.growth_rate = 0;  // rigid-body modes only
    out.unstable = out.growth_rate > 1e-9 * largest;
    if (!out.unstable) out.divergence = false;
  } catch (const Error& e) {
    out.known = false;
    out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
    out.message = e.what();
  }
  return out;
}

}  // namespace feran

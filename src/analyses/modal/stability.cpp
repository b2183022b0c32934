#include <feran/analyses/modal/stability.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

// The modes whose eigenvalues decide (the lowest by |p|).
constexpr Index stability_modes = 24;

constexpr const char* at_rest = "at rest an oil film carries nothing";

// Symmetric to round-off and positive semidefinite (the smallest eigenvalue not below
// −1e-10 of the largest magnitude: rigid-body and free motions give zeros).
bool symmetric(const Matrix& A) {
  if (A.size() == 0) return true;
  return (A - A.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A.cwiseAbs().maxCoeff();
}

bool symmetric_semidefinite(const Matrix& A) {
  if (A.size() == 0) return true;
  const Real scale = A.cwiseAbs().maxCoeff();
  if (scale == 0) return true;
  if (!symmetric(A)) return false;
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(A, Eigen::EigenvaluesOnly);
  if (eig.info() != Eigen::Success) return false;
  const Vector& lambda = eig.eigenvalues();
  return lambda.minCoeff() >= -1e-10 * lambda.cwiseAbs().maxCoeff();
}

// The energy test of one element at @p speed: false when it may feed energy in.
bool energy_stable_element(const Element& element, Real speed) {
  if (element.frequency_dependent()) {
    // A passive support: its stiffness symmetric at every frequency of its tables,
    // positive semidefinite at rest, its damping symmetric positive semidefinite at
    // every frequency (it dissipates at each one). Sampled at 129 frequencies over
    // each table's range and at 0: between the knots of a table linear in frequency
    // the matrices are convex combinations, which keep these properties.
    std::vector<Real> frequencies{0.0, speed};
    for (const SpeedRange& range : element.frequency_ranges())
      for (int i = 0; i <= 128; ++i) frequencies.push_back(range.low + (range.high - range.low) * i / 128.0);
    for (const Real w : frequencies) {
      const LocalMatrices lm = element.local_matrices(OperatingPoint(speed, w));
      if (speed != 0 && lm.Ki.size() != 0 && lm.Ki.cwiseAbs().maxCoeff() > 0) return false;
      if (!symmetric_semidefinite(lm.C) || !symmetric_semidefinite(lm.Ci)) return false;
      if (w == 0.0 ? !symmetric_semidefinite(lm.K) : !symmetric(lm.K)) return false;
    }
    return true;
  }
  const LocalMatrices lm = element.local_matrices(OperatingPoint(speed, speed));
  if (speed != 0 && lm.Ki.size() != 0 && lm.Ki.cwiseAbs().maxCoeff() > 0) return false;
  return symmetric_semidefinite(lm.K) && symmetric_semidefinite(lm.C) && symmetric_semidefinite(lm.Ci);
}

// The modes whose eigenvalues decide, the growth rate and the verdict from them.
StabilityPoint from_modes(const ModalResult& r, Real speed) {
  StabilityPoint out;
  out.speed = speed;
  if (!r.info.converged())
    return StabilityPoint::unknown(speed, fmt::format("the modal analysis failed: {}", r.info.message));
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
  return out;
}

ModalOptions stability_modal_options() {
  ModalOptions options;
  options.shapes = false;
  options.n_modes = stability_modes;
  return options;
}

StabilityPoint by_energy(Real speed) {
  StabilityPoint out;
  out.speed = speed;
  out.by_energy = true;
  out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
  return out;
}

}  // namespace

bool energy_stable(const Model& linear, Real speed) {
  return std::all_of(linear.elements.begin(), linear.elements.end(),
                     [&](const Element& element) { return energy_stable_element(element, speed); });
}

StabilityScan::StabilityScan(const Model& linear, bool needs_speed) : linear_(linear), needs_speed_(needs_speed) {
  for (std::size_t i = 0; i < linear.elements.size(); ++i) {
    const Element& element = linear.elements[i];
    if (element.speed_dependent() || element.frequency_dependent()) {
      varying_.push_back(i);
      continue;
    }
    // At rest its K_i does not act; above it a non-zero K_i is circulatory at every
    // speed. The rest of the test does not depend on speed.
    constant_stable_ = constant_stable_ && energy_stable_element(element, 0.0);
    if (!constant_circulatory_) {
      const LocalMatrices lm = element.local_matrices(OperatingPoint(0.0, 0.0));
      constant_circulatory_ = lm.Ki.size() != 0 && lm.Ki.cwiseAbs().maxCoeff() > 0;
    }
  }
}

bool StabilityScan::energy_stable_at(Real speed) const {
  if (!constant_stable_ || (speed != 0 && constant_circulatory_)) return false;
  return std::all_of(varying_.begin(), varying_.end(),
                     [&](std::size_t i) { return energy_stable_element(linear_.elements[i], speed); });
}

const ModalSolver& StabilityScan::solver() const {
  std::call_once(solver_once_,
                 [&] { solver_ = std::make_shared<const ModalSolver>(linear_, stability_modal_options()); });
  return *solver_;
}

StabilityPoint StabilityScan::at(Real speed) const {
  if (!(speed > 0) && needs_speed_) return StabilityPoint::unknown(speed, at_rest);
  try {
    if (energy_stable_at(speed)) return by_energy(speed);
    return from_modes(solver().solve(speed), speed);
  } catch (const Error& e) {
    return StabilityPoint::unknown(speed, e.what());
  }
}

StabilityPoint StabilityPoint::unknown(Real at_speed, std::string why) {
  StabilityPoint out;
  out.speed = at_speed;
  out.known = false;
  out.growth_rate = std::numeric_limits<Real>::quiet_NaN();
  out.message = std::move(why);
  return out;
}

StabilityPoint stability_at(const Model& model, Real speed) {
  const bool supported = has_supports(model);
  if (!(speed > 0) && needs_speed(model)) return StabilityPoint::unknown(speed, at_rest);
  try {
    return supported ? stability_of_linear(linearised(model), speed) : stability_of_linear(model, speed);
  } catch (const Error& e) {
    return StabilityPoint::unknown(speed, e.what());
  }
}

StabilityPoint stability_of_linear(const Model& linear, Real speed) {
  try {
    if (energy_stable(linear, speed)) return by_energy(speed);
    return from_modes(run_modal(linear, speed, stability_modal_options()), speed);
  } catch (const Error& e) {
    return StabilityPoint::unknown(speed, e.what());
  }
}

std::string stability_kind(const StabilityPoint& point) {
  return !point.known ? "unknown" : !point.unstable ? "stable" : point.divergence ? "divergence" : "flutter";
}

std::string stability_phrase(const StabilityPoint& point) {
  if (!point.known) return "unknown: " + point.message;
  if (!point.unstable)
    return point.by_energy ? "stable (no element feeds energy in)"
                           : fmt::format("stable (the least damped mode decays at {:.4g} 1/s)", -point.growth_rate);
  if (point.divergence)
    return fmt::format(
        "UNSTABLE: divergence, a real eigenvalue {:.4g} 1/s (a disturbance grows without "
        "oscillating)",
        point.growth_rate);
  return fmt::format("UNSTABLE: flutter, a mode at {:.4g} Hz grows at {:.4g} 1/s", point.frequency_hz,
                     point.growth_rate);
}

}  // namespace feran

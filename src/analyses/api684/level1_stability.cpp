#include <feran/analyses/api684/level1_stability.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/error.hpp>
#include <feran/core/root_finding.hpp>
#include <feran/elements/spring_damper.hpp>

namespace feran {

Real anticipated_cross_coupling(const StageLoading& stage, Real speed) {
  if (!(speed > 0)) throw Error(fmt::format("the rated speed must be positive, got {} rad/s", speed));
  if (!(stage.diameter > 0) || !(stage.width > 0))
    throw Error("a stage's impeller diameter and discharge width must be positive");
  return stage.factor * (stage.power / speed) / (stage.diameter * stage.width) * stage.density_ratio;
}

Model with_cross_coupling(const Model& model, Index node, Real q) {
  SpringDamperCoefficients c;
  c.kyz = q;
  c.kzy = -q;
  Model out = model;
  out.elements.emplace_back(SpringDamper(node, std::nullopt, c), "cross-coupling Q");
  return out;
}

std::pair<Real, Real> first_forward_log_decrement(const Model& model, Real speed) {
  ModalOptions options;
  options.shapes = false;
  options.oscillatory_only = true;
  const ModalResult r = run_modal(model, speed, options);
  if (!r.info.converged()) throw Error(fmt::format("the modal analysis failed: {}", r.info.message));
  for (const Mode& m : r.modes)
    if (m.type == ModeType::lateral && m.directivity > 0.05) return {m.log_decrement, m.frequency_hz};
  throw Error("the rotor has no forward lateral mode at the maximum continuous speed");
}

Index largest_forward_motion_node(const Model& model, Real speed) {
  ModalOptions mo;
  mo.oscillatory_only = true;
  const ModalResult r = run_modal(model, speed, mo);
  for (const Mode& m : r.modes) {
    if (m.type != ModeType::lateral || !(m.directivity > 0.05)) continue;
    Index best = -1;
    Real largest = -1;
    for (Index n = 0; n < model.n_nodes(); ++n) {
      if (!model.nodes[static_cast<std::size_t>(n)].rotating) continue;
      const Real a = std::norm(m.shape(global_dof(n, Dof::v))) + std::norm(m.shape(global_dof(n, Dof::w)));
      if (a > largest) largest = a, best = n;
    }
    if (best >= 0) return best;
  }
  throw Error(
      "the rotor has no forward lateral mode at the maximum continuous speed to place the cross-coupling "
      "at; give the node");
}

StabilitySweepResult run_stability_sweep(const Model& model, const StabilitySweepOptions& options) {
  if (options.node < 0 || options.node >= model.n_nodes())
    throw Error(fmt::format("no node {} in the model", options.node));
  if (!model.nodes[static_cast<std::size_t>(options.node)].rotating)
    throw Error(
        fmt::format("the cross-coupling acts on the rotor: node {} does not rotate", model.node_label(options.node)));
  if (!(options.speed > 0)) throw Error(fmt::format("the speed must be positive, got {} rad/s", options.speed));
  if (options.points < 2) throw Error(fmt::format("the sweep needs at least 2 points, got {}", options.points));
  if (options.anticipated && !(*options.anticipated > 0))
    throw Error(fmt::format("the anticipated cross-coupling must be positive, got {} N/m", *options.anticipated));

  StabilitySweepResult result;
  result.node = options.node;
  result.speed = options.speed;
  result.anticipated = options.anticipated;
  const auto delta = [&](Real q) {
    return first_forward_log_decrement(with_cross_coupling(model, options.node, q), options.speed).first;
  };

  // Q₀: bracket by doubling from a Q small against any bearing, then Brent's method.
  const Real d0 = delta(0.0);
  if (d0 > 0) {
    Real a = 0, fa = d0, b = 1e3, fb = delta(b);
    while (fb > 0 && b < 1e13) {
      a = b;
      fa = fb;
      b *= 2;
      fb = delta(b);
    }
    if (fb <= 0) result.q_zero = brent_root(delta, a, b, fa, fb, 1e-10 * b).x;
  }

  Real q_high = options.q_high;
  if (!(q_high > 0)) {
    q_high = result.q_zero ? 1.5 * *result.q_zero : 1e6;
    if (options.anticipated) q_high = std::max(q_high, 10 * *options.anticipated);
  }
  for (int i = 0; i < options.points; ++i) {
    if (options.stop.requested()) {
      result.info.fail(SolverStatus::interrupted, fmt::format("stopped after {} of {} points", i, options.points));
      return result;
    }
    const Real q = q_high * i / (options.points - 1);
    const auto [d, f] = first_forward_log_decrement(with_cross_coupling(model, options.node, q), options.speed);
    result.q.push_back(q);
    result.log_decrement.push_back(d);
    result.frequency_hz.push_back(f);
  }
  if (options.anticipated) {
    const Real da = delta(*options.anticipated);
    result.log_decrement_at_anticipated = da;
    result.screening_passes = result.q_zero && *result.q_zero / *options.anticipated >= 2.0 && da >= 0.1;
  }
  return result;
}

}  // namespace feran

#include <feran/analyses/api684/api684_analysis.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/forces/unbalance.hpp>

namespace feran {

namespace {

constexpr Real rpm_per_rad_s = 30.0 / pi;

// The mode's lateral amplitude at each node, signed against its largest: the
// projection of the node's (V, W) on the largest node's.
std::vector<Real> signed_amplitudes(const Model& model, const ComplexVector& shape) {
  const auto vw = [&](Index n) { return std::pair{shape(global_dof(n, Dof::v)), shape(global_dof(n, Dof::w))}; };
  Index ref = -1;
  Real largest = 0;
  for (Index n = 0; n < model.n_nodes(); ++n) {
    if (!model.nodes[static_cast<std::size_t>(n)].rotating) continue;
    const auto [v, w] = vw(n);
    const Real a = std::norm(v) + std::norm(w);
    if (a > largest) largest = a, ref = n;
  }
  std::vector<Real> out(static_cast<std::size_t>(model.n_nodes()), 0.0);
  if (ref < 0) return out;
  const auto [vr, wr] = vw(ref);
  for (Index n = 0; n < model.n_nodes(); ++n) {
    if (!model.nodes[static_cast<std::size_t>(n)].rotating) continue;
    const auto [v, w] = vw(n);
    out[static_cast<std::size_t>(n)] = (std::conj(vr) * v + std::conj(wr) * w).real() / std::sqrt(largest);
  }
  return out;
}

std::vector<Index> merged(std::vector<Index> a, const std::vector<Index>& b) {
  for (const Index i : b)
    if (std::find(a.begin(), a.end(), i) == a.end()) a.push_back(i);
  return a;
}

}  // namespace

Real rotating_mass(const Model& model, const std::function<bool(Index node)>& selected) {
  const OperatingPoint rest{};
  Real mass = 0;
  for (const auto& element : model.elements) {
    const auto m = element.local_matrices(rest);
    if (m.M.size() == 0) continue;
    Vector r = Vector::Zero(static_cast<Index>(m.dofs.size()));
    for (std::size_t i = 0; i < m.dofs.size(); ++i) {
      const Index node = m.dofs[i] / dofs_per_node;
      if (m.dofs[i] % dofs_per_node == static_cast<Index>(Dof::v) &&
          model.nodes[static_cast<std::size_t>(node)].rotating && (!selected || selected(node)))
        r(static_cast<Index>(i)) = 1.0;
    }
    mass += r.dot(m.M * r);
  }
  return mass;
}

Real api684_unbalance_amount(Real mass, Real speed) {
  if (!(speed > 0)) throw Error(fmt::format("the maximum continuous speed must be positive, got {} rad/s", speed));
  const Real n_rpm = std::min(speed * rpm_per_rad_s, 25000.0);
  return 6350.0 * mass / n_rpm * 1e-6;  // g·mm → kg·m
}

std::vector<JournalLoad> journal_loads(const Model& model, const std::vector<Index>& springs,
                                       const StaticOptions& gravity) {
  const Real g = gravity.gravity.norm();
  if (!(g > 0)) throw Error("the journal loads of 4W/N need gravity (a direction in [static] or the analysis's own)");
  const StaticResult r = run_static(model, gravity);
  if (!r.info.converged()) throw Error(fmt::format("the static analysis failed: {}", r.info.message));
  const Model lin = linearised(model);
  std::vector<JournalLoad> out;
  const auto lateral = [](const NodeValues& force) {
    return std::hypot(force[static_cast<std::size_t>(Dof::v)], force[static_cast<std::size_t>(Dof::w)]);
  };
  for (const Index e : springs) {
    JournalLoad j{e, journal_node(lin, e), 0, 0};
    if (const auto support = linearised_support_force(model, e)) {
      for (const auto& [force, value] : r.supports)
        if (force == static_cast<Index>(*support)) j.force = lateral(value);
    } else {
      for (const auto& [element, value] : r.springs)
        if (element == e) j.force = lateral(value);
    }
    j.mass = j.force / g;
    out.push_back(j);
  }
  return out;
}

std::vector<PlacedUnbalance> api684_placement(const Model& model, const ComplexVector& shape,
                                              const std::vector<JournalLoad>& journals, Real speed, Real multiple) {
  if (journals.empty()) throw Error("placing the analytical unbalance needs the rotor's bearings");
  const std::vector<Real> a = signed_amplitudes(model, shape);
  const auto x = [&](Index n) { return model.nodes[static_cast<std::size_t>(n)].x; };
  Real x_low = x(journals.front().node), x_high = x_low, total = 0;
  for (const JournalLoad& j : journals) {
    x_low = std::min(x_low, x(j.node));
    x_high = std::max(x_high, x(j.node));
    total += j.mass;
  }
  Index top = 0;
  for (Index n = 0; n < model.n_nodes(); ++n)
    if (std::abs(a[static_cast<std::size_t>(n)]) > std::abs(a[static_cast<std::size_t>(top)])) top = n;
  const auto placed = [&](Index node, Real mass, Real phase, std::string basis) {
    return PlacedUnbalance{node, multiple * api684_unbalance_amount(mass, speed), phase, mass, std::move(basis)};
  };
  // The mode is largest on an overhang: the overhung mass beyond the nearer bearing.
  const Real span = std::max(x_high - x_low, 1e-12);
  if (x(top) < x_low - 1e-9 * span || x(top) > x_high + 1e-9 * span) {
    const bool left = x(top) < x_low;
    const Real w = rotating_mass(model, [&](Index n) { return left ? x(n) < x_low : x(n) > x_high; });
    return {placed(top, w, 0.0, "overhung")};
  }
  // Between the bearings: in phase or in two opposite lobes.
  Index positive = -1, negative = -1;
  for (Index n = 0; n < model.n_nodes(); ++n) {
    if (x(n) < x_low || x(n) > x_high || !model.nodes[static_cast<std::size_t>(n)].rotating) continue;
    const Real v = a[static_cast<std::size_t>(n)];
    if (v > 0 && (positive < 0 || v > a[static_cast<std::size_t>(positive)])) positive = n;
    if (v < 0 && (negative < 0 || v < a[static_cast<std::size_t>(negative)])) negative = n;
  }
  const Real largest = std::abs(a[static_cast<std::size_t>(top)]);
  // A lobe counts when it moves at least a quarter of the largest amplitude.
  if (negative < 0 || positive < 0 || std::abs(a[static_cast<std::size_t>(negative)]) < 0.25 * largest ||
      a[static_cast<std::size_t>(positive)] < 0.25 * largest)
    return {placed(top, total, 0.0, "rotor")};
  const auto nearest = [&](Index node) {
    const JournalLoad* best = &journals.front();
    for (const JournalLoad& j : journals)
      if (std::abs(x(j.node) - x(node)) < std::abs(x(best->node) - x(node))) best = &j;
    return *best;
  };
  const JournalLoad jp = nearest(positive), jn = nearest(negative);
  const auto name = [&](const JournalLoad& j) {
    const bool labelled = linearised_support_force(model, j.element)
                              ? !model.forces[*linearised_support_force(model, j.element)].label().empty()
                              : !model.elements[static_cast<std::size_t>(j.element)].label().empty();
    return labelled ? linearised_element_name(model, j.element)
                    : fmt::format("bearing at node {}", model.node_label(j.node));
  };
  return {placed(positive, jp.mass, 0.0, name(jp)), placed(negative, jn.mass, pi, name(jn))};
}

OperatingStability operating_stability(const Model& model, Real low, Real high, int points) {
  OperatingStability out;
  const int n = low == high ? 1 : std::max(points, 2);
  for (int i = 0; i < n; ++i)
    out.points.push_back(stability_at(model, n == 1 ? low : low + (high - low) * i / (n - 1)));
  const auto rpm = [](Real speed) { return fmt::format("{:.0f} rpm", speed * rpm_per_rad_s); };
  for (const StabilityPoint& p : out.points) {
    if (p.unstable) {
      out.passes = false;
      out.reason = p.divergence
                       ? fmt::format(
                             "unstable at {}: divergence (a real eigenvalue {:.4g} 1/s: a negative stiffness "
                             "or a load beyond buckling)",
                             rpm(p.speed), p.growth_rate)
                       : fmt::format("unstable at {}: a mode at {:.4g} Hz grows at {:.4g} 1/s (log. decrement {:.3g})",
                                     rpm(p.speed), p.frequency_hz, p.growth_rate,
                                     -2 * pi * p.growth_rate / (2 * pi * p.frequency_hz));
      return out;
    }
    if (!p.known) {
      out.passes = false;
      out.reason = fmt::format("stability unknown at {}: {}", rpm(p.speed), p.message);
      return out;
    }
  }
  out.reason = fmt::format("stable at {} speeds from {} to {}", out.points.size(), rpm(low), rpm(high));
  return out;
}

Api684Result run_api684(const Model& model, const Api684Options& options) {
  if (!(options.low > 0) || !(options.high >= options.low))
    throw Error(fmt::format("the operating speed range needs 0 < minimum ≤ maximum, got {} to {} rpm",
                            options.low * rpm_per_rad_s, options.high * rpm_per_rad_s));
  if (options.speeds.size() < 3) throw Error("the unbalance responses need at least 3 speeds");
  Api684Result result;
  result.low = options.low;
  result.high = options.high;
  // Every kind of support, as the linear analyses take it: journal and rolling
  // bearings by their tangent about the static equilibrium at each speed (elements
  // numbered after the model's own, equilibrium.hpp).
  const Model lin = linearised(model);
  result.bearings = options.bearings.empty() ? bearing_elements(lin) : options.bearings;
  if (result.bearings.empty())
    throw Error(
        "the model has no bearings: no spring–damper, journal or rolling bearing holds a rotating node to "
        "the ground or to a non-rotating node");
  std::vector<Index> bearing_nodes;
  for (const Index e : result.bearings) bearing_nodes.push_back(journal_node(lin, e));
  // An oil film carries nothing at rest: the undamped critical speeds start from the
  // coefficients at the maximum continuous speed, and the responses leave out speed 0.
  const bool running = needs_speed(model);
  std::vector<Real> speeds = options.speeds;
  if (running) std::erase_if(speeds, [](Real s) { return !(s > 0); });
  if (speeds.size() < 3) throw Error("the unbalance responses need at least 3 speeds above 0");

  result.stability_verdict = operating_stability(model, options.low, options.high);
  result.undamped =
      undamped_critical_speeds(with_direct_bearing_stiffness(lin, result.bearings), std::max(options.modes, 4), true,
                               &result.info, running ? options.high : 0.0);

  // The unbalance cases.
  Model base = model;
  std::erase_if(base.forces, is_unbalance);
  const auto respond = [&](Api684Case c, const Model& m) {
    HarmonicOptions h;
    h.speeds = speeds;
    h.probes = options.probes;
    if (h.probes.empty()) {
      h.probes = bearing_nodes;
      for (const PlacedUnbalance& u : c.unbalances) h.probes = merged(h.probes, {u.node});
    }
    h.n_threads = options.n_threads;
    h.stop = options.stop;
    c.response = run_harmonic_response(m, h);
    if (!c.response.info.converged() && result.info.converged()) result.info = c.response.info;
    for (std::size_t p = 0; p < c.response.probes.size(); ++p) {
      c.checks.push_back(separation_checks(c.response, p, options.low, options.high));
      for (const SeparationCheck& check : c.checks.back())
        if (check.passes && !*check.passes) c.passes = false;
    }
    result.cases.push_back(std::move(c));
  };
  if (options.model_unbalance) {
    if (model.count_forces(is_unbalance) == 0)
      throw Error("the model has no [[unbalances]]: give some, or use the analytical unbalance (4W/N)");
    Api684Case c;
    c.name = "model unbalance";
    respond(std::move(c), model);
  } else {
    result.journals = journal_loads(model, result.bearings, options.gravity);
    ModalOptions mo;
    mo.oscillatory_only = true;
    const ModalResult modal = run_modal(model, options.high, mo);
    if (!modal.info.converged()) throw Error(fmt::format("the modal analysis failed: {}", modal.info.message));
    int n = 0;
    for (const Mode& mode : modal.modes) {
      if (n == options.modes || options.stop.requested()) break;
      if (mode.type != ModeType::lateral || !(mode.directivity > 0.05)) continue;
      Api684Case c;
      c.name = fmt::format("mode {}", ++n);
      c.mode = mode;
      c.unbalances = api684_placement(model, mode.shape, result.journals, options.high, options.unbalance_multiple);
      Model m = base;
      for (const PlacedUnbalance& u : c.unbalances)
        m.forces.emplace_back(Unbalance{u.node, u.amount, 1.0, u.phase, 0.0}, fmt::format("4W/N {}", c.name));
      respond(std::move(c), m);
    }
    if (n < options.modes && !options.stop.requested() && result.info.converged())
      result.info.fail(SolverStatus::not_converged,
                       fmt::format("the rotor has {} forward lateral modes at the maximum continuous speed, not {}", n,
                                   options.modes));
  }

  if (options.map) {
    CriticalSpeedMapOptions map = *options.map;
    if (map.springs.empty()) map.springs = result.bearings;
    map.stop = options.stop;
    result.map = run_critical_speed_map(lin, map);
  }
  if (options.stability) {
    StabilitySweepOptions s = *options.stability;
    s.stop = options.stop;
    result.stability = run_stability_sweep(model, s);
  }
  // Stopped on request where no sweep was running to say so (before the first
  // unbalance case, between cases): the result is incomplete all the same.
  if (options.stop.requested() && result.info.status != SolverStatus::interrupted)
    result.info.fail(SolverStatus::interrupted, fmt::format("stopped on request after {} unbalance case{}",
                                                            result.cases.size(), result.cases.size() == 1 ? "" : "s"));
  return result;
}

}  // namespace feran

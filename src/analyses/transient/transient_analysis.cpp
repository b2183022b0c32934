#include <feran/analyses/transient/transient_analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include <Eigen/SparseLU>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/analyses/transient/modal_basis.hpp>
#include <feran/analyses/transient/projected_system.hpp>
#include <feran/analyses/transient/rotor_system.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();
using ComplexSparse = Eigen::SparseMatrix<Complex>;

// Cubic Hermite interpolation between two states (x, v at both ends): fourth-order
// accurate, so sampling adds no error beyond the integrators' own.
void interpolate(const State& a, const State& b, Real t, Vector& x, Vector& v) {
  const Real h = b.t - a.t, s = (t - a.t) / h;
  const Real h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const Real h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  const Real d00 = 6 * s * s - 6 * s, d10 = 3 * s * s - 4 * s + 1, d01 = -6 * s * s + 6 * s, d11 = 3 * s * s - 2 * s;
  x = h00 * a.x + (h10 * h) * a.v + h01 * b.x + (h11 * h) * b.v;
  v = (d00 / h) * a.x + d10 * a.v + (d01 / h) * b.x + d11 * b.v;
}

// Unit forces and moments (v, w, ry, rz) at every node where a force of the run
// acts — its external and nonlinear forces, and its static loads when applied — in
// reduced coordinates: the static correction vectors of a reduced run.
// Gravity spreads over every node: its load vector is one more column.
Matrix load_vectors(const Model& model, const DofMap& dofs, const TransientOptions& options,
                    const Vector& constant_load) {
  std::vector<Index> nodes;
  for (const Force& f : model.forces)
    if (f.has_transient() || f.is_nonlinear() || (options.static_loads && f.has_static()))
      for (const Index node : f.nodes()) nodes.push_back(node);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const SparseMatrix Tt = dofs.transformation().transpose();
  const bool gravity = options.gravity.squaredNorm() > 0;
  Matrix loads(dofs.n_reduced(), 4 * static_cast<Index>(nodes.size()) + (gravity ? 1 : 0));
  Index c = 0;
  for (const Index node : nodes)
    for (const Dof d : {Dof::v, Dof::w, Dof::ry, Dof::rz}) loads.col(c++) = Vector(Tt.col(global_dof(node, d)));
  if (gravity) loads.col(c) = Tt * constant_load;
  return loads;
}

// The steady unbalance response at the first speed about the equilibrium @p q0 (all
// unconstrained DOFs): x(t) = Re(X·e^{iΩt}) of (K(Ω) + ΩK_i + iΩ(C + C_i + ΩG) − Ω²M)·X = F
// with the supports' tangents, F the forces that act in the run-up at ω = Ω.
std::pair<Vector, Vector> steady_unbalance_response(const Model& model, Real speed) {
  const Model linear = linearised(model);
  const Assembler assembler(linear);
  const SystemMatrices sys = assembler.at(speed);
  const ComplexSparse Z = (sys.stiffness(speed) - speed * speed * sys.M).cast<Complex>() +
                          Complex(0, speed) * sys.damping(speed).cast<Complex>();
  ComplexVector f = ComplexVector::Zero(model.n_dofs());
  const HarmonicExcitation excitation{speed, speed, true, true};
  for (const Force& force : model.forces)
    if (force.has_transient()) force.add_harmonic(excitation, f);
  const ComplexSparse T = assembler.dof_map().transformation().cast<Complex>();
  Eigen::SparseLU<ComplexSparse, Eigen::COLAMDOrdering<int>> lu(Z);
  if (lu.info() != Eigen::Success)
    throw Error(
        fmt::format("runup: the steady state at {:.6g} rad/s cannot be found: the dynamic stiffness is "
                    "singular there (an undamped resonance)",
                    speed));
  const ComplexVector X = T * ComplexVector(lu.solve(ComplexVector(T.transpose() * f)));
  return {X.real(), Vector((Complex(0, speed) * X).real())};
}

// The initial displacements and velocities (all unconstrained DOFs) of options.start.
std::pair<Vector, Vector> start_state(const Model& model, const TransientOptions& options) {
  if (options.start == RunupStart::rest) return {options.initial_displacement, options.initial_velocity};
  const Real speed = options.profile.speed(0.0);
  EquilibriumOptions at_start;
  at_start.gravity = options.gravity;
  at_start.loads = options.static_loads;
  at_start.frequency = std::nullopt;  // the coefficients the run-up integrates (synchronous)
  std::optional<Assembler> own;
  const Assembler& assembler = options.assembled ? *options.assembled : own.emplace(model);
  const Equilibrium e = solve_equilibrium(model, assembler, speed, at_start);
  if (!e.info.converged()) throw Error("runup: no start at the equilibrium: " + e.info.message);
  Vector x = e.q, v = Vector::Zero(model.n_dofs());
  if (options.start == RunupStart::steady_state) {
    const auto [xs, vs] = steady_unbalance_response(model, speed);
    x += xs;
    v += vs;
  }
  // A disturbance given with the start is added to it.
  if (options.initial_displacement.size() == model.n_dofs()) x += options.initial_displacement;
  if (options.initial_velocity.size() == model.n_dofs()) v += options.initial_velocity;
  return {x, v};
}

}  // namespace

TransientResult run_transient(const Model& model, const TransientOptions& options, const SampleSink& sink,
                              const ProgressSink& progress) {
  if (!(options.duration > 0)) throw Error("transient: the duration must be positive");
  if (!(options.output_interval > 0)) throw Error("transient: the output interval must be positive");
  if (!(options.settings.dt > 0)) throw Error("transient: the time step must be positive");
  for (Index e : options.springs)
    if (!model.elements.at(static_cast<std::size_t>(e)).transmission(0.0))
      throw Error("transient: a recorded element transmits no force (it is not a spring-damper)");

  TransientResult result;
  const Vector constant_load = options.gravity.squaredNorm() > 0 || options.static_loads
                                   ? static_load_vector(model, options.gravity, options.static_loads)
                                   : Vector();
  if (options.driven && !model.drive)
    throw Error("runup: a torque-driven run needs the model's [drive] (its motor and load torques)");
  if (options.driven && options.reduced_modes > 0)
    throw Error("runup: a torque-driven run integrates the full model: leave out reduced_modes");
  if (options.driven && options.profile.speed(0.0) == 0.0) {
    // From rest the motor must overcome the friction torque, which holds the rotor
    // at rest (set-valued at zero speed: no step of the smoothed sign resolves it).
    const Drive& d = *model.drive;
    const Real start = d.motor.torque(0.0);
    if (start < 0.0)
      throw Error(
          fmt::format("runup: the drive's motor gives {:.4g} N m at rest: it would turn the rotor backwards; "
                      "a motor torque at 0 Hz above 0 starts it",
                      start));
    if (d.friction_torque > 0.0 && start <= d.friction_torque)
      throw Error(
          fmt::format("runup: the drive cannot start the rotor from rest: its motor gives {:.4g} N m at 0 Hz, "
                      "not more than the friction torque {:.4g} N m of [drive], which holds the rotor at "
                      "rest; a stronger motor or less friction starts it",
                      start, d.friction_torque));
  }
  const auto [x_start, v_start] = start_state(model, options);
  RotorSystem rotor(model, options.profile, constant_load, options.driven ? &*model.drive : nullptr, options.assembled);
  std::unique_ptr<Integrator> integrator = make_integrator(options.integrator, options.settings);
  result.info.method = SolverMethod::time_integration;
  const DofMap& dofs = rotor.dof_map();
  std::unique_ptr<ProjectedSystem> projected;
  if (options.reduced_modes > 0) {
    std::vector<Real> speeds;
    for (int i = 0; i < modal_basis_speeds; ++i)
      speeds.push_back(options.profile.speed(options.duration * i / (modal_basis_speeds - 1)));
    projected = std::make_unique<ProjectedSystem>(
        rotor, undamped_mode_basis(rotor.assembler(), speeds, options.reduced_modes,
                                   load_vectors(model, dofs, options, constant_load)));
    result.basis_size = projected->size();
  }
  SecondOrderSystem& sys = projected ? static_cast<SecondOrderSystem&>(*projected) : rotor;
  const Index n = sys.size();
  // The integrated state in the model's reduced coordinates (after fixed DOFs and links).
  Vector x_model, v_model;
  auto model_coordinates = [&](const Vector& x, Vector& out) -> const Vector& {
    if (!projected) return x;
    out.noalias() = projected->basis() * x;
    return out;
  };

  // Envelope bins over the speeds the profile visits within the run (a driven run:
  // from its first speed to the motor's free speed).
  Real w_lo = options.profile.speed(0.0), w_hi = w_lo;
  if (options.driven) {
    w_lo = std::min(w_lo, model.drive->motor.free_speed());
    w_hi = std::max(w_hi, model.drive->motor.free_speed());
  } else {
    for (const auto& [t, w] : options.profile.points())
      if (t <= options.duration) w_lo = std::min(w_lo, w), w_hi = std::max(w_hi, w);
    w_lo = std::min(w_lo, options.profile.speed(options.duration));
    w_hi = std::max(w_hi, options.profile.speed(options.duration));
  }
  const Index bins = w_hi > w_lo ? std::max<Index>(options.envelope_bins, 1) : 1;
  for (std::size_t p = 0; p < options.probes.size(); ++p) {
    Envelope e;
    for (Index b = 0; b < bins; ++b)
      e.speed.push_back(w_lo + (w_hi - w_lo) * (static_cast<Real>(b) + 0.5) / static_cast<Real>(bins));
    e.magnitude.assign(static_cast<std::size_t>(bins), nan);
    result.envelopes.push_back(e);
  }
  // The supports' clearances, watched at every step: (v, w) of the journal, then of its
  // housing if it has one (the supports' DOFs, Force::dofs()).
  result.operating = operating_series(model);
  std::vector<OperatingSeries> operating_now = result.operating;
  std::vector<std::vector<Index>> clearance_dofs;
  for (const OperatingSeries& os : result.operating) {
    const Force& force = model.forces[static_cast<std::size_t>(os.force)];
    if (const std::optional<Real> c = force.clearance(); c && *c > 0) {
      result.clearance_use.push_back({.force = os.force, .clearance = *c});
      clearance_dofs.push_back(force.dofs());
    }
  }
  auto update_clearance_use = [&](const Vector& x, Real t, Real w) {
    for (std::size_t k = 0; k < clearance_dofs.size(); ++k) {
      const std::vector<Index>& d = clearance_dofs[k];
      Real dy = x(d[0]), dz = x(d[1]);
      if (d.size() >= 4) dy -= x(d[2]), dz -= x(d[3]);
      ClearanceUse& u = result.clearance_use[k];
      const Real ratio = std::hypot(dy, dz) / u.clearance;
      if (ratio > u.largest) u.largest = ratio, u.time = t, u.speed = w;
    }
  };

  auto update_envelopes = [&](const State& s) {
    const Vector x = rotor.expand(model_coordinates(s.x, x_model));
    const Real w = rotor.speed(s.t, s.v);
    const Index b =
        bins == 1
            ? 0
            : std::clamp<Index>(static_cast<Index>((w - w_lo) / (w_hi - w_lo) * static_cast<Real>(bins)), 0, bins - 1);
    for (std::size_t p = 0; p < options.probes.size(); ++p) {
      const Real r = std::hypot(x(global_dof(options.probes[p], Dof::v)), x(global_dof(options.probes[p], Dof::w)));
      Envelope& e = result.envelopes[p];
      Real& m = e.magnitude[static_cast<std::size_t>(b)];
      if (std::isnan(m) || r > m) m = r;
      if (r > e.peak) e.peak = r, e.peak_time = s.t, e.peak_speed = w;
    }
    update_clearance_use(x, s.t, w);
  };

  Vector x_full, v_full;
  auto emit = [&](Real t, const Vector& x, const Vector& v) {
    TransientSample sample;
    sample.t = t;
    sample.speed = rotor.speed(t, v);
    x_full = rotor.expand(model_coordinates(x, x_model));
    v_full = rotor.expand(model_coordinates(v, v_model));
    for (Index node : options.probes) {
      std::array<Real, dofs_per_node> q{};
      for (int d = 0; d < dofs_per_node; ++d) q[static_cast<std::size_t>(d)] = x_full(dofs_per_node * node + d);
      sample.probes.push_back(q);
      sample.magnitude.push_back(std::hypot(q[static_cast<std::size_t>(Dof::v)], q[static_cast<std::size_t>(Dof::w)]));
    }
    for (Index e : options.springs) {
      const Transmission link = *model.elements[static_cast<std::size_t>(e)].transmission(sample.speed);
      Eigen::Matrix<Real, dofs_per_node, 1> dx = x_full.segment<dofs_per_node>(dofs_per_node * link.node_a);
      Eigen::Matrix<Real, dofs_per_node, 1> dv = v_full.segment<dofs_per_node>(dofs_per_node * link.node_a);
      if (link.node_b) {
        dx -= x_full.segment<dofs_per_node>(dofs_per_node * *link.node_b);
        dv -= v_full.segment<dofs_per_node>(dofs_per_node * *link.node_b);
      }
      const Eigen::Matrix<Real, dofs_per_node, 1> f = link.K * dx + link.C * dv;
      std::array<Real, dofs_per_node> out{};
      for (int d = 0; d < dofs_per_node; ++d) out[static_cast<std::size_t>(d)] = f(d);
      sample.springs.push_back(out);
    }
    if (!operating_now.empty()) {
      append_in_motion(operating_now, model, rotor.motion(t, x, v), x_full, v_full);
      for (std::size_t k = 0; k < operating_now.size(); ++k) {
        sample.operating.push_back(std::move(operating_now[k].values.back()));
        operating_now[k].values.clear();
        if (options.keep_samples) result.operating[k].values.push_back(sample.operating.back());
      }
    }
    if (sink) sink(sample);
    if (options.keep_samples) result.samples.push_back(std::move(sample));
  };

  const Index n_model = rotor.model_size();
  Vector x0 = Vector::Zero(rotor.size()), v0 = Vector::Zero(rotor.size());
  for (Index i = 0; i < n_model; ++i) {
    if (x_start.size() == model.n_dofs()) x0(i) = x_start(dofs.full_dof(i));
    if (v_start.size() == model.n_dofs()) v0(i) = v_start(dofs.full_dof(i));
  }
  if (rotor.driven()) v0(n_model) = options.profile.speed(0.0);  // the angle starts at 0
  State s{0.0, Vector::Zero(n), Vector::Zero(n), Vector::Zero(n)};
  if (projected) {
    // The M-orthogonal projection onto the basis (ΦᵀMΦ = I): η = Φᵀ·M·x.
    Vector mx(n_model);
    rotor.mass_times(x0, mx);
    s.x = projected->basis().transpose() * mx;
    rotor.mass_times(v0, mx);
    s.v = projected->basis().transpose() * mx;
  } else {
    s.x = x0;
    s.v = v0;
  }
  const StepReport started = integrator->start(sys, s);
  if (!started.ok) {
    result.info.fail(SolverStatus::numerical_failure, started.message);
    return result;
  }
  result.warning = started.message;
  emit(0.0, s.x, s.v);
  update_envelopes(s);

  Index next_output = 1;
  Real dt = options.settings.dt;
  const Real t_end = options.duration;
  State previous = s;
  Vector xi, vi;
  auto fail = [&](const std::string& why) {
    result.info.fail(SolverStatus::numerical_failure, fmt::format("stopped at t = {:.6g} s (speed {:.4g} Hz): {}", s.t,
                                                                  rad_to_hz(rotor.speed(s.t, s.v)), why));
  };
  while (s.t < t_end * (1 - 1e-12)) {
    if (options.stop.requested()) {
      result.info.fail(SolverStatus::interrupted, fmt::format("stopped on request at t = {:.6g} s (speed {:.4g} Hz)",
                                                              s.t, rad_to_hz(rotor.speed(s.t, s.v))));
      break;
    }
    const Real h = std::min(dt, t_end - s.t);
    previous = s;
    StepReport rep;
    try {
      rep = integrator->step(sys, s, h);
    } catch (const Error& e) {
      // A force that cannot be evaluated in the step's state (a journal at its
      // bearing's wall): the run ends there, its samples so far kept.
      s = previous;
      fail(e.what());
      break;
    }
    ++result.steps;
    result.rejected += rep.rejected;
    result.factorizations += rep.factorizations;
    result.newton_iterations += rep.iterations;
    if (!rep.ok) {
      s = previous;
      fail(rep.message);
      break;
    }
    if (integrator->adaptive()) dt = rep.dt_next;
    // Blow-up and non-finite values, located at a node and DOF.
    Index worst = -1;
    Real worst_value = 0;
    const Vector& xm = model_coordinates(s.x, x_model);
    const Vector& vm = model_coordinates(s.v, v_model);
    for (Index i = 0; i < n_model; ++i) {
      const Real a = std::abs(xm(i));
      if (!std::isfinite(xm(i)) || !std::isfinite(vm(i))) {
        worst = i, worst_value = nan;
        break;
      }
      if (a > worst_value) worst = i, worst_value = a;
    }
    if (worst >= 0 && (std::isnan(worst_value) || worst_value > options.blowup_limit)) {
      const Index full = dofs.full_dof(worst);
      const std::string where = fmt::format("node {} DOF {}", model.node_label(full / dofs_per_node),
                                            dof_name(static_cast<Dof>(full % dofs_per_node)));
      const std::string why = std::isnan(worst_value)
                                  ? fmt::format("a non-finite value appeared at {}", where)
                                  : fmt::format("the motion blew up: |{}| reached {:.3g} (limit {:.3g})", where,
                                                worst_value, options.blowup_limit);
      fail(why);
      s = previous;
      break;
    }
    while (static_cast<Real>(next_output) * options.output_interval <= s.t * (1 + 1e-12) &&
           static_cast<Real>(next_output) * options.output_interval <= t_end * (1 + 1e-12)) {
      const Real to = std::min(static_cast<Real>(next_output) * options.output_interval, s.t);
      interpolate(previous, s, to, xi, vi);
      emit(to, xi, vi);
      ++next_output;
    }
    update_envelopes(s);
    if (progress && result.steps % 200 == 0) progress(s.t, rep.dt);
  }
  result.t_end = s.t;
  result.speed_end = rotor.speed(s.t, s.v);
  return result;
}

}  // namespace feran

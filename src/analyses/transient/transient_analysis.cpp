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

namespace {

// The options a run cannot start without, as a C++ caller may have set them.
void check_options(const Model& model, const TransientOptions& options) {
  if (!(options.duration > 0)) throw Error("transient: the duration must be positive");
  if (!(options.output_interval > 0)) throw Error("transient: the output interval must be positive");
  if (!(options.settings.dt > 0)) throw Error("transient: the time step must be positive");
  for (Index e : options.springs)
    if (!model.elements.at(static_cast<std::size_t>(e)).transmission(0.0))
      throw Error("transient: a recorded element transmits no force (it is not a spring-damper)");
  // Run-ups integrate M·x'' = r(t, x, v) with a constant mass matrix.
  for (const Element& e : model.elements)
    if (e.speed_dependent() && e.local_matrices({}).M.size() != 0)
      throw Error(
          fmt::format("runup: '{}' ({}) has an added mass that changes with speed, and a run-up integrates "
                      "with a constant mass matrix; the steady-state analyses (modal, campbell, response, "
                      "static, api684) take it",
                      e.label(), e.kind()));
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
}

Vector constant_load_of(const Model& model, const TransientOptions& options) {
  return options.gravity.squaredNorm() > 0 || options.static_loads
             ? static_load_vector(model, options.gravity, options.static_loads)
             : Vector();
}

// A run-up in named steps: the system integrated (the rotor, or its projection on a
// modal basis), what it watches (envelopes(), clearances()), its initial state
// (initial_state()), the steps (advance(), blown_up()) and what it records at the
// output times (emit()) and at every step (watch()).
class TransientRun {
 public:
  TransientRun(const Model& model, const TransientOptions& options, const SampleSink& sink,
               const ProgressSink& progress)
      : model_(model),
        options_(options),
        sink_(sink),
        progress_(progress),
        constant_load_(constant_load_of(model, options)),
        rotor_(model, options.profile, constant_load_, options.driven ? &*model.drive : nullptr, options.assembled),
        integrator_(make_integrator(options.integrator, options.settings)),
        n_model_(rotor_.model_size()) {
    result_.info.method = SolverMethod::time_integration;
    if (options.reduced_modes > 0) {
      std::vector<Real> speeds;
      for (int i = 0; i < modal_basis_speeds; ++i)
        speeds.push_back(options.profile.speed(options.duration * i / (modal_basis_speeds - 1)));
      projected_ = std::make_unique<ProjectedSystem>(
          rotor_, undamped_mode_basis(rotor_.assembler(), speeds, options.reduced_modes,
                                      load_vectors(model, rotor_.dof_map(), options, constant_load_)));
      result_.basis_size = projected_->size();
    }
  }

  TransientResult run() {
    envelopes();
    clearances();
    State s = initial_state();
    SecondOrderSystem& sys = system();
    const StepReport started = integrator_->start(sys, s);
    if (!started.ok) {
      result_.info.fail(SolverStatus::numerical_failure, started.message);
      return std::move(result_);
    }
    result_.warning = started.message;
    emit(0.0, s.x, s.v);
    watch(s);
    advance(s);
    result_.t_end = s.t;
    result_.speed_end = rotor_.speed(s.t, s.v);
    return std::move(result_);
  }

 private:
  SecondOrderSystem& system() { return projected_ ? static_cast<SecondOrderSystem&>(*projected_) : rotor_; }

  // The integrated state in the model's reduced coordinates (after fixed DOFs and links).
  const Vector& model_coordinates(const Vector& x, Vector& out) const {
    if (!projected_) return x;
    out.noalias() = projected_->basis() * x;
    return out;
  }

  // Envelope bins over the speeds the profile visits within the run (a driven run:
  // from its first speed to the motor's free speed).
  void envelopes() {
    w_lo_ = options_.profile.speed(0.0), w_hi_ = w_lo_;
    if (options_.driven) {
      w_lo_ = std::min(w_lo_, model_.drive->motor.free_speed());
      w_hi_ = std::max(w_hi_, model_.drive->motor.free_speed());
    } else {
      for (const auto& [t, w] : options_.profile.points())
        if (t <= options_.duration) w_lo_ = std::min(w_lo_, w), w_hi_ = std::max(w_hi_, w);
      w_lo_ = std::min(w_lo_, options_.profile.speed(options_.duration));
      w_hi_ = std::max(w_hi_, options_.profile.speed(options_.duration));
    }
    bins_ = w_hi_ > w_lo_ ? std::max<Index>(options_.envelope_bins, 1) : 1;
    for (std::size_t p = 0; p < options_.probes.size(); ++p) {
      Envelope e;
      for (Index b = 0; b < bins_; ++b)
        e.speed.push_back(w_lo_ + (w_hi_ - w_lo_) * (static_cast<Real>(b) + 0.5) / static_cast<Real>(bins_));
      e.magnitude.assign(static_cast<std::size_t>(bins_), nan);
      result_.envelopes.push_back(e);
    }
  }

  // The supports' clearances, watched at every step: (v, w) of the journal, then of
  // its housing if it has one (the supports' DOFs, Force::dofs()).
  void clearances() {
    result_.operating = operating_series(model_);
    operating_now_ = result_.operating;
    for (const OperatingSeries& os : result_.operating) {
      const Force& force = model_.forces[static_cast<std::size_t>(os.force)];
      if (const std::optional<Real> c = force.clearance(); c && *c > 0) {
        result_.clearance_use.push_back({.force = os.force, .clearance = *c});
        clearance_dofs_.push_back(force.dofs());
      }
    }
  }

  // The state at t = 0 (rest, the equilibrium or the steady response), projected on
  // the basis for a reduced run.
  State initial_state() {
    const auto [x_start, v_start] = start_state(model_, options_);
    const DofMap& dofs = rotor_.dof_map();
    Vector x0 = Vector::Zero(rotor_.size()), v0 = Vector::Zero(rotor_.size());
    for (Index i = 0; i < n_model_; ++i) {
      if (x_start.size() == model_.n_dofs()) x0(i) = x_start(dofs.full_dof(i));
      if (v_start.size() == model_.n_dofs()) v0(i) = v_start(dofs.full_dof(i));
    }
    if (rotor_.driven()) v0(n_model_) = options_.profile.speed(0.0);  // the angle starts at 0
    const Index n = system().size();
    State s{0.0, Vector::Zero(n), Vector::Zero(n), Vector::Zero(n)};
    if (projected_) {
      // The M-orthogonal projection onto the basis (ΦᵀMΦ = I): η = Φᵀ·M·x.
      Vector mx(n_model_);
      rotor_.mass_times(x0, mx);
      s.x = projected_->basis().transpose() * mx;
      rotor_.mass_times(v0, mx);
      s.v = projected_->basis().transpose() * mx;
    } else {
      s.x = x0;
      s.v = v0;
    }
    return s;
  }

  // At every step: each probe's |r| into its envelope and peak, each journal's
  // excursion into its clearance use.
  void watch(const State& s) {
    const Vector x = rotor_.expand(model_coordinates(s.x, x_model_));
    const Real w = rotor_.speed(s.t, s.v);
    const Index b =
        bins_ == 1 ? 0
                   : std::clamp<Index>(static_cast<Index>((w - w_lo_) / (w_hi_ - w_lo_) * static_cast<Real>(bins_)), 0,
                                       bins_ - 1);
    for (std::size_t p = 0; p < options_.probes.size(); ++p) {
      const Real r = std::hypot(x(global_dof(options_.probes[p], Dof::v)), x(global_dof(options_.probes[p], Dof::w)));
      Envelope& e = result_.envelopes[p];
      Real& m = e.magnitude[static_cast<std::size_t>(b)];
      if (std::isnan(m) || r > m) m = r;
      if (r > e.peak) e.peak = r, e.peak_time = s.t, e.peak_speed = w;
    }
    for (std::size_t k = 0; k < clearance_dofs_.size(); ++k) {
      const std::vector<Index>& d = clearance_dofs_[k];
      Real dy = x(d[0]), dz = x(d[1]);
      if (d.size() >= 4) dy -= x(d[2]), dz -= x(d[3]);
      ClearanceUse& u = result_.clearance_use[k];
      const Real ratio = std::hypot(dy, dz) / u.clearance;
      if (ratio > u.largest) u.largest = ratio, u.time = s.t, u.speed = w;
    }
  }

  // A sample at output time @p t: the probes, the springs' forces, the supports' state.
  void emit(Real t, const Vector& x, const Vector& v) {
    TransientSample sample;
    sample.t = t;
    sample.speed = rotor_.speed(t, v);
    x_full_ = rotor_.expand(model_coordinates(x, x_model_));
    v_full_ = rotor_.expand(model_coordinates(v, v_model_));
    for (Index node : options_.probes) {
      std::array<Real, dofs_per_node> q{};
      for (int d = 0; d < dofs_per_node; ++d) q[static_cast<std::size_t>(d)] = x_full_(dofs_per_node * node + d);
      sample.probes.push_back(q);
      sample.magnitude.push_back(std::hypot(q[static_cast<std::size_t>(Dof::v)], q[static_cast<std::size_t>(Dof::w)]));
    }
    for (Index e : options_.springs) {
      const Transmission link = *model_.elements[static_cast<std::size_t>(e)].transmission(sample.speed);
      Eigen::Matrix<Real, dofs_per_node, 1> dx = x_full_.segment<dofs_per_node>(dofs_per_node * link.node_a);
      Eigen::Matrix<Real, dofs_per_node, 1> dv = v_full_.segment<dofs_per_node>(dofs_per_node * link.node_a);
      if (link.node_b) {
        dx -= x_full_.segment<dofs_per_node>(dofs_per_node * *link.node_b);
        dv -= v_full_.segment<dofs_per_node>(dofs_per_node * *link.node_b);
      }
      const Eigen::Matrix<Real, dofs_per_node, 1> f = link.K * dx + link.C * dv;
      std::array<Real, dofs_per_node> out{};
      for (int d = 0; d < dofs_per_node; ++d) out[static_cast<std::size_t>(d)] = f(d);
      sample.springs.push_back(out);
    }
    if (!operating_now_.empty()) {
      append_in_motion(operating_now_, model_, rotor_.motion(t, x, v), x_full_, v_full_);
      for (std::size_t k = 0; k < operating_now_.size(); ++k) {
        sample.operating.push_back(std::move(operating_now_[k].values.back()));
        operating_now_[k].values.clear();
        if (options_.keep_samples) result_.operating[k].values.push_back(sample.operating.back());
      }
    }
    if (sink_) sink_(sample);
    if (options_.keep_samples) result_.samples.push_back(std::move(sample));
  }

  void fail(const State& s, const std::string& why) {
    result_.info.fail(SolverStatus::numerical_failure, fmt::format("stopped at t = {:.6g} s (speed {:.4g} Hz): {}", s.t,
                                                                   rad_to_hz(rotor_.speed(s.t, s.v)), why));
  }

  // Why the motion after a step cannot go on: a non-finite value, or a displacement
  // beyond the blow-up limit, located at a node and DOF; empty when it can.
  std::string blown_up(const State& s) {
    Index worst = -1;
    Real worst_value = 0;
    const Vector& xm = model_coordinates(s.x, x_model_);
    const Vector& vm = model_coordinates(s.v, v_model_);
    for (Index i = 0; i < n_model_; ++i) {
      const Real a = std::abs(xm(i));
      if (!std::isfinite(xm(i)) || !std::isfinite(vm(i))) {
        worst = i, worst_value = nan;
        break;
      }
      if (a > worst_value) worst = i, worst_value = a;
    }
    if (worst < 0 || !(std::isnan(worst_value) || worst_value > options_.blowup_limit)) return {};
    const Index full = rotor_.dof_map().full_dof(worst);
    const std::string where = fmt::format("node {} DOF {}", model_.node_label(full / dofs_per_node),
                                          dof_name(static_cast<Dof>(full % dofs_per_node)));
    return std::isnan(worst_value) ? fmt::format("a non-finite value appeared at {}", where)
                                   : fmt::format("the motion blew up: |{}| reached {:.3g} (limit {:.3g})", where,
                                                 worst_value, options_.blowup_limit);
  }

  // The steps to the end, each sample between them interpolated at its output time;
  // a stop, a failed step or a blow-up ends the run at the last good state.
  void advance(State& s) {
    SecondOrderSystem& sys = system();
    Index next_output = 1;
    Real dt = options_.settings.dt;
    const Real t_end = options_.duration;
    State previous = s;
    Vector xi, vi;
    while (s.t < t_end * (1 - 1e-12)) {
      if (options_.stop.requested()) {
        result_.info.fail(SolverStatus::interrupted, fmt::format("stopped on request at t = {:.6g} s (speed {:.4g} Hz)",
                                                                 s.t, rad_to_hz(rotor_.speed(s.t, s.v))));
        return;
      }
      const Real h = std::min(dt, t_end - s.t);
      previous = s;
      StepReport rep;
      try {
        rep = integrator_->step(sys, s, h);
      } catch (const Error& e) {
        // A force that cannot be evaluated in the step's state (a journal at its
        // bearing's wall): the run ends there, its samples so far kept.
        s = previous;
        fail(s, e.what());
        return;
      }
      ++result_.steps;
      result_.rejected += rep.rejected;
      result_.factorizations += rep.factorizations;
      result_.newton_iterations += rep.iterations;
      if (!rep.ok) {
        s = previous;
        fail(s, rep.message);
        return;
      }
      if (integrator_->adaptive()) dt = rep.dt_next;
      if (const std::string why = blown_up(s); !why.empty()) {
        fail(s, why);
        s = previous;
        return;
      }
      while (static_cast<Real>(next_output) * options_.output_interval <= s.t * (1 + 1e-12) &&
             static_cast<Real>(next_output) * options_.output_interval <= t_end * (1 + 1e-12)) {
        const Real to = std::min(static_cast<Real>(next_output) * options_.output_interval, s.t);
        interpolate(previous, s, to, xi, vi);
        emit(to, xi, vi);
        ++next_output;
      }
      watch(s);
      if (progress_ && result_.steps % 200 == 0) progress_(s.t, rep.dt);
    }
  }

  const Model& model_;
  const TransientOptions& options_;
  const SampleSink& sink_;
  const ProgressSink& progress_;
  const Vector constant_load_;
  RotorSystem rotor_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<ProjectedSystem> projected_;
  const Index n_model_;
  TransientResult result_;
  Real w_lo_ = 0, w_hi_ = 0;  // the envelopes' speed range
  Index bins_ = 1;
  std::vector<OperatingSeries> operating_now_;
  std::vector<std::vector<Index>> clearance_dofs_;
  Vector x_model_, v_model_, x_full_, v_full_;  // work vectors
};

}  // namespace

TransientResult run_transient(const Model& model, const TransientOptions& options, const SampleSink& sink,
                              const ProgressSink& progress) {
  check_options(model, options);
  return TransientRun(model, options, sink, progress).run();
}

}  // namespace feran

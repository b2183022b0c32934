#include <feran/analyses/response/harmonic_response.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <feran/analyses/static/equilibrium.hpp>
#include <feran/assembly/assembler.hpp>
#include <feran/core/banded_lu.hpp>
#include <feran/core/parallel.hpp>

namespace feran {

namespace {

const Complex I(0.0, 1.0);
using ComplexSparse = Eigen::SparseMatrix<Complex>;

NodeAmplitudes node_values(const ComplexVector& q, Index node) {
  NodeAmplitudes a;
  for (int d = 0; d < dofs_per_node; ++d) a[static_cast<std::size_t>(d)] = q(dofs_per_node * node + d);
  return a;
}

Real peak_lateral(const NodeAmplitudes& f) {
  return orbit(f[static_cast<std::size_t>(Dof::v)], f[static_cast<std::size_t>(Dof::w)]).major;
}

struct SegmentData {
  Index element;
  ShaftSegment segment;
  LocalMatrices matrices;  // speed-independent for shaft elements
};

// An element's end forces Z·q for its dynamic stiffness at rotor speed Ω and
// excitation frequency ω, Z = (1 + jη)K + ΩK_i − ω²M + jω(C + C_i + ΩG), η its loss
// factor plus @p extra_eta. Z's real and imaginary parts are formed apart (real
// matrices: this runs for every shaft element at every point).
ComplexVector element_forces(const LocalMatrices& lm, Real speed, Real omega, Real extra_eta, const ComplexVector& q) {
  const auto n = static_cast<Index>(lm.dofs.size());
  Matrix re = Matrix::Zero(n, n), im = Matrix::Zero(n, n);
  if (lm.K.size()) re += lm.K, im += (lm.loss_factor + extra_eta) * lm.K;
  if (lm.M.size()) re -= (omega * omega) * lm.M;
  if (lm.Ki.size()) re += speed * lm.Ki;
  if (lm.C.size()) im += omega * lm.C;
  if (lm.Ci.size()) im += omega * lm.Ci;
  if (lm.G.size()) im += (omega * speed) * lm.G;
  const Vector qr = q.real(), qi = q.imag();
  ComplexVector f(n);
  f.real() = re * qr - im * qi;
  f.imag() = re * qi + im * qr;
  return f;
}

// Positions in @p pattern's value array of the nonzeros of @p A (same size, both
// compressed, column-major); −1 for an entry outside the pattern.
std::vector<Index> positions(const SparseMatrix& A, const ComplexSparse& pattern) {
  std::vector<Index> pos;
  pos.reserve(static_cast<std::size_t>(A.nonZeros()));
  for (Index j = 0; j < A.outerSize(); ++j) {
    Index p = pattern.outerIndexPtr()[j];
    const Index end = pattern.outerIndexPtr()[j + 1];
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      while (p < end && pattern.innerIndexPtr()[p] < it.row()) ++p;
      pos.push_back(p < end && pattern.innerIndexPtr()[p] == it.row() ? p : -1);
    }
  }
  return pos;
}

// The dynamic stiffness K(1 + jη) + Ω·K_i − ω²M + jω(C + C_i + Ω·G) + j·K_h on one
// sparsity pattern, the union of the matrices' patterns: a sweep only rewrites the
// values, so the LU's symbolic analysis (ordering, elimination tree) is done once.
class DynamicStiffness {
 public:
  explicit DynamicStiffness(const SystemMatrices& constant) : constant_(constant) {
    SparseMatrix sum = abs_sum(constant_);
    A_ = sum.cast<Complex>();
    A_.makeCompressed();
    locate();
  }

  // A at the point; false when a speed-dependent element fills an entry outside
  // the pattern (a coefficient that was zero when the pattern was made), after
  // which the pattern has been widened and needs a new analysis.
  bool assemble(const SystemMatrices* variable, Real speed, Real omega, Real eta, ComplexSparse& A) const {
    A = A_;
    std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), Complex(0.0));
    add(constant_, constant_positions_, speed, omega, eta, A);
    if (!variable) return true;
    std::array<std::vector<Index>, 7> pos;
    for (std::size_t m = 0; m < pos.size(); ++m) {
      pos[m] = positions(*parts(*variable)[m], A_);
      if (std::find(pos[m].begin(), pos[m].end(), -1) != pos[m].end()) return false;
    }
    add(*variable, pos, speed, omega, eta, A);
    return true;
  }

  // Adds the pattern of @p variable to the union.
  void widen(const SystemMatrices& variable) {
    SparseMatrix sum = abs_sum(constant_) + abs_sum(variable) + SparseMatrix(A_.real().cwiseAbs());
    A_ = sum.cast<Complex>();
    A_.makeCompressed();
    locate();
  }

  const ComplexSparse& pattern() const { return A_; }

 private:
  static std::array<const SparseMatrix*, 7> parts(const SystemMatrices& s) {
    return {&s.M, &s.C, &s.K, &s.G, &s.Ci, &s.Ki, &s.Kh};
  }
  static SparseMatrix abs_sum(const SystemMatrices& s) {
    SparseMatrix sum = s.M.cwiseAbs();
    for (const SparseMatrix* m : parts(s)) sum += m->cwiseAbs();
    return sum;
  }
  void locate() {
    for (std::size_t m = 0; m < constant_positions_.size(); ++m)
      constant_positions_[m] = positions(*parts(constant_)[m], A_);
  }
  // Coefficients of M, C, K, G, C_i, K_i, K_h in the dynamic stiffness.
  static void add(const SystemMatrices& s, const std::array<std::vector<Index>, 7>& pos, Real speed, Real omega,
                  Real eta, ComplexSparse& A) {
    const std::array<Complex, 7> coef{
        Complex(-omega * omega, 0.0), Complex(0.0, omega), Complex(1.0, eta), Complex(0.0, omega * speed),
        Complex(0.0, omega),          Complex(speed, 0.0), Complex(0.0, 1.0)};
    Complex* values = A.valuePtr();
    const auto mats = parts(s);
    for (std::size_t m = 0; m < mats.size(); ++m) {
      const Real* v = mats[m]->valuePtr();
      const std::vector<Index>& p = pos[m];
      for (std::size_t k = 0; k < p.size(); ++k) values[p[k]] += coef[m] * v[k];
    }
  }

  SystemMatrices constant_;
  ComplexSparse A_;  // the pattern (values unused)
  std::array<std::vector<Index>, 7> constant_positions_;
};

// One point of a sweep, computed independently of the others.
struct PointResult {
  bool solved = false;
  bool skipped = false;  // not started: a stop was asked for
  bool finite = true;    // false: the solve gave non-finite amplitudes
  std::vector<NodeAmplitudes> probes, springs, supports, reactions;
  std::vector<Real> support_orbits;   // per support: the journal's orbit relative to its housing [m]
  std::vector<SectionForces> forces;  // every station (StationOutput::all)
  std::vector<SectionStress> stress;
  StationPeaks peaks;
  StabilityPoint stability;
};

// Keeps the larger of a peak and a station's value.
void consider(StationPeak& peak, Real value, Index station) {
  if (peak.station < 0 || value > peak.value) peak = {value, station};
}

// Per thread: the matrix and its LU (analysed for the pattern it was last given):
// banded with partial pivoting where the half-bandwidth is at most 64 (a shaft line's
// is about 10; zgbtrf on 3010 DOF takes a tenth of the sparse LU's time,
// docs/performance.md), else the sparse LU.
struct Workspace {
  ComplexSparse A;
  Eigen::SparseLU<ComplexSparse, Eigen::COLAMDOrdering<int>> lu;
  ComplexBandedLU band;
  bool banded = false;
  bool used_sparse = false;  // a point was solved by the sparse LU
  Index analysed_for = -1;   // pattern generation the LU was analysed for
};

}  // namespace

namespace {

// A sweep of the response in named steps: what it reports (items()), each point's
// dynamic stiffness (factorize()), load and solve (solve_point()) and the forces derived
// from its motion (transmitted_forces(), reactions(), stations()), then the points in
// sweep order (gather()) and the supports' state (operating()).
class HarmonicSweep {
 public:
  HarmonicSweep(const Model& model, const HarmonicOptions& options)
      : model_(model),
        options_(options),
        supported_(has_supports(model)),
        linear_copy_(supported_ ? linearised(model) : Model{}),
        linear_(supported_ ? linear_copy_ : model),
        assembler_(linear_),
        T_(assembler_.dof_map().transformation().cast<Complex>()),
        Tt_(T_.transpose()),
        stiffness_(assembler_.constant()) {
    result_.frequency_sweep = !options.frequencies.empty();
    result_.info.method = SolverMethod::sparse_lu;
    if (result_.frequency_sweep) require_running(model.forces, options.speed);
    for (const Real speed : options.speeds) require_running(model.forces, speed);
  }

  HarmonicResult run() {
    items();
    const std::size_t n_points = result_.frequency_sweep ? options_.frequencies.size() : options_.speeds.size();
    points_.resize(n_points);
    // The stability of the linearised model itself (its supports' equilibrium solved
    // once per speed for both), with what no speed changes judged once; a frequency
    // sweep turns at one speed: its stability once.
    if (options_.stability) scan_.emplace(linear_, needs_speed(model_));
    if (options_.stability && result_.frequency_sweep && n_points > 0)
      fixed_speed_stability_ = scan_->at(options_.speed);
    std::vector<Workspace> workspaces(static_cast<std::size_t>(resolve_threads(options_.n_threads)));
    parallel_for(static_cast<Index>(n_points), options_.n_threads, [&](Index k, int worker) {
      solve_point(static_cast<std::size_t>(k), workspaces[static_cast<std::size_t>(worker)]);
    });
    if (n_points > 0 &&
        std::none_of(workspaces.begin(), workspaces.end(), [](const Workspace& w) { return w.used_sparse; }) &&
        std::any_of(workspaces.begin(), workspaces.end(), [](const Workspace& w) { return w.banded; }))
      result_.info.method = SolverMethod::banded_lu;
    // Results in sweep order, up to the first point that could not be solved.
    for (std::size_t k = 0; k < n_points && gather(k); ++k) {
    }
    operating();
    return std::move(result_);
  }

 private:
  Real speed_of(std::size_t k) const { return result_.frequency_sweep ? options_.speed : options_.speeds[k]; }
  Real omega_of(std::size_t k) const { return result_.frequency_sweep ? options_.frequencies[k] : options_.speeds[k]; }

  // What the sweep reports: probes, spring–dampers, supports, reactions, stations.
  void items() {
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& el = model_.elements[e];
      if (const auto segment = el.shaft_segment())
        beams_.push_back({static_cast<Index>(e), *segment, el.local_matrices({})});
      if (el.transmission(0.0)) springs_.push_back(static_cast<Index>(e));
    }
    reaction_items();
    for (Index node : options_.probes) result_.probes.push_back({node, {}, {}});
    for (const Index e : springs_) result_.springs.push_back({e, {}, {}});
    // The supports' tangents: the elements linearised() appended, in the order of the
    // supporting forces.
    for (std::size_t i = 0, e = model_.elements.size(); i < model_.forces.size(); ++i)
      if (model_.forces[i].supports()) {
        result_.supports.push_back({static_cast<Index>(i), {}, {}, {}, {}});
        support_elements_.push_back(static_cast<Index>(e++));
      }
    if (options_.stations != StationOutput::none) result_.shaft_stations = shaft_stations(model_);
    if (options_.stations == StationOutput::all)
      for (const ShaftStation& st : result_.shaft_stations) result_.stations.push_back({st, {}, {}});
  }

  // The nodes with fixed DOFs and the elements touching one: their end forces give
  // the support reactions.
  void reaction_items() {
    std::vector<bool> fixed_dof(static_cast<std::size_t>(model_.n_dofs()), false);
    for (const FixedDofs& f : model_.fixed)
      for (int d = 0; d < dofs_per_node; ++d)
        if (f.dofs[static_cast<std::size_t>(d)]) fixed_dof[static_cast<std::size_t>(dofs_per_node * f.node + d)] = true;
    for (std::size_t e = 0; e < linear_.elements.size(); ++e) {
      const std::vector<Index> lm_dofs = linear_.elements[e].dofs();
      if (std::any_of(lm_dofs.begin(), lm_dofs.end(), [&](Index d) { return fixed_dof[static_cast<std::size_t>(d)]; }))
        reaction_elements_.push_back(static_cast<Index>(e));
    }
    for (const FixedDofs& f : model_.fixed) {
      auto it = std::find_if(result_.reactions.begin(), result_.reactions.end(),
                             [&](const ReactionResponse& r) { return r.node == f.node; });
      if (it == result_.reactions.end()) {
        result_.reactions.push_back({f.node, {}, {}, {}});
        it = result_.reactions.end() - 1;
      }
      for (int d = 0; d < dofs_per_node; ++d)
        it->fixed[static_cast<std::size_t>(d)] |= f.dofs[static_cast<std::size_t>(d)];
    }
  }

  // The dynamic stiffness at (speed, ω) in @p ws, its LU analysed for the pattern the
  // sweep has reached (a speed-dependent coefficient may widen it).
  void assemble(Real speed, Real omega, Workspace& ws) {
    std::optional<SystemMatrices> variable;
    // Frequency-dependent coefficients at the excitation frequency itself.
    if (assembler_.speed_dependent()) variable = assembler_.variable_at(speed, omega);
    const SystemMatrices* var = variable ? &*variable : nullptr;
    for (;;) {
      Index gen = 0;
      bool filled = false;
      {
        const std::lock_guard<std::mutex> lock(pattern_mutex_);
        gen = generation_;
        filled = stiffness_.assemble(var, speed, omega, options_.loss_factor, ws.A);
        if (!filled) {
          stiffness_.widen(*var);
          ++generation_;
        }
      }
      if (!filled) continue;
      if (ws.analysed_for != gen) {
        ws.banded = ws.band.analyse(ws.A, 64);
        if (!ws.banded) ws.lu.analyzePattern(ws.A);
        ws.analysed_for = gen;
      }
      return;
    }
  }

  // The motion under @p f_reduced, or nothing where the dynamic stiffness is singular.
  static std::optional<ComplexVector> solve(const ComplexVector& f_reduced, Workspace& ws) {
    if (ws.banded) {
      if (!ws.band.factorize(ws.A)) return std::nullopt;
      ComplexVector y = f_reduced;
      ws.band.solve_in_place(y);
      return y;
    }
    ws.lu.factorize(ws.A);
    if (ws.lu.info() != Eigen::Success) return std::nullopt;
    ws.used_sparse = true;
    return ComplexVector(ws.lu.solve(f_reduced));
  }

  void solve_point(std::size_t k, Workspace& ws) {
    PointResult& out = points_[k];
    if (options_.stop.requested()) {
      out.skipped = true;
      return;
    }
    const Real speed = speed_of(k), omega = omega_of(k);
    assemble(speed, omega, ws);
    ComplexVector f_full = ComplexVector::Zero(model_.n_dofs());
    const HarmonicExcitation excitation{speed, omega, !result_.frequency_sweep, options_.unbalance};
    for (const Force& force : model_.forces) force.add_harmonic(excitation, f_full);
    for (const HarmonicForce& force : options_.extra_forces) force.add_harmonic(excitation, f_full);
    const ComplexVector f_reduced = Tt_ * f_full;
    ComplexVector q_full;
    if (f_reduced.isZero(0.0)) {
      // Nothing acts (an unbalance at rest): the response is zero, even where the
      // dynamic stiffness is singular (free axial or torsional motion at ω = 0).
      q_full = ComplexVector::Zero(model_.n_dofs());
    } else {
      const std::optional<ComplexVector> y = solve(f_reduced, ws);
      if (!y) return;
      q_full = T_ * *y;
    }
    out.solved = true;
    if (options_.stability) out.stability = fixed_speed_stability_ ? *fixed_speed_stability_ : scan_->at(speed);
    if (!q_full.allFinite()) {
      out.finite = false;
      return;
    }
    for (const ProbeResponse& p : result_.probes) out.probes.push_back(node_values(q_full, p.node));
    transmitted_forces(q_full, speed, omega, out);
    if (!result_.reactions.empty()) reactions(q_full, f_full, speed, omega, out);
    stations(q_full, speed, omega, out);
  }

  // What each spring–damper and support transmits: (K(1 + jη) + jωC − ω²M)·(q_a − q_b), and
  // each journal's orbit relative to its housing.
  void transmitted_forces(const ComplexVector& q_full, Real speed, Real omega, PointResult& out) const {
    // The motion of a connecting element's first node relative to its second.
    auto relative = [&](const Transmission& link) {
      NodeAmplitudes dq = node_values(q_full, link.node_a);
      if (link.node_b) {
        const NodeAmplitudes qb = node_values(q_full, *link.node_b);
        for (std::size_t d = 0; d < dq.size(); ++d) dq[d] -= qb[d];
      }
      return dq;
    };
    auto transmitted = [&](const Element& element) {
      const Transmission link = *element.transmission(speed, omega);
      const NodeAmplitudes dq = relative(link);
      const Eigen::Map<const Eigen::Matrix<Complex, dofs_per_node, 1>> delta(dq.data());
      Eigen::Matrix<Complex, dofs_per_node, dofs_per_node> Z =
          Complex(1.0, link.loss_factor + options_.loss_factor) * link.K.cast<Complex>() +
          I * omega * link.C.cast<Complex>();
      if (link.M.size() != 0) Z -= omega * omega * link.M.cast<Complex>();  // a seal's added mass
      const Eigen::Matrix<Complex, dofs_per_node, 1> force = Z * delta;
      NodeAmplitudes f;
      for (int d = 0; d < dofs_per_node; ++d) f[static_cast<std::size_t>(d)] = force(d);
      return f;
    };
    for (const Index e : springs_) out.springs.push_back(transmitted(model_.elements[static_cast<std::size_t>(e)]));
    for (const Index e : support_elements_) {
      const Element& element = linear_.elements[static_cast<std::size_t>(e)];
      out.supports.push_back(transmitted(element));
      const NodeAmplitudes dq = relative(*element.transmission(speed, omega));
      out.support_orbits.push_back(
          orbit(dq[static_cast<std::size_t>(Dof::v)], dq[static_cast<std::size_t>(Dof::w)]).major);
    }
  }

  // The force the structure puts on its supports at the fixed DOFs: the applied load
  // there minus the element forces (dynamic stiffness times motion).
  void reactions(const ComplexVector& q_full, const ComplexVector& f_full, Real speed, Real omega,
                 PointResult& out) const {
    ComplexVector r = f_full;
    for (Index e : reaction_elements_) {
      const LocalMatrices lm = linear_.elements[static_cast<std::size_t>(e)].local_matrices({speed});
      const auto n = static_cast<Index>(lm.dofs.size());
      ComplexVector q(n);
      for (Index i = 0; i < n; ++i) q(i) = q_full(lm.dofs[static_cast<std::size_t>(i)]);
      const ComplexVector fe = element_forces(lm, speed, omega, options_.loss_factor, q);
      for (Index i = 0; i < n; ++i) r(lm.dofs[static_cast<std::size_t>(i)]) -= fe(i);
    }
    for (const ReactionResponse& rr : result_.reactions) {
      NodeAmplitudes f{};
      for (int d = 0; d < dofs_per_node; ++d)
        if (rr.fixed[static_cast<std::size_t>(d)]) f[static_cast<std::size_t>(d)] = r(dofs_per_node * rr.node + d);
      out.reactions.push_back(f);
    }
  }

  // The section forces and stresses at the shaft stations. Each element's end forces
  // include its own inertia and gyroscopic moments, so the section forces are in
  // equilibrium with the element's motion.
  void stations(const ComplexVector& q_full, Real speed, Real omega, PointResult& out) const {
    std::size_t b = 0;
    ComplexVector end_forces;
    const bool keep_all = options_.stations == StationOutput::all;
    for (std::size_t i = 0; i < result_.shaft_stations.size(); ++i) {
      const ShaftStation& st = result_.shaft_stations[i];
      if (beams_[b].element != st.element || end_forces.size() == 0) {
        while (beams_[b].element != st.element) ++b;
        end_forces = element_forces(beams_[b].matrices, speed, omega, options_.loss_factor,
                                    element_values(beams_[b].segment, q_full));
      }
      const SectionForces forces = section_forces(end_forces, st.end);
      const SectionStress stress = section_stress(beams_[b].segment.section_at_end(st.end), forces);
      const auto station = static_cast<Index>(i);
      consider(out.peaks.von_mises, stress.von_mises, station);
      consider(out.peaks.bending_moment, orbit(forces.My, forces.Mz).major, station);
      consider(out.peaks.shear_force, orbit(forces.Vy, forces.Vz).major, station);
      if (keep_all) {
        out.forces.push_back(forces);
        out.stress.push_back(stress);
      }
    }
  }

  // Point k appended to the result; false (the sweep ends there, said in its info)
  // when it was not started, not solved or not finite.
  bool gather(std::size_t k) {
    PointResult& pt = points_[k];
    const Real speed = speed_of(k), omega = omega_of(k);
    const Real at_hz = rad_to_hz(result_.frequency_sweep ? omega : speed);
    if (pt.skipped) {
      result_.info.fail(SolverStatus::interrupted, fmt::format("stopped on request before {:.6g} Hz", at_hz));
      return false;
    }
    if (!pt.solved) {
      result_.info.status = SolverStatus::numerical_failure;
      result_.info.message = fmt::format(
          "the dynamic stiffness is singular at {:.6g} Hz (an undamped resonance on the grid); "
          "add damping or move the grid",
          at_hz);
      return false;
    }
    if (!pt.finite) {
      result_.info.fail(SolverStatus::numerical_failure,
                        fmt::format("the response is not finite at {:.6g} Hz (the dynamic stiffness is too badly "
                                    "conditioned for the loads); the results stop before it",
                                    at_hz));
      return false;
    }
    result_.speeds.push_back(speed);
    result_.frequencies.push_back(omega);
    if (options_.stability) result_.stability.push_back(pt.stability);
    ++result_.info.n_converged;
    for (std::size_t p = 0; p < result_.probes.size(); ++p) {
      ProbeResponse& pr = result_.probes[p];
      pr.q.push_back(pt.probes[p]);
      pr.orbit.push_back(
          orbit(pt.probes[p][static_cast<std::size_t>(Dof::v)], pt.probes[p][static_cast<std::size_t>(Dof::w)]));
    }
    for (std::size_t s = 0; s < result_.springs.size(); ++s) {
      result_.springs[s].force.push_back(pt.springs[s]);
      result_.springs[s].peak_lateral.push_back(peak_lateral(pt.springs[s]));
    }
    for (std::size_t s = 0; s < result_.supports.size(); ++s) {
      SupportForceResponse& sr = result_.supports[s];
      sr.amplitude.push_back(pt.supports[s]);
      sr.peak_lateral.push_back(peak_lateral(pt.supports[s]));
      sr.orbit.push_back(pt.support_orbits[s]);
      const std::optional<Real> c = model_.forces[static_cast<std::size_t>(sr.force)].clearance();
      sr.orbit_clearance_ratio.push_back(c && *c > 0 ? pt.support_orbits[s] / *c
                                                     : std::numeric_limits<Real>::quiet_NaN());
    }
    for (std::size_t r = 0; r < result_.reactions.size(); ++r) {
      result_.reactions[r].force.push_back(pt.reactions[r]);
      result_.reactions[r].peak_lateral.push_back(peak_lateral(pt.reactions[r]));
    }
    if (!result_.shaft_stations.empty()) result_.station_peaks.push_back(pt.peaks);
    for (std::size_t s = 0; s < result_.stations.size(); ++s) {
      result_.stations[s].forces.push_back(pt.forces[s]);
      result_.stations[s].stress.push_back(pt.stress[s]);
    }
    pt = PointResult{};  // free as we go
    return true;
  }

  // The supports' state at each speed's equilibrium (found above for the tangents); a
  // frequency sweep runs at one speed.
  void operating() {
    if (!supported_) return;
    result_.operating = operating_series(model_);
    for (std::size_t k = 0; k < result_.speeds.size(); ++k) {
      if (k > 0 && result_.speeds[k] == result_.speeds[k - 1])
        for (OperatingSeries& s : result_.operating) s.values.push_back(s.values.back());
      else
        append_at_equilibrium(result_.operating, linear_, result_.speeds[k]);
    }
  }

  const Model& model_;
  const HarmonicOptions& options_;
  // Supports (fluid-film bearings) as their tangent about the equilibrium at each
  // speed: elements after the model's own, which keep their indices (a copy only when
  // there are supports to replace).
  const bool supported_;
  const Model linear_copy_;
  const Model& linear_;
  const Assembler assembler_;
  const ComplexSparse T_, Tt_;
  DynamicStiffness stiffness_;
  Index generation_ = 0;  // changes when a speed-dependent coefficient widens the pattern
  std::mutex pattern_mutex_;
  HarmonicResult result_;
  std::vector<SegmentData> beams_;
  std::vector<Index> springs_;            // the connecting elements, whose transmitted force is reported
  std::vector<Index> reaction_elements_;  // elements touching a fixed DOF
  std::vector<Index> support_elements_;   // the supports' tangents in the linearised model
  std::vector<PointResult> points_;
  std::optional<StabilityScan> scan_;
  std::optional<StabilityPoint> fixed_speed_stability_;
};

}  // namespace

HarmonicResult run_harmonic_response(const Model& model, const HarmonicOptions& options) {
  return HarmonicSweep(model, options).run();
}

Index first_unstable_point(const HarmonicResult& result) {
  for (std::size_t k = 0; k < result.stability.size(); ++k)
    if (result.stability[k].unstable) return static_cast<Index>(k);
  return -1;
}

Index unstable_points(const HarmonicResult& result) {
  return static_cast<Index>(std::count_if(result.stability.begin(), result.stability.end(),
                                          [](const StabilityPoint& s) { return s.unstable; }));
}

ResponseSummary summarize(const HarmonicResult& r) {
  ResponseSummary s;
  auto consider = [](ResponseSummary::Peak& peak, Real value, Index point, Index item) {
    if (peak.point < 0 || value > peak.value) peak = {value, point, item};
  };
  for (std::size_t p = 0; p < r.probes.size(); ++p) {
    ResponseSummary::Peak peak;
    for (std::size_t k = 0; k < r.probes[p].orbit.size(); ++k)
      consider(peak, r.probes[p].orbit[k].major, static_cast<Index>(k), static_cast<Index>(p));
    s.probe_peaks.push_back(peak);
  }
  for (std::size_t i = 0; i < r.springs.size(); ++i)
    for (std::size_t k = 0; k < r.springs[i].peak_lateral.size(); ++k)
      consider(s.spring_force, r.springs[i].peak_lateral[k], static_cast<Index>(k), static_cast<Index>(i));
  for (std::size_t i = 0; i < r.supports.size(); ++i)
    for (std::size_t k = 0; k < r.supports[i].peak_lateral.size(); ++k)
      consider(s.support_force, r.supports[i].peak_lateral[k], static_cast<Index>(k), static_cast<Index>(i));
  for (std::size_t i = 0; i < r.reactions.size(); ++i)
    for (std::size_t k = 0; k < r.reactions[i].peak_lateral.size(); ++k)
      consider(s.reaction_force, r.reactions[i].peak_lateral[k], static_cast<Index>(k), static_cast<Index>(i));
  for (std::size_t k = 0; k < r.station_peaks.size(); ++k) {
    const StationPeak& p = r.station_peaks[k].von_mises;
    if (p.station >= 0) consider(s.stress, p.value, static_cast<Index>(k), p.station);
  }
  return s;
}

const char* to_string(StationOutput output) {
  switch (output) {
    case StationOutput::all:
      return "all";
    case StationOutput::summary:
      return "summary";
    case StationOutput::none:
      return "none";
  }
  return "?";
}

std::vector<std::string> clearance_warnings(const HarmonicResult& result, const Model& model) {
  std::vector<std::string> out;
  for (const SupportForceResponse& sr : result.supports) {
    Real largest = 0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < sr.orbit_clearance_ratio.size(); ++k)
      if (sr.orbit_clearance_ratio[k] > largest) largest = sr.orbit_clearance_ratio[k], at = k;
    if (!(largest > 1)) continue;
    const Force& force = model.forces[static_cast<std::size_t>(sr.force)];
    const Real x = result.frequency_sweep ? result.frequencies[at] : result.speeds[at];
    const std::string where = result.frequency_sweep ? fmt::format("{:.6g} Hz excitation", x / (2 * pi))
                                                     : fmt::format("{:.6g} rpm", x * 30 / pi);
    out.push_back(
        fmt::format("the journal orbit in {} reaches {:.3g} × its clearance at {}: the linearised "
                    "response is no motion the bearing allows there (the excitation is too large for a "
                    "linear analysis; a run-up shows the real motion)",
                    force.label().empty() ? std::string(force.kind()) : "'" + force.label() + "'", largest, where));
  }
  return out;
}

}  // namespace feran

#include <feran/analyses/harmonic/harmonic_response.hpp>

#include <algorithm>
#include <cmath>

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <feran/assembly/assembler.hpp>
#include <feran/elements/spring_damper.hpp>

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

struct BeamData {
  Index element;
  const TimoshenkoBeam* beam;
  LocalMatrices matrices;  // speed-independent for shaft elements
};

// An element's dynamic stiffness at rotor speed Ω and excitation frequency ω:
// (1 + jη)K + ΩK_i − ω²M + jω(C + C_i + ΩG), η its loss factor plus @p extra_eta.
ComplexMatrix dynamic_stiffness(const LocalMatrices& lm, Real speed, Real omega, Real extra_eta) {
  const auto n = static_cast<Index>(lm.dofs.size());
  ComplexMatrix Z = ComplexMatrix::Zero(n, n);
  if (lm.K.size()) Z += Complex(1.0, lm.loss_factor + extra_eta) * lm.K.cast<Complex>();
  if (lm.M.size()) Z -= omega * omega * lm.M.cast<Complex>();
  if (lm.C.size()) Z += I * omega * lm.C.cast<Complex>();
  if (lm.Ci.size()) Z += I * omega * lm.Ci.cast<Complex>();
  if (lm.G.size()) Z += I * omega * speed * lm.G.cast<Complex>();
  if (lm.Ki.size()) Z += speed * lm.Ki.cast<Complex>();
  return Z;
}

}  // namespace

ComplexVector unbalance_forces(const Model& model, Real speed) {
  ComplexVector f = ComplexVector::Zero(model.n_dofs());
  for (const Unbalance& u : model.unbalances) {
    // F_y + i·F_z = m r Ω² e^{i(Ωt + φ)}: F_y = m r Ω² e^{iφ}, F_z = −i·m r Ω² e^{iφ}
    // as amplitudes of Re(·e^{iΩt}); the lever l adds M_y = −l·F_z, M_z = l·F_y.
    const Complex fy = u.mass * u.radius * speed * speed * std::polar(1.0, u.phase);
    const Complex fz = -I * fy;
    f(global_dof(u.node, Dof::v)) += fy;
    f(global_dof(u.node, Dof::w)) += fz;
    f(global_dof(u.node, Dof::ry)) += -u.lever * fz;
    f(global_dof(u.node, Dof::rz)) += u.lever * fy;
  }
  return f;
}

void add_harmonic_forces(const std::vector<HarmonicForce>& forces, ComplexVector& f) {
  for (const HarmonicForce& h : forces) {
    const Complex a = h.amplitude * std::polar(1.0, h.phase);
    switch (h.kind) {
      case HarmonicForce::Kind::fixed: f(global_dof(h.node, h.direction)) += a; break;
      case HarmonicForce::Kind::rotating_force:
        f(global_dof(h.node, Dof::v)) += a;
        f(global_dof(h.node, Dof::w)) += -I * a;
        break;
      case HarmonicForce::Kind::rotating_moment:
        f(global_dof(h.node, Dof::ry)) += a;
        f(global_dof(h.node, Dof::rz)) += -I * a;
        break;
    }
  }
}

HarmonicResult run_harmonic_response(const Model& model, const HarmonicOptions& options) {
  HarmonicResult result;
  result.frequency_sweep = !options.frequencies.empty();
  result.info.method = "sparse-lu";
  const Assembler assembler(model);
  const DofMap& dofs = assembler.dof_map();
  const ComplexSparse T = dofs.transformation().cast<Complex>();
  const ComplexSparse Tt = T.transpose();

  std::vector<BeamData> beams;
  std::vector<std::pair<Index, const SpringDamper*>> springs;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    if (const auto* b = el.target<TimoshenkoBeam>()) beams.push_back({static_cast<Index>(e), b, el.local_matrices({})});
    if (const auto* s = el.target<SpringDamper>()) springs.emplace_back(static_cast<Index>(e), s);
  }
  // Elements touching a fixed DOF: their end forces give the support reactions.
  std::vector<bool> fixed_dof(static_cast<std::size_t>(model.n_dofs()), false);
  for (const FixedDofs& f : model.fixed)
    for (int d = 0; d < dofs_per_node; ++d)
      if (f.dofs[static_cast<std::size_t>(d)]) fixed_dof[static_cast<std::size_t>(dofs_per_node * f.node + d)] = true;
  std::vector<Index> reaction_elements;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const LocalMatrices lm = model.elements[e].local_matrices({});
    if (std::any_of(lm.dofs.begin(), lm.dofs.end(), [&](Index d) { return fixed_dof[static_cast<std::size_t>(d)]; }))
      reaction_elements.push_back(static_cast<Index>(e));
  }
  for (const FixedDofs& f : model.fixed) {
    auto it = std::find_if(result.reactions.begin(), result.reactions.end(),
                           [&](const ReactionResponse& r) { return r.node == f.node; });
    if (it == result.reactions.end()) {
      result.reactions.push_back({f.node, {}, {}, {}});
      it = result.reactions.end() - 1;
    }
    for (int d = 0; d < dofs_per_node; ++d) it->fixed[static_cast<std::size_t>(d)] |= f.dofs[static_cast<std::size_t>(d)];
  }

  for (Index node : options.probes) result.probes.push_back({node, {}, {}});
  for (const auto& [e, s] : springs) result.springs.push_back({e, {}, {}});
  for (const ShaftStation& st : shaft_stations(model)) result.stations.push_back({st, {}, {}});

  const std::size_t n_points = result.frequency_sweep ? options.frequencies.size() : options.speeds.size();
  Eigen::SparseLU<ComplexSparse, Eigen::COLAMDOrdering<int>> lu;
  for (std::size_t k = 0; k < n_points; ++k) {
    const Real speed = result.frequency_sweep ? options.speed : options.speeds[k];
    const Real omega = result.frequency_sweep ? options.frequencies[k] : speed;
    const SystemMatrices sys = assembler.at(speed);

    const SparseMatrix real_part = sys.stiffness(speed) - omega * omega * sys.M;
    const SparseMatrix imag_part = omega * sys.damping(speed) + sys.Kh + options.loss_factor * sys.K;
    ComplexSparse A = real_part.cast<Complex>() + I * imag_part.cast<Complex>();
    A.makeCompressed();

    ComplexVector f_full = ComplexVector::Zero(model.n_dofs());
    if (!result.frequency_sweep && options.unbalance) f_full += unbalance_forces(model, speed);
    if (options.model_forces) add_harmonic_forces(model.forces, f_full);
    add_harmonic_forces(options.extra_forces, f_full);

    lu.compute(A);
    if (lu.info() != Eigen::Success) {
      result.info.converged = false;
      result.info.message = fmt::format(
          "the dynamic stiffness is singular at {:.6g} Hz (an undamped resonance on the grid); "
          "add damping or move the grid",
          rad_to_hz(result.frequency_sweep ? omega : speed));
      break;
    }
    const ComplexVector q_full = T * ComplexVector(lu.solve(Tt * f_full));
    result.speeds.push_back(speed);
    result.frequencies.push_back(omega);
    ++result.info.n_converged;

    for (ProbeResponse& p : result.probes) {
      p.q.push_back(node_values(q_full, p.node));
      p.orbit.push_back(orbit(p.q.back()[static_cast<std::size_t>(Dof::v)], p.q.back()[static_cast<std::size_t>(Dof::w)]));
    }
    for (std::size_t s = 0; s < springs.size(); ++s) {
      const SpringDamper& sd = *springs[s].second;
      NodeAmplitudes dq = node_values(q_full, sd.node_a());
      if (sd.node_b()) {
        const NodeAmplitudes qb = node_values(q_full, *sd.node_b());
        for (std::size_t d = 0; d < dq.size(); ++d) dq[d] -= qb[d];
      }
      const Eigen::Map<const Eigen::Matrix<Complex, dofs_per_node, 1>> delta(dq.data());
      const Eigen::Matrix<Complex, dofs_per_node, 1> force =
          (Complex(1.0, sd.coefficients().loss_factor + options.loss_factor) * sd.stiffness_6x6(speed).cast<Complex>() +
           I * omega * sd.damping_6x6(speed).cast<Complex>()) * delta;
      NodeAmplitudes out;
      for (int d = 0; d < dofs_per_node; ++d) out[static_cast<std::size_t>(d)] = force(d);
      result.springs[s].force.push_back(out);
      result.springs[s].peak_lateral.push_back(peak_lateral(out));
    }
    if (!result.reactions.empty()) {
      // The force the structure puts on its supports at the fixed DOFs: the applied
      // load there minus the element forces (dynamic stiffness times motion).
      ComplexVector r = f_full;
      for (Index e : reaction_elements) {
        const LocalMatrices lm = model.elements[static_cast<std::size_t>(e)].local_matrices({speed});
        const auto n = static_cast<Index>(lm.dofs.size());
        ComplexVector q(n);
        for (Index i = 0; i < n; ++i) q(i) = q_full(lm.dofs[static_cast<std::size_t>(i)]);
        const ComplexVector fe = dynamic_stiffness(lm, speed, omega, options.loss_factor) * q;
        for (Index i = 0; i < n; ++i) r(lm.dofs[static_cast<std::size_t>(i)]) -= fe(i);
      }
      for (ReactionResponse& rr : result.reactions) {
        NodeAmplitudes out{};
        for (int d = 0; d < dofs_per_node; ++d)
          if (rr.fixed[static_cast<std::size_t>(d)]) out[static_cast<std::size_t>(d)] = r(dofs_per_node * rr.node + d);
        rr.force.push_back(out);
        rr.peak_lateral.push_back(peak_lateral(out));
      }
    }
    // Each element's end forces include its own inertia and gyroscopic moments, so
    // the section forces are in equilibrium with the element's motion.
    std::size_t b = 0;
    ComplexVector end_forces;
    for (StationResponse& st : result.stations) {
      if (beams[b].element != st.station.element || end_forces.size() == 0) {
        while (beams[b].element != st.station.element) ++b;
        end_forces = dynamic_stiffness(beams[b].matrices, speed, omega, options.loss_factor) *
                     element_values(*beams[b].beam, q_full);
      }
      const SectionForces f = section_forces(end_forces, st.station.end);
      st.forces.push_back(f);
      st.stress.push_back(section_stress(beams[b].beam->section(), f));
    }
  }
  return result;
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
  for (std::size_t i = 0; i < r.reactions.size(); ++i)
    for (std::size_t k = 0; k < r.reactions[i].peak_lateral.size(); ++k)
      consider(s.reaction_force, r.reactions[i].peak_lateral[k], static_cast<Index>(k), static_cast<Index>(i));
  for (std::size_t i = 0; i < r.stations.size(); ++i)
    for (std::size_t k = 0; k < r.stations[i].stress.size(); ++k)
      consider(s.stress, r.stations[i].stress[k].von_mises, static_cast<Index>(k), static_cast<Index>(i));
  return s;
}

}  // namespace feran

#include <feran/analyses/static/static_analysis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <feran/assembly/assembler.hpp>
#include <feran/assembly/checks.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/core/error.hpp>

namespace feran {

namespace {

// K·q = f for a linear model. Free motions (allowed by free_motions) make K singular.
// The load must leave them alone; then the solution orthogonal to them (in M) is
// unique, found with the shifted matrix K + μM and one step of iterative refinement.
Vector solve_linear(const Model& model, const Assembler& assembler, const SystemMatrices& sys, const Vector& f) {
  const Matrix N = stiffness_null_space(sys.K, sys.M);
  Vector q;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  if (N.cols() == 0) {
    lu.compute(sys.K);
    if (lu.info() != Eigen::Success) throw Error("static analysis: the stiffness matrix is singular");
    return lu.solve(f);
  }
  require_unloaded_free_motions(model, assembler, N, f);
  Real lambda_max = 0;
  for (Index i = 0; i < sys.M.rows(); ++i) lambda_max = std::max(lambda_max, sys.K.coeff(i, i) / sys.M.coeff(i, i));
  lu.compute(SparseMatrix(sys.K + 1e-8 * lambda_max * sys.M));
  if (lu.info() != Eigen::Success) throw Error("static analysis: the stiffness matrix is singular");
  auto project = [&](Vector& x) { x -= N * (N.transpose() * (sys.M * x)); };
  q = lu.solve(f);
  project(q);
  for (int it = 0; it < 3; ++it) {
    Vector dq = lu.solve(Vector(f - sys.K * q));
    project(dq);
    q += dq;
  }
  return q;
}

// The steps of run_static, each filling its part of the result.

// What each connecting element transmits, K·Δq (its damping carries nothing at rest).
void transmitted_by_elements(const Model& model, const StaticOptions& options, StaticResult& result) {
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const std::optional<Transmission> link = model.elements[e].transmission(options.speed, 0.0);
    if (!link) continue;
    Eigen::Matrix<Real, dofs_per_node, 1> dq = result.q.segment<dofs_per_node>(dofs_per_node * link->node_a);
    if (link->node_b) dq -= result.q.segment<dofs_per_node>(dofs_per_node * *link->node_b);
    const Eigen::Matrix<Real, dofs_per_node, 1> force = link->K * dq;
    NodeValues out;
    for (int d = 0; d < dofs_per_node; ++d) out[static_cast<std::size_t>(d)] = force(d);
    result.springs.emplace_back(static_cast<Index>(e), out);
  }
}

// What each support transmits to its housing or the ground: the negative of its force
// on the journal, in the journal's DOF directions, with its operating state. Returns
// the supports' forces on the model's DOFs.
Vector transmitted_by_supports(const Model& model, const StaticOptions& options, StaticResult& result) {
  Vector on_dofs = Vector::Zero(model.n_dofs());
  for (std::size_t i = 0; i < model.forces.size(); ++i) {
    const Force& force = model.forces[i];
    if (!force.supports()) continue;
    const std::vector<Index> dofs = force.dofs();
    const auto n = static_cast<Index>(dofs.size());
    Vector x(n);
    for (Index k = 0; k < n; ++k) x(k) = result.q(dofs[static_cast<std::size_t>(k)]);
    const Vector f = force.force({.speed = options.speed}, x, Vector::Zero(n)).f;
    NodeValues out{};
    const Index journal = force.nodes().front();
    for (Index k = 0; k < n; ++k) {
      on_dofs(dofs[static_cast<std::size_t>(k)]) += f(k);
      if (dofs[static_cast<std::size_t>(k)] / dofs_per_node == journal)
        out[static_cast<std::size_t>(dofs[static_cast<std::size_t>(k)] % dofs_per_node)] = -f(k);
    }
    result.supports.emplace_back(static_cast<Index>(i), out);
    result.support_data.push_back(force.operating_data({.speed = options.speed}, x, Vector::Zero(n)));
  }
  return on_dofs;
}

// Force on the supports at the fixed DOFs: the load applied there minus the element
// forces K_e·q_e, plus the supports' forces there (a fixed bearing housing).
void reactions_at_fixed_dofs(const Model& model, const StaticOptions& options, const Vector& f_full,
                             const Vector& supports, StaticResult& result) {
  std::vector<std::array<bool, dofs_per_node>> fixed(static_cast<std::size_t>(model.n_nodes()));
  bool any_fixed = false;
  for (const FixedDofs& fd : model.fixed)
    for (int d = 0; d < dofs_per_node; ++d)
      if (fd.dofs[static_cast<std::size_t>(d)])
        fixed[static_cast<std::size_t>(fd.node)][static_cast<std::size_t>(d)] = any_fixed = true;
  if (!any_fixed) return;
  Vector r = f_full + supports;
  for (const Element& e : model.elements) {
    const LocalMatrices lm = e.local_matrices({options.speed});
    const auto n = static_cast<Index>(lm.dofs.size());
    const bool touches = std::any_of(lm.dofs.begin(), lm.dofs.end(), [&](Index dof) {
      return fixed[static_cast<std::size_t>(dof / dofs_per_node)][static_cast<std::size_t>(dof % dofs_per_node)];
    });
    if (!touches || lm.K.size() == 0) continue;
    Vector qe(n);
    for (Index i = 0; i < n; ++i) qe(i) = result.q(lm.dofs[static_cast<std::size_t>(i)]);
    const Vector fe = lm.K * qe;
    for (Index i = 0; i < n; ++i) r(lm.dofs[static_cast<std::size_t>(i)]) -= fe(i);
  }
  for (Index node = 0; node < model.n_nodes(); ++node) {
    const auto& mask = fixed[static_cast<std::size_t>(node)];
    if (std::none_of(mask.begin(), mask.end(), [](bool b) { return b; })) continue;
    NodeValues out{};
    for (int d = 0; d < dofs_per_node; ++d)
      if (mask[static_cast<std::size_t>(d)]) out[static_cast<std::size_t>(d)] = r(dofs_per_node * node + d);
    result.reactions.emplace_back(node, out);
  }
}

// Section forces from the element end forces K_e·q_e minus the element's share of the
// gravity load M_e·g (consistent, so the results are in equilibrium), and stresses.
void shaft_section_results(const Model& model, const StaticOptions& options, StaticResult& result) {
  const ComplexVector qc = result.q.cast<Complex>();
  result.stations = shaft_stations(model);
  ComplexVector end_forces;
  Index last = -1;
  for (const ShaftStation& st : result.stations) {
    const Element& el = model.elements[static_cast<std::size_t>(st.element)];
    const ShaftSegment segment = *el.shaft_segment();
    if (st.element != last) {
      const LocalMatrices lm = el.local_matrices({});
      Vector g = Vector::Zero(Index{2} * dofs_per_node);
      for (int k = 0; k < 2; ++k)
        for (int d = 0; d < 3; ++d) g(dofs_per_node * k + d) = options.gravity(d);
      end_forces = (lm.K * element_values(segment, qc).real() - lm.M * g).cast<Complex>();
      last = st.element;
    }
    const SectionForces sf = section_forces(end_forces, st.end);
    result.section_forces.push_back(sf);
    result.stresses.push_back(section_stress(segment.section_at_end(st.end), sf));
  }
}

// The applied load's resultant force and its moment about the origin.
void applied_resultant(const Model& model, const Vector& f_full, StaticResult& result) {
  for (Index node = 0; node < model.n_nodes(); ++node) {
    const Real x = model.nodes[static_cast<std::size_t>(node)].x;
    const Real fx = f_full(global_dof(node, Dof::u)), fy = f_full(global_dof(node, Dof::v)),
               fz = f_full(global_dof(node, Dof::w));
    result.total_load[0] += fx;
    result.total_load[1] += fy;
    result.total_load[2] += fz;
    result.total_load[3] += f_full(global_dof(node, Dof::rx));
    // Moment of a force at (x, 0, 0) about the origin: (0, −x·F_z, x·F_y).
    result.total_load[4] += f_full(global_dof(node, Dof::ry)) - x * fz;
    result.total_load[5] += f_full(global_dof(node, Dof::rz)) + x * fy;
  }
}

// The motion about this equilibrium: the supports linearised about the equilibrium
// under the same gravity and loads.
StabilityPoint stability_at_equilibrium(const Model& model, const StaticOptions& options) {
  if (!options.stability) return StabilityPoint::unknown(options.speed, "not asked for");
  if (!has_supports(model)) return stability_of_linear(model, options.speed);
  try {
    return stability_of_linear(
        linearised(model, EquilibriumOptions{.gravity = options.gravity, .loads = options.loads}), options.speed);
  } catch (const Error& e) {
    return StabilityPoint::unknown(options.speed, e.what());
  }
}

}  // namespace

StaticResult run_static(const Model& model, const StaticOptions& options) {
  StaticResult result;
  result.info.method = SolverMethod::sparse_lu;
  const Assembler assembler(model);
  const SparseMatrix& T = assembler.dof_map().transformation();
  const Vector f_full = static_load_vector(model, options.gravity, options.loads);
  if (has_supports(model)) {
    // Nonlinear supports (fluid-film bearings): the equilibrium by Newton's method.
    Equilibrium e =
        solve_equilibrium(model, assembler, options.speed, {.gravity = options.gravity, .loads = options.loads});
    result.q = std::move(e.q);
    if (!e.info.converged()) {
      result.info = e.info;  // the last iterate is kept
      return result;
    }
  } else {
    result.q = T * solve_linear(model, assembler, assembler.at(options.speed, 0.0), T.transpose() * f_full);
  }
  if (!result.q.allFinite()) {
    // Overflow (a model built in code, past the builder's physical ranges): nothing
    // derived from the displacements can be trusted.
    result.info.fail(SolverStatus::numerical_failure,
                     "static analysis: the displacements are not finite (the stiffness is too badly conditioned "
                     "for the loads)");
    return result;
  }
  transmitted_by_elements(model, options, result);
  const Vector supports = transmitted_by_supports(model, options, result);
  reactions_at_fixed_dofs(model, options, f_full, supports, result);
  shaft_section_results(model, options, result);
  applied_resultant(model, f_full, result);
  result.info.n_converged = 1;
  result.stability = stability_at_equilibrium(model, options);
  return result;
}

}  // namespace feran

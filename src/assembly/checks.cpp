#include <feran/assembly/checks.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <feran/core/components.hpp>
#include <feran/core/error.hpp>
#include <feran/core/tolerances.hpp>

namespace feran {

namespace {

// Which family a local DOF belongs to: 0 axial, 1 torsion, 2 x–y plane, 3 x–z plane.
int family_of(Index full_dof) {
  switch (static_cast<Dof>(full_dof % dofs_per_node)) {
    case Dof::u:
      return 0;
    case Dof::rx:
      return 1;
    case Dof::v:
    case Dof::rz:
      return 2;
    case Dof::w:
    case Dof::ry:
      return 3;
  }
  return 0;
}

std::string node_list(const Model& model, const std::vector<Index>& nodes) {
  if (nodes.size() == static_cast<std::size_t>(model.n_nodes())) return "all nodes";
  std::vector<std::string> labels;
  for (Index n : nodes) labels.push_back(model.node_label(n));
  if (labels.size() > 8) {
    labels.resize(8);
    labels.emplace_back("…");
  }
  return fmt::format("node{} {}", nodes.size() > 1 ? "s" : "", fmt::join(labels, ", "));
}

// Nodes whose DOFs of @p family move in the full-coordinate vector @p q.
std::vector<Index> moving_nodes(const Vector& q, int family) {
  Real peak = 0.0;
  for (Index i = 0; i < q.size(); ++i)
    if (family_of(i) == family) peak = std::max(peak, std::abs(q(i)));
  std::vector<Index> nodes;
  for (Index i = 0; i < q.size(); ++i)
    if (family_of(i) == family && std::abs(q(i)) > 1e-6 * peak) {
      const Index node = i / dofs_per_node;
      if (nodes.empty() || nodes.back() != node) nodes.push_back(node);
    }
  return nodes;
}

// Describes one lateral rigid motion in a bending plane from its nodal values.
std::string describe_plane_motion(const Model& model, const Vector& q, int family) {
  const Dof d = family == 2 ? Dof::v : Dof::w;
  const char* axis = family == 2 ? "y" : "z";
  const char* about = family == 2 ? "z" : "y";
  // Least-squares fit of the transverse displacement: q = a + b·x.
  Real sx = 0, sq = 0, sxx = 0, sxq = 0, n = 0;
  for (Index node = 0; node < model.n_nodes(); ++node) {
    const Real x = model.nodes[static_cast<std::size_t>(node)].x;
    const Real value = q(global_dof(node, d));
    sx += x, sq += value, sxx += x * x, sxq += x * value, n += 1;
  }
  const Real det = n * sxx - sx * sx;
  const Real b = det > 0 ? (n * sxq - sx * sq) / det : 0.0;
  const Real a = (sq - b * sx) / n;
  const Real span = det > 0 ? std::sqrt(det) / n : 1.0;
  if (std::abs(b) * span < 1e-6 * std::abs(a)) return fmt::format("translation along {}", axis);
  return fmt::format("rotation about the {} axis through x = {:.4g} m", about, -a / b);
}

// The number of separate parts of a system: connected groups of DOFs, two DOFs
// joined when K or M couples them (union–find over the non-zeros).
Index connected_parts(const SparseMatrix& K, const SparseMatrix& M) {
  const std::vector<Index> component = connected_components(K.rows(), {&K, &M}, true);
  return component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
}

}  // namespace

Matrix stiffness_null_space(const SparseMatrix& K_in, const SparseMatrix& M) {
  const Index n = K_in.rows();
  if (n == 0) return Matrix(0, 0);
  const SparseMatrix K = 0.5 * (K_in + SparseMatrix(K_in.transpose()));

  Real lambda_max = 0.0;
  for (Index i = 0; i < n; ++i)
    if (M.coeff(i, i) > 0) lambda_max = std::max(lambda_max, K.coeff(i, i) / M.coeff(i, i));
  if (lambda_max <= 0.0) lambda_max = 1.0;
  // Shift μ: rigid motions (λ = 0) are amplified by 1/μ, elastic ones by at most
  // 1/(λ₁ + μ), so a few inverse iterations isolate the null space.
  const Real mu = 1e-8 * lambda_max;
  // A motion is rigid when its Rayleigh quotient is below this: 1e-12·λ_max, i.e.
  // a natural frequency 10⁻⁶ times the highest one, far above round-off (~1e-16·λ_max).
  const Real rigid_tol = tolerance::rigid_body * lambda_max;

  // Sylvester's law of inertia: an LDLᵀ factorisation of K − τ·M has as many negative
  // pivots as (K, M) has eigenvalues below τ (-1: it could not be factorised). Ritz
  // values bound the lowest eigenvalues from above, so no more motions than that can
  // pass the Rayleigh-quotient test below.
  const auto count_below = [&](Real tau) -> Index {
    const Eigen::SimplicialLDLT<SparseMatrix> inertia(SparseMatrix(K - tau * M));
    if (inertia.info() != Eigen::Success) return -1;
    return (inertia.vectorD().array() < 0.0).count();
  };
  // None below τ, for the usual model held by its bearings: one factorisation.
  Index expected = count_below(rigid_tol);
  if (expected == 0) return Matrix(n, 0);
  Real tol = rigid_tol, shift = mu;
  if (expected > 0) {
    // Eigenvalues between the floor and τ are vibrations of a wide spectrum (a fine
    // mesh), not rigid motions: the test moves down to the floor, and the shift with
    // it, so that the iteration separates the two (with μ far above them it did not
    // converge, and grew with the model).
    const Real floor = tolerance::rigid_body_floor * lambda_max;
    const Index below_floor = count_below(floor);
    if (below_floor >= 0 && below_floor < expected) {
      if (below_floor == 0) return Matrix(n, 0);
      expected = below_floor;
      tol = floor;
      shift = 0.1 * floor;
    }
  }
  // A body has at most six rigid motions, so more eigenvalues below the test than six
  // per separate part are vibrations whose frequencies are 10⁻⁷ of the highest and
  // less, within a hundred times the round-off of double precision: rigid-body
  // motion cannot be told from vibration, and the lowest modes of any analysis would
  // lose their accuracy. Said as such, rather than naming vibrations free motions.
  const Index most_rigid = 6 * connected_parts(K, M);
  if (expected > most_rigid)
    throw ModelStructureError(
        fmt::format("the stiffness spans too many orders of magnitude to be resolved: {} motions have natural "
                    "frequencies below 1e-6 times the highest ({:.3g} Hz), more than the {} rigid-body motions "
                    "the model's parts can have; very short shaft elements (a fine mesh: the highest frequency "
                    "grows with the number of elements) or very stiff springs beside soft parts cause this; use "
                    "fewer, longer elements",
                    expected, std::sqrt(lambda_max) / (2 * pi), most_rigid));

  Eigen::SimplicialLDLT<SparseMatrix> shifted(K + shift * M);
  if (shifted.info() != Eigen::Success)
    throw ModelStructureError("the stiffness matrix could not be factorised (is it indefinite?)");

  // Subspace iteration on a few more vectors than the motions counted above.
  const Index p0 = expected > 0 ? std::min<Index>(n, expected + 6) : std::min<Index>(n, 12);
  for (Index p = p0;; p = std::min<Index>(n, 2 * p)) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<Real> dist(-1.0, 1.0);
    Matrix X(n, p);
    for (Index j = 0; j < p; ++j)
      for (Index i = 0; i < n; ++i) X(i, j) = dist(rng);
    for (int it = 0; it < 6; ++it) {
      X = shifted.solve(M * X);
      X = Eigen::HouseholderQR<Matrix>(X).householderQ() * Matrix::Identity(n, p);
    }
    const Matrix kr = X.transpose() * (K * X);
    const Matrix mr = X.transpose() * (M * X);
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> ritz(0.5 * (kr + kr.transpose()), 0.5 * (mr + mr.transpose()));
    Index n_null = 0;
    while (n_null < p && ritz.eigenvalues()(n_null) < tol) ++n_null;
    if (n_null < p || p == n) return X * ritz.eigenvectors().leftCols(n_null);
  }
}

SparseMatrix held_stiffness(const Model& model, const Assembler& assembler, const SparseMatrix& K) {
  std::vector<Eigen::Triplet<Real>> holds;
  Real k = 0.0;
  for (Index i = 0; i < K.rows(); ++i) k = std::max(k, std::abs(K.coeff(i, i)));
  if (k == 0.0) k = 1.0;
  for (const Force& force : model.forces) {
    if (!force.supports()) continue;
    const std::vector<Index> dofs = force.dofs();  // the journal's, then as many of the housing's
    const std::size_t half = dofs.size() == 4 ? 2 : dofs.size();
    for (std::size_t d = 0; d < half; ++d) {
      holds.emplace_back(dofs[d], dofs[d], k);
      if (half == dofs.size()) continue;
      holds.emplace_back(dofs[d + half], dofs[d + half], k);
      holds.emplace_back(dofs[d], dofs[d + half], -k);
      holds.emplace_back(dofs[d + half], dofs[d], -k);
    }
  }
  if (holds.empty()) return K;
  SparseMatrix H(model.n_dofs(), model.n_dofs());
  H.setFromTriplets(holds.begin(), holds.end());
  const SparseMatrix& T = assembler.dof_map().transformation();
  return K + SparseMatrix(T.transpose() * H * T);
}

std::vector<FreeMotionInfo> find_free_motions(const Model& model, const Assembler& assembler) {
  const SystemMatrices sys = assembler.at(0.0);
  const Matrix null_space = stiffness_null_space(held_stiffness(model, assembler, sys.K), sys.M);

  std::vector<FreeMotionInfo> motions;
  if (null_space.cols() == 0) return motions;
  const Matrix full = assembler.dof_map().transformation() * null_space;
  // A family takes part in the null space when its share of the basis is well above
  // the round-off leaking into it from the other families (~1e-8 of the whole).
  const Real basis_size = full.colwise().norm().maxCoeff();
  for (int family = 0; family < 4; ++family) {
    Matrix part = Matrix::Zero(full.rows(), full.cols());
    for (Index i = 0; i < full.rows(); ++i)
      if (family_of(i) == family) part.row(i) = full.row(i);
    Eigen::JacobiSVD<Matrix> svd(part, Eigen::ComputeThinU);
    Index rank = 0;
    while (rank < svd.singularValues().size() && svd.singularValues()(rank) > 1e-4 * basis_size) ++rank;
    for (Index r = 0; r < rank; ++r) {
      const Vector q = svd.matrixU().col(r);
      FreeMotionInfo info;
      info.nodes = moving_nodes(q, family);
      if (family == 0) {
        info.family = FreeMotion::axial;
        info.description = "translation along the x axis (axial)";
      } else if (family == 1) {
        info.family = FreeMotion::torsion;
        info.description = "rotation about the x axis (torsion)";
      } else {
        info.family = FreeMotion::lateral;
        info.description = rank > 1 ? (family == 2 ? "translation along y and rotation about z"
                                                   : "translation along z and rotation about y")
                                    : describe_plane_motion(model, q, family);
      }
      info.description += " of " + node_list(model, info.nodes);
      motions.push_back(std::move(info));
      if (family >= 2 && rank > 1) break;  // one description covers the plane
    }
  }
  return motions;
}

void check_model(const Model& model, const Assembler& assembler) {
  const DofMap& dofs = assembler.dof_map();
  if (dofs.n_reduced() == 0) throw ModelStructureError(std::string(no_free_dof_message));
  const SystemMatrices sys = assembler.at(0.0);
  for (Index i = 0; i < sys.M.rows(); ++i) {
    if (sys.M.coeff(i, i) > 0.0) continue;
    const Index full = dofs.full_dof(i);
    const Index node = full / dofs_per_node;
    throw ModelStructureError(fmt::format("the mass matrix is singular: node {} has no mass in DOF {}; attach a rigid "
                                          "body or a shaft to it, or fix or link that DOF",
                                          model.node_label(node), dof_name(static_cast<Dof>(full % dofs_per_node))),
                              node);
  }
  Eigen::SimplicialLLT<SparseMatrix> llt(sys.M);
  if (llt.info() != Eigen::Success)
    throw ModelStructureError(
        "the mass matrix is not positive definite (check the rigid-body "
        "inertias and densities)");

  std::vector<std::string> problems;
  std::vector<std::string> names;
  Index first_node = -1;
  for (const FreeMotionInfo& m : find_free_motions(model, assembler)) {
    const auto& allowed = model.free_motions;
    if (std::find(allowed.begin(), allowed.end(), m.family) != allowed.end()) continue;
    problems.push_back(m.description);
    const char* name = m.family == FreeMotion::axial     ? "axial"
                       : m.family == FreeMotion::torsion ? "torsion"
                                                         : "lateral";
    if (std::find(names.begin(), names.end(), name) == names.end()) names.emplace_back(name);
    if (first_node < 0 && !m.nodes.empty()) first_node = m.nodes.front();
  }
  if (problems.empty()) return;
  std::vector<std::string> quoted;
  for (const auto& n : names) quoted.push_back(fmt::format("\"{}\"", n));
  throw ModelStructureError(fmt::format("the stiffness matrix is singular after constraints: free rigid-body motion: "
                                        "{}. Hold it with springs or fixed DOFs, or allow it with [options] "
                                        "free_motions = [{}]",
                                        fmt::join(problems, "; "), fmt::join(quoted, ", ")),
                            first_node);
}

}  // namespace feran

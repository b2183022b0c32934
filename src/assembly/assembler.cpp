#include <feran/assembly/assembler.hpp>

#include <algorithm>
#include <utility>

#include <feran/core/error.hpp>

namespace feran {

namespace {
using Triplets = std::vector<Eigen::Triplet<Real>>;

struct FullTriplets {
  Triplets M, C, K, G, Ci, Ki, Kh;
};

void scatter(const std::vector<Index>& dofs, const Matrix& local, Triplets& out) {
  if (local.size() == 0) return;
  const auto n = static_cast<Index>(dofs.size());
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i)
      if (local(i, j) != 0.0)
        out.emplace_back(dofs[static_cast<std::size_t>(i)], dofs[static_cast<std::size_t>(j)], local(i, j));
}

void add_element(const Element& e, const OperatingPoint& op, FullTriplets& t) {
  const LocalMatrices lm = e.local_matrices(op);
  scatter(lm.dofs, lm.M, t.M);
  scatter(lm.dofs, lm.C, t.C);
  scatter(lm.dofs, lm.K, t.K);
  scatter(lm.dofs, lm.G, t.G);
  scatter(lm.dofs, lm.Ci, t.Ci);
  scatter(lm.dofs, lm.Ki, t.Ki);
  if (lm.loss_factor != 0.0) scatter(lm.dofs, lm.loss_factor * lm.K, t.Kh);
}

using Rows = std::vector<std::vector<std::pair<Index, Real>>>;

Rows transformation_rows(const SparseMatrix& T_in) {
  const Eigen::SparseMatrix<Real, Eigen::RowMajor> T = T_in;
  Rows rows(static_cast<std::size_t>(T.rows()));
  for (Index r = 0; r < T.rows(); ++r)
    for (Eigen::SparseMatrix<Real, Eigen::RowMajor>::InnerIterator it(T, r); it; ++it)
      rows[static_cast<std::size_t>(r)].emplace_back(it.col(), it.value());
  return rows;
}

// Tᵀ·A·T from A's triplets (full DOFs), entry by entry: (i, j, v) adds T(i,a)·T(j,b)·v
// to (a, b) for the entries of rows i and j of T. A fixed DOF's row is empty (its
// entries drop out); a plain DOF's row is one weight 1 (the entry moves, its value
// unchanged); a rigid link's slave row spreads it over the master's DOFs. Explicit
// zeros (summed or given) are removed.
SparseMatrix reduce(const Triplets& triplets, const Rows& rows, Index n) {
  Triplets reduced;
  reduced.reserve(triplets.size());
  for (const Eigen::Triplet<Real>& t : triplets)
    for (const auto& [a, ta] : rows[static_cast<std::size_t>(t.row())])
      for (const auto& [b, tb] : rows[static_cast<std::size_t>(t.col())])
        reduced.emplace_back(a, b, ta * tb * t.value());
  SparseMatrix out(n, n);
  out.setFromTriplets(reduced.begin(), reduced.end());
  out.prune(0.0);
  return out;
}

SystemMatrices reduce(const FullTriplets& t, const Rows& rows, Index n) {
  return {reduce(t.M, rows, n),  reduce(t.C, rows, n),  reduce(t.K, rows, n), reduce(t.G, rows, n),
          reduce(t.Ci, rows, n), reduce(t.Ki, rows, n), reduce(t.Kh, rows, n)};
}
}  // namespace

SparseMatrix SystemMatrices::damping(Real speed) const { return C + Ci + speed * G; }

SparseMatrix SystemMatrices::stiffness(Real speed) const { return K + speed * Ki; }

Assembler::Assembler(const Model& model) : dofs_(model), rows_(transformation_rows(dofs_.transformation())) {
  FullTriplets t;
  for (const Element& e : model.elements) {
    frequency_dependent_ = frequency_dependent_ || e.frequency_dependent();
    if (e.speed_dependent() || e.frequency_dependent())
      speed_dependent_elements_.push_back(e);
    else
      add_element(e, OperatingPoint{}, t);
  }
  constant_ = reduce(t, rows_, dofs_.n_reduced());
  build_variable_scatter();
}

void Assembler::build_variable_scatter() {
  // Each local DOF i maps to the reduced DOFs of row i of T; a local entry (i, j)
  // touches every (a, b) with T(i, a)·T(j, b) ≠ 0.
  const Index n = dofs_.n_reduced();
  auto row = [&](Index dof) -> const std::vector<std::pair<Index, Real>>& {
    return rows_[static_cast<std::size_t>(dof)];
  };

  std::vector<std::vector<Index>> element_dofs;
  Triplets pattern;
  for (const Element& e : speed_dependent_elements_) {
    element_dofs.push_back(e.dofs());
    for (const Index di : element_dofs.back())
      for (const Index dj : element_dofs.back())
        for (const auto& [a, ta] : row(di))
          for (const auto& [b, tb] : row(dj)) pattern.emplace_back(a, b, 1.0);
  }
  variable_pattern_.resize(n, n);
  variable_pattern_.setFromTriplets(pattern.begin(), pattern.end());
  variable_pattern_.makeCompressed();
  auto value_index = [&](Index a, Index b) {
    using StorageIndex = SparseMatrix::StorageIndex;
    const StorageIndex* inner = variable_pattern_.innerIndexPtr();
    const StorageIndex* begin = inner + variable_pattern_.outerIndexPtr()[b];
    const StorageIndex* end = inner + variable_pattern_.outerIndexPtr()[b + 1];
    return static_cast<Index>(std::lower_bound(begin, end, static_cast<StorageIndex>(a)) - inner);
  };
  for (const std::vector<Index>& dofs : element_dofs) {
    std::vector<Scatter> scatter_list;
    const auto m = static_cast<Index>(dofs.size());
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < m; ++i)
        for (const auto& [a, ta] : row(dofs[static_cast<std::size_t>(i)]))
          for (const auto& [b, tb] : row(dofs[static_cast<std::size_t>(j)]))
            scatter_list.push_back({i + j * m, value_index(a, b), ta * tb});
    variable_scatter_.push_back(std::move(scatter_list));
    variable_dof_counts_.push_back(dofs.size());
  }
}

void Assembler::variable_values(Real speed, SystemMatrices& out) const {
  SparseMatrix* const parts[] = {&out.M, &out.C, &out.K, &out.G, &out.Ci, &out.Ki, &out.Kh};
  for (SparseMatrix* p : parts) {
    if (p->rows() != variable_pattern_.rows() || p->nonZeros() != variable_pattern_.nonZeros()) {
      *p = variable_pattern_;
    }
    std::fill_n(p->valuePtr(), p->nonZeros(), 0.0);
  }
  for (std::size_t e = 0; e < speed_dependent_elements_.size(); ++e) {
    const LocalMatrices lm = speed_dependent_elements_[e].local_matrices(OperatingPoint{speed});
    if (lm.dofs.size() != variable_dof_counts_[e])
      throw Error("assembly: a speed-dependent element changed its DOFs with the speed");
    auto add = [&](const Matrix& local, Real factor, SparseMatrix& target) {
      if (local.size() == 0 || factor == 0.0) return;
      if (local.rows() != static_cast<Index>(lm.dofs.size()) || local.cols() != local.rows())
        throw Error("assembly: an element's matrix does not match its DOF list");
      Real* values = target.valuePtr();
      const Real* l = local.data();
      for (const Scatter& s : variable_scatter_[e]) values[s.value] += factor * s.weight * l[s.local];
    };
    add(lm.M, 1.0, out.M);
    add(lm.C, 1.0, out.C);
    add(lm.K, 1.0, out.K);
    add(lm.G, 1.0, out.G);
    add(lm.Ci, 1.0, out.Ci);
    add(lm.Ki, 1.0, out.Ki);
    add(lm.K, lm.loss_factor, out.Kh);
  }
}

SystemMatrices Assembler::variable_at(Real speed, std::optional<Real> frequency) const {
  FullTriplets t;
  for (const Element& e : speed_dependent_elements_) add_element(e, OperatingPoint{speed, frequency}, t);
  return reduce(t, rows_, dofs_.n_reduced());
}

SystemMatrices Assembler::at(Real speed, std::optional<Real> frequency) const {
  if (speed_dependent_elements_.empty()) return constant_;
  const SystemMatrices var = variable_at(speed, frequency);
  SystemMatrices out = constant_;
  out.M += var.M;
  out.C += var.C;
  out.K += var.K;
  out.G += var.G;
  out.Ci += var.Ci;
  out.Ki += var.Ki;
  out.Kh += var.Kh;
  return out;
}

}  // namespace feran

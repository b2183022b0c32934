#include <feran/assembly/assembler.hpp>

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

SparseMatrix reduce(const Triplets& triplets, const SparseMatrix& T) {
  SparseMatrix full(T.rows(), T.rows());
  full.setFromTriplets(triplets.begin(), triplets.end());
  SparseMatrix reduced = SparseMatrix(T.transpose()) * full * T;
  reduced.prune(0.0);
  return reduced;
}

SystemMatrices reduce(const FullTriplets& t, const SparseMatrix& T) {
  return {reduce(t.M, T), reduce(t.C, T),  reduce(t.K, T), reduce(t.G, T),
          reduce(t.Ci, T), reduce(t.Ki, T), reduce(t.Kh, T)};
}
}  // namespace

SparseMatrix SystemMatrices::damping(Real speed) const { return C + Ci + speed * G; }

SparseMatrix SystemMatrices::stiffness(Real speed) const { return K + speed * Ki; }

Assembler::Assembler(const Model& model) : dofs_(model) {
  FullTriplets t;
  for (const Element& e : model.elements) {
    if (e.speed_dependent())
      speed_dependent_elements_.push_back(e);
    else
      add_element(e, OperatingPoint{}, t);
  }
  constant_ = reduce(t, dofs_.transformation());
}

SystemMatrices Assembler::variable_at(Real speed) const {
  FullTriplets t;
  for (const Element& e : speed_dependent_elements_) add_element(e, OperatingPoint{speed}, t);
  return reduce(t, dofs_.transformation());
}

SystemMatrices Assembler::at(Real speed) const {
  if (speed_dependent_elements_.empty()) return constant_;
  const SystemMatrices var = variable_at(speed);
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

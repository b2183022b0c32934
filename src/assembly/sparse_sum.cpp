#include <feran/assembly/sparse_sum.hpp>

#include <algorithm>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// Calls f(entry number, row, column, value) for each stored entry of A, column by column.
template <class F>
void for_each_entry(const SparseMatrix& A, F f) {
  Index e = 0;
  for (Index k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) f(e++, it.row(), it.col(), it.value());
}

}  // namespace

SparseSum::SparseSum(const std::vector<const SparseMatrix*>& terms) {
  if (terms.empty()) return;
  const Index rows = terms.front()->rows(), cols = terms.front()->cols();
  std::vector<Eigen::Triplet<Real>> trip;
  for (const SparseMatrix* A : terms) {
    if (A->rows() != rows || A->cols() != cols) throw Error("SparseSum: terms of different sizes");
    for_each_entry(*A, [&](Index, Index i, Index j, Real) { trip.emplace_back(i, j, 0.0); });
  }
  pattern_.resize(rows, cols);
  pattern_.setFromTriplets(trip.begin(), trip.end());  // duplicates summed: the union
  pattern_.makeCompressed();
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (const SparseMatrix* A : terms) {
    std::vector<Index> where(static_cast<std::size_t>(A->nonZeros()));
    for_each_entry(*A, [&](Index e, Index i, Index j, Real) {
      const int* at = std::lower_bound(inner + outer[j], inner + outer[j + 1], static_cast<int>(i));
      where[static_cast<std::size_t>(e)] = at - inner;
    });
    where_.push_back(std::move(where));
  }
}

Index SparseSum::position(Index row, Index col) const {
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  if (col < 0 || col >= pattern_.cols()) throw Error("SparseSum::position: no such column");
  const int* at = std::lower_bound(inner + outer[col], inner + outer[col + 1], static_cast<int>(row));
  if (at == inner + outer[col + 1] || *at != row) throw Error("SparseSum::position: no such entry");
  return at - inner;
}

void SparseSum::evaluate(const std::vector<Real>& c, const std::vector<const SparseMatrix*>& terms,
                         SparseMatrix& out) const {
  if (c.size() != where_.size() || terms.size() != where_.size())
    throw Error("SparseSum::evaluate: not the terms it was built for");
  const bool same_pattern =
      out.rows() == pattern_.rows() && out.cols() == pattern_.cols() && out.isCompressed() &&
      out.nonZeros() == pattern_.nonZeros() &&
      std::equal(out.innerIndexPtr(), out.innerIndexPtr() + out.nonZeros(), pattern_.innerIndexPtr()) &&
      std::equal(out.outerIndexPtr(), out.outerIndexPtr() + out.outerSize() + 1, pattern_.outerIndexPtr());
  if (!same_pattern) out = pattern_;
  Real* v = out.valuePtr();
  std::fill(v, v + out.nonZeros(), 0.0);
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const std::vector<Index>& where = where_[k];
    if (terms[k]->nonZeros() != static_cast<Index>(where.size()))
      throw Error("SparseSum::evaluate: a term's pattern changed");
    const Real ck = c[k];
    for_each_entry(*terms[k],
                   [&](Index e, Index, Index, Real value) { v[where[static_cast<std::size_t>(e)]] += ck * value; });
  }
}

}  // namespace feran

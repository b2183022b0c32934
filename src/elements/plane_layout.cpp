#include <feran/elements/plane_layout.hpp>

namespace feran::detail {

namespace {
// Local index in the 6-DOF layout of standard-plane DOF i, for each plane.
Index xy_index(Index i) { return dofs_per_node * (i / 2) + (i % 2 == 0 ? 1 : 5); }
Index xz_index(Index i) { return dofs_per_node * (i / 2) + (i % 2 == 0 ? 2 : 4); }
Real xz_sign(Index i) { return i % 2 == 0 ? 1.0 : -1.0; }
}  // namespace

void add_to_both_planes(const Matrix& a, Matrix& out) {
  for (Index i = 0; i < a.rows(); ++i)
    for (Index j = 0; j < a.cols(); ++j) {
      out(xy_index(i), xy_index(j)) += a(i, j);
      out(xz_index(i), xz_index(j)) += xz_sign(i) * xz_sign(j) * a(i, j);
    }
}

void add_plane_coupling(const Matrix& b, Matrix& out) {
  for (Index i = 0; i < b.rows(); ++i)
    for (Index j = 0; j < b.cols(); ++j) {
      out(xy_index(i), xz_index(j)) += b(i, j) * xz_sign(j);
      out(xz_index(j), xy_index(i)) -= xz_sign(j) * b(i, j);
    }
}

}  // namespace feran::detail

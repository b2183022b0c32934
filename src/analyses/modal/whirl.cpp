#include <feran/analyses/modal/whirl.hpp>

#include <algorithm>
#include <cmath>

namespace feran {

namespace {

// The pair (V, W) of node @p node: translations, or the tilt vector (rz, −ry).
// (A reference to a column of a matrix binds without a copy.)
std::pair<Complex, Complex> orbit_pair(const Eigen::Ref<const ComplexVector>& s, Index node, bool tilt) {
  if (tilt) return {s(global_dof(node, Dof::rz)), -s(global_dof(node, Dof::ry))};
  return {s(global_dof(node, Dof::v)), s(global_dof(node, Dof::w))};
}

bool translations_vanish(const Eigen::Ref<const ComplexVector>& s) {
  Real trans = 0, tilt = 0;
  for (Index node = 0; node < s.size() / dofs_per_node; ++node) {
    trans = std::max({trans, magnitude(s(global_dof(node, Dof::v))), magnitude(s(global_dof(node, Dof::w)))});
    tilt = std::max({tilt, magnitude(s(global_dof(node, Dof::ry))), magnitude(s(global_dof(node, Dof::rz)))});
  }
  return trans <= 1e-9 * tilt;
}

}  // namespace

WhirlResult classify_whirl(const ComplexVector& shape) {
  const Index n_nodes = shape.size() / dofs_per_node;
  const bool tilt = translations_vanish(shape);
  std::vector<Real> rf(static_cast<std::size_t>(n_nodes)), rb(static_cast<std::size_t>(n_nodes));
  Real peak = 0.0;
  for (Index node = 0; node < n_nodes; ++node) {
    const auto [V, W] = orbit_pair(shape, node, tilt);
    rf[static_cast<std::size_t>(node)] = magnitude(V + Complex(0, 1) * W) / 2.0;
    rb[static_cast<std::size_t>(node)] = magnitude(V - Complex(0, 1) * W) / 2.0;
    peak = std::max(peak, rf[static_cast<std::size_t>(node)] + rb[static_cast<std::size_t>(node)]);
  }
  WhirlResult out;
  if (peak == 0.0) return out;  // no lateral motion

  bool any_forward = false, any_backward = false;
  Real num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < rf.size(); ++i) {
    num += rf[i] * rf[i] - rb[i] * rb[i];
    den += rf[i] * rf[i] + rb[i] * rb[i];
    const Real size = rf[i] + rb[i];
    if (size < 0.05 * peak) continue;
    const Real d = (rf[i] - rb[i]) / size;
    any_forward = any_forward || d > 0.05;
    any_backward = any_backward || d < -0.05;
  }
  out.directivity = num / den;
  out.whirl = any_forward && any_backward ? Whirl::mixed
              : any_forward               ? Whirl::forward
              : any_backward              ? Whirl::backward
                                          : Whirl::planar;
  return out;
}

namespace {
// Σ over nodes of term(V_a, W_a, V_b, W_b) for every pair of columns a, b.
template <class Term>
ComplexMatrix node_form(const ComplexMatrix& shapes, Term term) {
  const Index m = shapes.cols();
  const bool tilt = m > 0 && translations_vanish(shapes.col(0));
  ComplexMatrix h = ComplexMatrix::Zero(m, m);
  for (Index node = 0; node < shapes.rows() / dofs_per_node; ++node)
    for (Index a = 0; a < m; ++a)
      for (Index b = 0; b < m; ++b) {
        const auto [Va, Wa] = orbit_pair(shapes.col(a), node, tilt);
        const auto [Vb, Wb] = orbit_pair(shapes.col(b), node, tilt);
        h(a, b) += term(Va, Wa, Vb, Wb);
      }
  return h;
}
}  // namespace

ShapeResult classify_shape(const ComplexVector& shape, const std::vector<std::pair<Index, Real>>& nodes) {
  ShapeResult out;
  const auto n = static_cast<Real>(nodes.size());
  if (nodes.empty()) return out;
  Real mean_x = 0;
  for (const auto& [node, x] : nodes) mean_x += x / n;
  Real sxx = 0;
  for (const auto& [node, x] : nodes) sxx += (x - mean_x) * (x - mean_x);
  Real residual = 0, total = 0, translation = 0, tilt = 0;
  for (const Dof d : {Dof::v, Dof::w}) {
    Complex a = 0, b = 0;
    for (const auto& [node, x] : nodes) {
      const Complex y = shape(global_dof(node, d));
      a += y / n;
      if (sxx > 0) b += y * (x - mean_x) / sxx;
    }
    for (const auto& [node, x] : nodes) {
      const Complex y = shape(global_dof(node, d));
      residual += std::norm(y - a - b * (x - mean_x));
      total += std::norm(y);
    }
    translation += n * std::norm(a);
    tilt += std::norm(b) * sxx;
  }
  if (!(total > 0)) return out;
  out.bending = std::clamp(residual / total, 0.0, 1.0);
  out.kind = out.bending >= 0.1    ? ModeShape::bending
             : translation >= tilt ? ModeShape::cylindrical
                                   : ModeShape::conical;
  return out;
}

ComplexMatrix whirl_form(const ComplexMatrix& shapes) {
  return node_form(shapes, [](Complex Va, Complex Wa, Complex Vb, Complex Wb) {
    return Complex(0, 0.5) * (std::conj(Va) * Wb - std::conj(Wa) * Vb);
  });
}

ComplexMatrix lateral_form(const ComplexMatrix& shapes) {
  return node_form(
      shapes, [](Complex Va, Complex Wa, Complex Vb, Complex Wb) { return std::conj(Va) * Vb + std::conj(Wa) * Wb; });
}

}  // namespace feran

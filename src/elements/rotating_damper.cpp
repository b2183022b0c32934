#include <feran/elements/rotating_damper.hpp>

#include <feran/elements/plane_layout.hpp>

namespace feran {

RotatingDamper::RotatingDamper(Index node_a, std::optional<Index> node_b, RotatingDamperCoefficients c)
    : node_a_(node_a), node_b_(node_b), c_(c) {}

LocalMatrices RotatingDamper::local_matrices(const OperatingPoint& /*op*/) const {
  LocalMatrices out;
  for (int d = 0; d < dofs_per_node; ++d) out.dofs.push_back(dofs_per_node * node_a_ + d);
  if (node_b_)
    for (int d = 0; d < dofs_per_node; ++d) out.dofs.push_back(dofs_per_node * *node_b_ + d);
  const auto n = static_cast<Index>(out.dofs.size());
  const Index n_nodes = n / dofs_per_node;

  // Rotating-frame damping of one bending plane in standard (displacement, slope)
  // DOFs, for the relative motion of the nodes.
  Matrix plane_node(2, 2);
  plane_node << c_.translational, 0, 0, c_.rotational;
  Matrix plane(2 * n_nodes, 2 * n_nodes);
  if (n_nodes == 1)
    plane = plane_node;
  else
    plane << plane_node, -plane_node, -plane_node, plane_node;

  out.Ci = Matrix::Zero(n, n);
  detail::add_to_both_planes(plane, out.Ci);
  out.Ki = Matrix::Zero(n, n);
  detail::add_plane_coupling(plane, out.Ki);
  for (Index a = 0; a < n_nodes; ++a)
    for (Index b = 0; b < n_nodes; ++b) {
      const Real s = a == b ? 1.0 : -1.0;
      out.Ci(dofs_per_node * a + static_cast<Index>(Dof::u), dofs_per_node * b + static_cast<Index>(Dof::u)) +=
          s * c_.axial;
      out.Ci(dofs_per_node * a + static_cast<Index>(Dof::rx), dofs_per_node * b + static_cast<Index>(Dof::rx)) +=
          s * c_.torsional;
    }
  return out;
}

}  // namespace feran

#include <feran/elements/rigid_body.hpp>

namespace feran {

RigidBody::RigidBody(Index node, RigidBodyProperties props, bool rotating)
    : node_(node), props_(props), rotating_(rotating) {}

RigidBodyProperties RigidBody::disk(Real density, Real outer_diameter, Real inner_diameter, Real width) {
  const Real ro2 = outer_diameter * outer_diameter / 4.0;
  const Real ri2 = inner_diameter * inner_diameter / 4.0;
  RigidBodyProperties p;
  p.mass = density * pi * (ro2 - ri2) * width;
  p.polar_inertia = 0.5 * p.mass * (ro2 + ri2);
  p.transverse_inertia = 0.25 * p.mass * (ro2 + ri2) + p.mass * width * width / 12.0;
  return p;
}

LocalMatrices RigidBody::local_matrices(const OperatingPoint& /*op*/) const {
  constexpr auto u = static_cast<Index>(Dof::u), v = static_cast<Index>(Dof::v), w = static_cast<Index>(Dof::w),
                 rx = static_cast<Index>(Dof::rx), ry = static_cast<Index>(Dof::ry), rz = static_cast<Index>(Dof::rz);
  const Real m = props_.mass, e = props_.offset;
  LocalMatrices out;
  out.dofs.resize(dofs_per_node);
  for (int d = 0; d < dofs_per_node; ++d) out.dofs[static_cast<std::size_t>(d)] = dofs_per_node * node_ + d;

  // Centre of mass moves by v + e·rz and w − e·ry; J_A is about the node.
  out.M = Matrix::Zero(dofs_per_node, dofs_per_node);
  out.M(u, u) = m;
  out.M(v, v) = m;
  out.M(w, w) = m;
  out.M(rx, rx) = props_.polar_inertia;
  out.M(ry, ry) = props_.transverse_inertia;
  out.M(rz, rz) = props_.transverse_inertia;
  out.M(v, rz) = out.M(rz, v) = m * e;
  out.M(w, ry) = out.M(ry, w) = -m * e;

  if (rotating_) {
    out.G = Matrix::Zero(dofs_per_node, dofs_per_node);
    out.G(rz, ry) = -props_.polar_inertia;
    out.G(ry, rz) = props_.polar_inertia;
  }
  return out;
}

}  // namespace feran

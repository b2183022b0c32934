#include <feran/analyses/common/shaft_sections.hpp>

#include <cmath>

#include <feran/analyses/common/orbit.hpp>

namespace feran {

std::vector<ShaftStation> shaft_stations(const Model& model) {
  std::vector<ShaftStation> out;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const auto* beam = model.elements[e].target<TimoshenkoBeam>();
    if (!beam) continue;
    const auto ei = static_cast<Index>(e);
    out.push_back({ei, 0, beam->node_a(), model.nodes[static_cast<std::size_t>(beam->node_a())].x});
    out.push_back({ei, 1, beam->node_b(), model.nodes[static_cast<std::size_t>(beam->node_b())].x});
  }
  return out;
}

SectionForces section_forces(const TimoshenkoBeam& beam, const Matrix& K_e, const ComplexVector& q_full,
                             int end, Real extra_loss_factor) {
  Eigen::Matrix<Complex, 2 * dofs_per_node, 1> q;
  for (int d = 0; d < dofs_per_node; ++d) {
    q(d) = q_full(dofs_per_node * beam.node_a() + d);
    q(d + dofs_per_node) = q_full(dofs_per_node * beam.node_b() + d);
  }
  const Complex factor(1.0, beam.options().loss_factor + extra_loss_factor);
  const Eigen::Matrix<Complex, 2 * dofs_per_node, 1> f = factor * (K_e.cast<Complex>() * q);
  // End forces act on the element; the section resultant on the +x face is the force
  // at the end node b, and minus the force at node a.
  const int o = end == 0 ? 0 : dofs_per_node;
  const Real s = end == 0 ? -1.0 : 1.0;
  return {s * f(o + static_cast<int>(Dof::u)),  s * f(o + static_cast<int>(Dof::v)),
          s * f(o + static_cast<int>(Dof::w)),  s * f(o + static_cast<int>(Dof::rx)),
          s * f(o + static_cast<int>(Dof::ry)), s * f(o + static_cast<int>(Dof::rz))};
}

SectionStress section_stress(const CircularSection& section, const SectionForces& f) {
  const Real ro = section.outer_diameter / 2, ri = section.inner_diameter / 2;
  const Real A = section.area(), I = section.second_moment(), J = section.polar_moment();
  // Largest transverse shear stress of an annulus, at the neutral axis:
  // (4/3)(r_o² + r_o r_i + r_i²)/(r_o² + r_i²)·V/A (4/3 solid, 2 thin-walled).
  const Real k_shear = 4.0 / 3.0 * (ro * ro + ro * ri + ri * ri) / (ro * ro + ri * ri);
  SectionStress s;
  s.axial = std::abs(f.N) / A;
  s.bending = orbit(f.My, f.Mz).major * ro / I;
  s.torsion = std::abs(f.T) * ro / J;
  s.shear = k_shear * orbit(f.Vy, f.Vz).major / A;
  s.von_mises = std::sqrt((s.axial + s.bending) * (s.axial + s.bending) +
                          3.0 * (s.torsion + s.shear) * (s.torsion + s.shear));
  return s;
}

}  // namespace feran

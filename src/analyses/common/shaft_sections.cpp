#include <feran/analyses/common/shaft_sections.hpp>

#include <cmath>

#include <feran/analyses/common/orbit.hpp>

namespace feran {

std::vector<ShaftStation> shaft_stations(const Model& model) {
  std::vector<ShaftStation> out;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const std::optional<ShaftSegment> segment = model.elements[e].shaft_segment();
    if (!segment) continue;
    const auto ei = static_cast<Index>(e);
    out.push_back({ei, 0, segment->node_a, model.nodes[static_cast<std::size_t>(segment->node_a)].x});
    out.push_back({ei, 1, segment->node_b, model.nodes[static_cast<std::size_t>(segment->node_b)].x});
  }
  return out;
}

ComplexVector element_values(const ShaftSegment& segment, const ComplexVector& q_full) {
  ComplexVector q(2 * dofs_per_node);
  q.head<dofs_per_node>() = q_full.segment<dofs_per_node>(dofs_per_node * segment.node_a);
  q.tail<dofs_per_node>() = q_full.segment<dofs_per_node>(dofs_per_node * segment.node_b);
  return q;
}

SectionForces section_forces(const ComplexVector& f, int end) {
  // The resultant on the +x face is the force node b exerts on the element, and
  // minus the force node a exerts on it.
  const Index o = end == 0 ? 0 : dofs_per_node;
  const Real s = end == 0 ? -1.0 : 1.0;
  return {s * f(o + static_cast<Index>(Dof::u)),  s * f(o + static_cast<Index>(Dof::v)),
          s * f(o + static_cast<Index>(Dof::w)),  s * f(o + static_cast<Index>(Dof::rx)),
          s * f(o + static_cast<Index>(Dof::ry)), s * f(o + static_cast<Index>(Dof::rz))};
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
  s.von_mises =
      std::sqrt((s.axial + s.bending) * (s.axial + s.bending) + 3.0 * (s.torsion + s.shear) * (s.torsion + s.shear));
  return s;
}

}  // namespace feran

#include <feran/analyses/nonlinear/coulomb_friction.hpp>
#include <feran/analyses/nonlinear/nonlinear_force.hpp>

namespace feran {

// One line per kind of nonlinear force the model format knows.
std::vector<NonlinearForce> nonlinear_forces(const Model& model) {
  std::vector<NonlinearForce> out;
  for (const CoulombFriction& f : model.friction) out.emplace_back(CoulombFrictionForce(f), f.label);
  return out;
}

}  // namespace feran

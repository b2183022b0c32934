// [[friction]]: Coulomb friction between rotating parts: the family's field table (its keys, bounds, units and help)
// and its build step (the checks across its keys, and the element or force it adds to the model).
#include <feran/spec/entries/friction.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<FrictionSpec>& fields_of<FrictionSpec>() {
  using S = FrictionSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"friction <i>\"`"),
      node_field<S>("must be a rotating node"),
      to_field<S>("axis", "the rotating frame's axis, or another rotating node", "`\"axis\"`"),
      {.key = "force",
       .kind = K::quantity,
       .member = &S::force,
       .doc = "F_ct0, the friction force",
       .quantity = Q::force,
       .bound = non_negative},
      {.key = "moment",
       .kind = K::quantity,
       .member = &S::moment,
       .doc = "F_cr0, the friction moment",
       .quantity = Q::moment,
       .bound = non_negative},
      {.key = "epsilon_t",
       .kind = K::quantity,
       .member = &S::epsilon_t,
       .doc = "regularisation of the force",
       .quantity = Q::velocity,
       .bound = positive},
      {.key = "epsilon_r",
       .kind = K::quantity,
       .member = &S::epsilon_r,
       .doc = "regularisation of the moment",
       .quantity = Q::angular_velocity,
       .bound = positive},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_friction() {
  constexpr std::string_view reason = "Coulomb friction acts between rotating parts";
  for (std::size_t i = 0; i < spec_.friction.size(); ++i) {
    const FrictionSpec& s = spec_.friction[i];
    const std::string path = element("friction", i);
    CoulombFriction f;
    const std::string label = entry_label(s.name, "friction", i);
    f.node_a = node(s.node, child(path, "node"), "node");
    require_rotating(f.node_a, child(path, "node"), reason);
    f.node_b = other_node(s.to, path, axis_word, f.node_a);
    if (f.node_b) require_rotating(*f.node_b, child(path, "to"), reason);
    check_bounds(s, path);
    if (s.force == 0.0 && s.moment == 0.0) fail(path, "Coulomb friction needs a positive 'force' or 'moment'");
    f.force_amplitude = s.force;
    f.moment_amplitude = s.moment;
    f.epsilon_t = s.epsilon_t;
    f.epsilon_r = s.epsilon_r;
    model_.forces.emplace_back(f, label);
  }
}

}  // namespace builder

}  // namespace feran

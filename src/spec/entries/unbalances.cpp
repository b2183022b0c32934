// [[unbalances]]: mass unbalances at rotor nodes: the family's field table (its keys, bounds, units and help) and its
// build step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/unbalances.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<UnbalanceSpec>& fields_of<UnbalanceSpec>() {
  using S = UnbalanceSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"unbalance <i>\"`"),
      node_field<S>("the node the unbalance acts at"),
      {.key = "mass",
       .kind = K::quantity,
       .member = &S::mass,
       .doc = "unbalance mass m_U",
       .quantity = Q::mass,
       .bound = positive,
       .required = true},
      {.key = "radius",
       .kind = K::quantity,
       .member = &S::radius,
       .doc = "radius r_U",
       .bound = positive,
       .required = true,
       .unit = "mm"},
      {.key = "phase",
       .kind = K::quantity,
       .member = &S::phase,
       .doc = "angle at t = 0, measured from +y towards +z",
       .quantity = Q::angle,
       .unit = "deg"},
      {.key = "lever",
       .kind = K::quantity,
       .member = &S::lever,
       .doc = "axial distance from the node to the unbalance plane",
       .unit = "mm"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_unbalances() {
  for (std::size_t i = 0; i < spec_.unbalances.size(); ++i) {
    const UnbalanceSpec& s = spec_.unbalances[i];
    const std::string path = element("unbalances", i);
    Unbalance u;
    const std::string label = entry_label(s.name, "unbalance", i);
    u.node = node(s.node, child(path, "node"), "node");
    check_bounds(s, path);
    u.mass = s.mass;
    u.radius = s.radius;
    u.phase = s.phase;
    u.lever = s.lever;
    model_.forces.emplace_back(u, label);
  }
}

}  // namespace builder

}  // namespace feran

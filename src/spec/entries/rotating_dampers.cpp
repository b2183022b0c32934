// [[rotating_dampers]]: viscous (internal) damping between rotating parts: the family's field table (its keys, bounds,
// units and help) and its build step (the checks across its keys, and the element or force it adds to the model).
#include <feran/spec/entries/rotating_dampers.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<RotatingDamperSpec>& fields_of<RotatingDamperSpec>() {
  using S = RotatingDamperSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"rotating damper <i>\"`"),
      node_field<S>("must be a rotating node"),
      to_field<S>("axis", "the rotating frame's axis, or another rotating node", "`\"axis\"`"),
      {.key = "ct",
       .kind = K::quantity,
       .member = &S::ct,
       .doc = "lateral (translational) c_it",
       .quantity = Q::damping,
       .bound = non_negative},
      {.key = "cr",
       .kind = K::quantity,
       .member = &S::cr,
       .doc = "tilt c_ir",
       .quantity = Q::rotational_damping,
       .bound = non_negative},
      {.key = "cx",
       .kind = K::quantity,
       .member = &S::cx,
       .doc = "axial",
       .quantity = Q::damping,
       .bound = non_negative},
      {.key = "crx",
       .kind = K::quantity,
       .member = &S::crx,
       .doc = "torsional",
       .quantity = Q::rotational_damping,
       .bound = non_negative},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_rotating_dampers() {
  constexpr std::string_view reason = "a rotating damper acts between rotating parts";
  for (std::size_t i = 0; i < spec_.rotating_dampers.size(); ++i) {
    const RotatingDamperSpec& s = spec_.rotating_dampers[i];
    const std::string path = element("rotating_dampers", i);
    const std::string label = entry_label(s.name, "rotating damper", i);
    const Index a = node(s.node, child(path, "node"), "node");
    require_rotating(a, child(path, "node"), reason);
    const std::optional<Index> b = other_node(s.to, path, axis_word, a);
    if (b) require_rotating(*b, child(path, "to"), reason);
    check_bounds(s, path);
    if (s.ct == 0.0 && s.cr == 0.0 && s.cx == 0.0 && s.crx == 0.0)
      fail(path, "a rotating damper needs at least one positive coefficient: ct, cr, cx or crx");
    model_.elements.emplace_back(RotatingDamper(a, b, {s.ct, s.cr, s.cx, s.crx}), label);
  }
}

}  // namespace builder

}  // namespace feran

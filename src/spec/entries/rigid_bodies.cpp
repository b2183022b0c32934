// [[rigid_bodies]]: disks, impellers and other rigid bodies at a node (mass, inertias, offset): the family's field
// table (its keys, bounds, units and help) and its build step (the checks across its keys, and what it adds to the
// model).
#include <feran/spec/entries/rigid_bodies.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<RigidBodySpec>& fields_of<RigidBodySpec>() {
  using S = RigidBodySpec;
  static const FieldTable<S> table = {
      name_field<S>("label (i counts the entries from 1)", "`\"rigid body <i>\"`"),
      node_field<S>("the node the body sits at"),
      {.key = "mass",
       .kind = K::quantity,
       .member = &S::mass,
       .doc = "mass form: the mass",
       .quantity = Q::mass,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "Ja",
       .kind = K::quantity,
       .member = &S::Ja,
       .doc = "mass form: about a transverse axis **through the node**",
       .quantity = Q::inertia,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "Jp",
       .kind = K::quantity,
       .member = &S::Jp,
       .doc = "mass form: polar, about the x axis",
       .quantity = Q::inertia,
       .bound = non_negative,
       .default_text = "required in the mass form"},
      {.key = "outer_diameter",
       .kind = K::quantity,
       .member = &S::outer_diameter,
       .doc = "disk form: outer diameter",
       .bound = positive,
       .unit = "mm",
       .default_text = "required in the disk form"},
      {.key = "inner_diameter",
       .kind = K::quantity,
       .member = &S::inner_diameter,
       .doc = "disk form: bore diameter, < `outer_diameter`",
       .bound = non_negative,
       .unit = "mm",
       .default_text = "`0` (disk form)"},
      {.key = "width",
       .kind = K::quantity,
       .member = &S::width,
       .doc = "disk form: axial width",
       .bound = positive,
       .unit = "mm",
       .default_text = "required in the disk form"},
      {.key = "material",
       .kind = K::text,
       .member = &S::material,
       .doc = "disk form: name of a material (its `rho` is used)",
       .default_text = "required in the disk form"},
      {.key = "offset",
       .kind = K::quantity,
       .member = &S::offset,
       .doc = "axial position of the centre of mass relative to the node",
       .unit = "mm",
       .default_text = "`0`"},
      {.key = "rotating",
       .kind = K::flag,
       .member = &S::rotating,
       .doc = "whether the body spins (adds the gyroscopic term of Jp)",
       .default_text = "the node's flag"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_rigid_bodies() {
  for (std::size_t i = 0; i < spec_.rigid_bodies.size(); ++i) {
    const RigidBodySpec& s = spec_.rigid_bodies[i];
    const std::string path = element("rigid_bodies", i);
    const auto at = [&](std::string_view key) { return child(path, key); };
    const std::string label = entry_label(s.name, "rigid body", i);
    const Index node_index = node(s.node, at("node"), "node");

    // The first key given of each form, in the order the field table lists them.
    const std::array<std::pair<std::string_view, bool>, 3> mass_keys = {
        {{"mass", s.mass.has_value()}, {"Ja", s.Ja.has_value()}, {"Jp", s.Jp.has_value()}}};
    const std::array<std::pair<std::string_view, bool>, 4> disk_keys = {
        {{"outer_diameter", s.outer_diameter.has_value()},
         {"inner_diameter", s.inner_diameter.has_value()},
         {"width", s.width.has_value()},
         {"material", !s.material.empty()}}};
    std::string_view mass_key, disk_key;
    for (const auto& [k, present] : mass_keys)
      if (present && mass_key.empty()) mass_key = k;
    for (const auto& [k, present] : disk_keys)
      if (present && disk_key.empty()) disk_key = k;
    if (!mass_key.empty() && !disk_key.empty())
      fail(earlier(at(mass_key), at(disk_key)) ? at(disk_key) : at(mass_key),
           fmt::format("a rigid body is given either by mass, Ja and Jp or as a disk by "
                       "outer_diameter, width, inner_diameter and material; this one mixes the "
                       "two forms ('{}' and '{}')",
                       mass_key, disk_key));
    if (mass_key.empty() && disk_key.empty())
      fail(path,
           "a rigid body needs either mass, Ja and Jp, or the disk form outer_diameter, "
           "width and material (inner_diameter optional)");
    check_bounds(s, path);

    RigidBodyProperties props;
    if (!mass_key.empty()) {
      for (const auto& [key, value, kind] :
           {std::tuple{"mass", s.mass, Quantity::mass}, std::tuple{"Ja", s.Ja, Quantity::inertia},
            std::tuple{"Jp", s.Jp, Quantity::inertia}})
        if (!value) fail(path, missing_key(key, "[[rigid_bodies]]", expected_quantity(kind)));
      props.mass = *s.mass;
      props.transverse_inertia = *s.Ja;
      props.polar_inertia = *s.Jp;
    } else {
      if (!s.outer_diameter)
        fail(path, missing_key("outer_diameter", "[[rigid_bodies]]", expected_quantity(Quantity::length)));
      if (!s.width) fail(path, missing_key("width", "[[rigid_bodies]]", expected_quantity(Quantity::length)));
      const Real inner = s.inner_diameter.value_or(0.0);
      if (!(inner < *s.outer_diameter))
        fail(at("inner_diameter"), fmt::format("inner_diameter ({}) must be smaller than outer_diameter ({})",
                                               shown(at("inner_diameter"), inner, Quantity::length, "mm"),
                                               shown(at("outer_diameter"), *s.outer_diameter, Quantity::length, "mm")));
      if (s.material.empty())
        fail(path,
             missing_key("material", "[[rigid_bodies]]", "the name of a material, whose density the disk form uses"));
      const Material& m = material(s.material, at("material"));
      props = RigidBody::disk(m.rho, *s.outer_diameter, inner, *s.width);
    }

    if (s.offset) {
      props.offset = *s.offset;
      const Real parallel_axis = props.mass * *s.offset * *s.offset;
      if (!disk_key.empty()) {
        // The disk's inertia is about its centre; Ja is about the node.
        props.transverse_inertia += parallel_axis;
      } else if (props.transverse_inertia < parallel_axis) {
        fail(at("Ja"), fmt::format("'Ja' ({} kg*m^2) is about a transverse axis through the node, so it "
                                   "must be at least mass·offset² = {} kg*m^2",
                                   props.transverse_inertia, parallel_axis));
      }
    }
    const bool rotating = s.rotating.value_or(model_.nodes[static_cast<std::size_t>(node_index)].rotating);
    model_.elements.emplace_back(RigidBody(node_index, props, rotating), label);
  }
}

}  // namespace builder

}  // namespace feran

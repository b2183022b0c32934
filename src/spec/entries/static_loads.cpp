// [[static_loads]]: constant forces and moments: the family's field table (its keys, bounds, units and help) and its
// build step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/static_loads.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<StaticLoadSpec>& fields_of<StaticLoadSpec>() {
  using S = StaticLoadSpec;
  static const FieldTable<S> table = {
      name_field<S>("label", "`\"static load <i>\"`"),
      node_field<S>("the node the load acts at"),
      {.key = "fx", .kind = K::quantity, .member = &S::fx, .doc = "force along x (any sign)", .quantity = Q::force},
      {.key = "fy", .kind = K::quantity, .member = &S::fy, .doc = "force along y (any sign)", .quantity = Q::force},
      {.key = "fz", .kind = K::quantity, .member = &S::fz, .doc = "force along z (any sign)", .quantity = Q::force},
      {.key = "mx",
       .kind = K::quantity,
       .member = &S::mx,
       .doc = "moment about x (any sign, right-hand rule)",
       .quantity = Q::moment},
      {.key = "my",
       .kind = K::quantity,
       .member = &S::my,
       .doc = "moment about y (any sign, right-hand rule)",
       .quantity = Q::moment},
      {.key = "mz",
       .kind = K::quantity,
       .member = &S::mz,
       .doc = "moment about z (any sign, right-hand rule)",
       .quantity = Q::moment},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_static_loads() {
  for (std::size_t i = 0; i < spec_.static_loads.size(); ++i) {
    const StaticLoadSpec& s = spec_.static_loads[i];
    const std::string path = element("static_loads", i);
    StaticLoad load;
    const std::string label = entry_label(s.name, "static load", i);
    load.node = node(s.node, child(path, "node"), "node");
    check_bounds(s, path);
    load.load = {s.fx, s.fy, s.fz, s.mx, s.my, s.mz};
    if (std::all_of(load.load.begin(), load.load.end(), [](Real v) { return v == 0.0; }))
      fail(path,
           "a static load needs at least one non-zero component: the forces fx, fy, fz "
           "or the moments mx, my, mz");
    model_.forces.emplace_back(load, label);
  }
}

}  // namespace builder

}  // namespace feran

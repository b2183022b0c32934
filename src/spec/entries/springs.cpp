// [[springs]]: spring–dampers between a node and the ground or another node, each coefficient constant or a law of
// speed or frequency: the family's field table (its keys, bounds, units and help) and its build step (the checks across
// its keys, and the element or force it adds to the model).
#include <feran/spec/entries/springs.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<SpringSpec>& fields_of<SpringSpec>() {
  using S = SpringSpec;
  const auto coefficient = [](std::string_view key, std::optional<SpeedCoefficient> S::*member, Quantity q, bool direct,
                              std::string_view doc) {
    return Field<S>{.key = key,
                    .kind = K::coefficient,
                    .member = member,
                    .doc = doc,
                    .quantity = q,
                    .bound = direct ? non_negative : Bound{},
                    .direct = direct,
                    .default_text = "`0`"};
  };
  static const FieldTable<S> table = {
      name_field<S>("label; referred to by `springs` of `[runup]`", "`\"spring <i>\"`"),
      node_field<S>("the first node"),
      to_field<S>("ground", "a node other than `node`, or the ground", "`\"ground\"`"),
      coefficient("kx", &S::kx, Q::stiffness, true, "direct stiffness along x"),
      coefficient("ky", &S::ky, Q::stiffness, true, "direct stiffness along y"),
      coefficient("kz", &S::kz, Q::stiffness, true, "direct stiffness along z"),
      coefficient("krx", &S::krx, Q::rotational_stiffness, true, "direct stiffness about x (torsion)"),
      coefficient("kry", &S::kry, Q::rotational_stiffness, true, "direct stiffness about y"),
      coefficient("krz", &S::krz, Q::rotational_stiffness, true, "direct stiffness about z"),
      coefficient("kyz", &S::kyz, Q::stiffness, false,
                  "cross-coupled stiffness, force along y from w; may be negative"),
      coefficient("kzy", &S::kzy, Q::stiffness, false,
                  "cross-coupled stiffness, force along z from v; may be negative"),
      coefficient("cx", &S::cx, Q::damping, true, "direct damping along x"),
      coefficient("cy", &S::cy, Q::damping, true, "direct damping along y"),
      coefficient("cz", &S::cz, Q::damping, true, "direct damping along z"),
      coefficient("crx", &S::crx, Q::rotational_damping, true, "direct damping about x (torsion)"),
      coefficient("cry", &S::cry, Q::rotational_damping, true, "direct damping about y"),
      coefficient("crz", &S::crz, Q::rotational_damping, true, "direct damping about z"),
      coefficient("cyz", &S::cyz, Q::damping, false, "cross-coupled damping, force along y from w'; may be negative"),
      coefficient("czy", &S::czy, Q::damping, false, "cross-coupled damping, force along z from v'; may be negative"),
      {.key = "loss_factor",
       .kind = K::number,
       .member = &S::loss_factor,
       .doc = "hysteretic loss factor η of the spring's stiffness",
       .bound = non_negative},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_springs() {
  for (std::size_t i = 0; i < spec_.springs.size(); ++i) {
    const SpringSpec& s = spec_.springs[i];
    const std::string path = element("springs", i);
    const std::string label = entry_label(s.name, "spring", i);
    const Index a = node(s.node, child(path, "node"), "node");
    const std::optional<Index> b = other_node(s.to, path, ground_word, a);
    check_bounds(s, path);

    SpringDamperCoefficients c;
    bool any = false;
    const auto take = [&](const std::optional<SpeedCoefficient>& in, SpeedCoefficient& out) {
      if (in) {
        out = *in;
        any = true;
      }
    };
    const std::array<const std::optional<SpeedCoefficient>*, dofs_per_node> k = {&s.kx,  &s.ky,  &s.kz,
                                                                                 &s.krx, &s.kry, &s.krz};
    const std::array<const std::optional<SpeedCoefficient>*, dofs_per_node> d = {&s.cx,  &s.cy,  &s.cz,
                                                                                 &s.crx, &s.cry, &s.crz};
    for (std::size_t j = 0; j < dofs_per_node; ++j) {
      take(*k[j], c.k[j]);
      take(*d[j], c.c[j]);
    }
    take(s.kyz, c.kyz);
    take(s.kzy, c.kzy);
    take(s.cyz, c.cyz);
    take(s.czy, c.czy);
    c.loss_factor = s.loss_factor;
    if (!any)
      fail(path, fmt::format("a spring needs at least one coefficient: kx, ky, kz, krx, kry, krz, "
                             "kyz, kzy, cx, cy, cz, crx, cry, crz, cyz or czy{}",
                             s.loss_factor != 0.0 || given(child(path, "loss_factor"))
                                 ? " ('loss_factor' only scales the stiffness coefficients, it "
                                   "is not one)"
                                 : ""));
    if (s.name.empty()) unnamed_spring_labels_.push_back(label);
    model_.elements.emplace_back(SpringDamper(a, b, c), label);
  }
}

}  // namespace builder

}  // namespace feran

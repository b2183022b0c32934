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
  static const FieldTable<S> table = [] {
    FieldTable<S> t = {
        name_field<S>("label; referred to by `springs` of `[runup]`", "`\"spring <i>\"`"),
        node_field<S>("the first node"),
        to_field<S>("ground", "a node other than `node`, or the ground", "`\"ground\"`"),
    };
    // The coefficients, one field each, from their one name table.
    for (std::size_t i = 0; i < spring::count; ++i) {
      const spring::CoefficientName& c = spring::names[i];
      const Quantity q = c.damping ? (c.rotational ? Q::rotational_damping : Q::damping)
                                   : (c.rotational ? Q::rotational_stiffness : Q::stiffness);
      t.push_back({.key = c.name,
                   .kind = K::coefficient,
                   .member = ArrayElement<S, std::optional<SpeedCoefficient>, spring::count>{&S::coefficients, i},
                   .doc = c.doc,
                   .quantity = q,
                   .bound = c.direct ? non_negative : Bound{},
                   .direct = c.direct,
                   .default_text = "`0`"});
    }
    t.push_back({.key = "loss_factor",
                 .kind = K::number,
                 .member = &S::loss_factor,
                 .doc = "hysteretic loss factor η of the spring's stiffness",
                 .bound = non_negative});
    return t;
  }();
  return table;
}

}  // namespace spec

namespace builder {

namespace {
// "kx, ky, …, cyz or czy".
std::string coefficient_list() {
  std::vector<std::string> names;
  for (const spring::CoefficientName& c : spring::names) names.emplace_back(c.name);
  return detail::join_list(names, "or");
}
}  // namespace

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
    for (std::size_t j = 0; j < spring::count; ++j)
      if (const std::optional<SpeedCoefficient>& value = s.coefficients[j]) {
        coefficient(c, static_cast<spring::Coefficient>(j)) = *value;
        any = true;
      }
    c.loss_factor = s.loss_factor;
    if (!any)
      fail(path, fmt::format("a spring needs at least one coefficient: {}{}", coefficient_list(),
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

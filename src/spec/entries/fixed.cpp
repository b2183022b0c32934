// [[fixed]]: DOFs held at zero: the family's field table (its keys, bounds, units and help) and its build
// step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/fixed.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<FixedSpec>& fields_of<FixedSpec>() {
  using S = FixedSpec;
  static const FieldTable<S> table = {
      node_field<S>("the node whose DOFs are held"),
      {.key = "dofs",
       .kind = K::choice_list,
       .member = &S::dofs,
       .doc = "DOFs and groups of DOFs held at zero (below)",
       .choices = dof_names,
       .default_text = "`[\"all\"]`",
       .if_empty = "leave it out to fix all DOFs"},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_fixed() {
  const std::span<const std::string_view> valid = spec::choices_of<FixedSpec>("dofs");
  const std::vector<std::string> names(valid.begin(), valid.end());
  std::vector<int> slot_of(model_.nodes.size(), -1);
  for (std::size_t i = 0; i < spec_.fixed.size(); ++i) {
    const FixedSpec& s = spec_.fixed[i];
    const std::string path = element("fixed", i);
    const Index n = node(s.node, child(path, "node"), "node");
    std::array<bool, dofs_per_node> dofs{};
    const auto set = [&](std::initializer_list<Dof> list) {
      for (const Dof d : list) dofs[static_cast<std::size_t>(d)] = true;
    };
    if (s.dofs.empty()) dofs.fill(true);
    for (std::size_t j = 0; j < s.dofs.size(); ++j) {
      const std::string& d = s.dofs[j];
      if (d == "u")
        set({Dof::u});
      else if (d == "v")
        set({Dof::v});
      else if (d == "w")
        set({Dof::w});
      else if (d == "rx")
        set({Dof::rx});
      else if (d == "ry")
        set({Dof::ry});
      else if (d == "rz")
        set({Dof::rz});
      else if (d == "all")
        set({Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry, Dof::rz});
      else if (d == "lateral")
        set({Dof::v, Dof::w, Dof::ry, Dof::rz});
      else if (d == "translations")
        set({Dof::u, Dof::v, Dof::w});
      else if (d == "rotations")
        set({Dof::rx, Dof::ry, Dof::rz});
      else {
        std::string message =
            fmt::format("entries of 'dofs' must be one of {}, got \"{}\"", join_list(names, "or", '"'), d);
        if (const auto m = closest_match(d, names, 2)) message += fmt::format("; did you mean \"{}\"?", *m);
        fail(element(child(path, "dofs"), j), message);
      }
    }
    // Several [[fixed]] entries for one node add up.
    int& slot = slot_of[static_cast<std::size_t>(n)];
    if (slot < 0) {
      slot = static_cast<int>(model_.fixed.size());
      model_.fixed.push_back(FixedDofs{n, {}});
    }
    auto& target = model_.fixed[static_cast<std::size_t>(slot)].dofs;
    for (std::size_t d = 0; d < target.size(); ++d) target[d] = target[d] || dofs[d];
  }
}

}  // namespace builder

}  // namespace feran

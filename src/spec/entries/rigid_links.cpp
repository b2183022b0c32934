// [[rigid_links]]: nodes moving as one rigid body with a master node: the family's field table (its keys, bounds, units
// and help) and its build step (the checks across its keys, and what it adds to the model).
#include <feran/spec/entries/rigid_links.hpp>

#include "../builder.hpp"
#include "../field_helpers.hpp"

namespace feran {

namespace spec {

using namespace field_helpers;  // NOLINT(google-build-using-namespace)

template <>
const FieldTable<RigidLinkSpec>& fields_of<RigidLinkSpec>() {
  using S = RigidLinkSpec;
  static const FieldTable<S> table = {
      {.key = "nodes",
       .kind = K::node_list,
       .member = &S::nodes,
       .doc = "at least two distinct nodes; the first is the leader",
       .required = true},
  };
  return table;
}

}  // namespace spec

namespace builder {

void Builder::build_rigid_links() {
  for (std::size_t i = 0; i < spec_.rigid_links.size(); ++i) {
    const RigidLinkSpec& s = spec_.rigid_links[i];
    const std::string path = child(element("rigid_links", i), "nodes");
    if (s.nodes.size() < 2)
      fail(path, fmt::format("'nodes' of a rigid link needs at least two nodes, got {}", s.nodes.size()));
    const std::vector<Index> nodes = distinct_nodes(s.nodes, path, "nodes");
    RigidLink link;
    link.leader = nodes.front();
    link.followers.assign(nodes.begin() + 1, nodes.end());
    model_.links.push_back(link);
  }
}

}  // namespace builder

}  // namespace feran

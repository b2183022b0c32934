#include <feran/assembly/dof_map.hpp>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {
using Row = std::vector<std::pair<Index, Real>>;  // sparse row of T: (reduced column, value)

void add_scaled(Row& target, const Row& source, Real factor) {
  if (factor == 0.0) return;
  for (const auto& [col, value] : source) target.emplace_back(col, factor * value);
}
}  // namespace

DofMap::DofMap(const Model& model) : n_full_(model.n_dofs()) {
  const Index n_nodes = model.n_nodes();
  std::vector<Index> leader(static_cast<std::size_t>(n_nodes), -1);
  for (const RigidLink& link : model.links)
    for (Index f : link.followers) {
      if (f == link.leader)
        throw ModelStructureError(fmt::format("node {} cannot follow itself in a rigid link", model.node_label(f)), f);
      if (leader[static_cast<std::size_t>(f)] >= 0)
        throw ModelStructureError(
            fmt::format("node {} follows two rigid links; join them into one", model.node_label(f)), f);
      leader[static_cast<std::size_t>(f)] = link.leader;
    }
  // Resolve chains (a leader that follows another node) to the ultimate leader,
  // accumulating nothing: positions are used directly from the nodes.
  auto root = [&](Index node) {
    Index r = node, steps = 0;
    while (leader[static_cast<std::size_t>(r)] >= 0) {
      r = leader[static_cast<std::size_t>(r)];
      if (++steps > n_nodes)
        throw ModelStructureError(fmt::format("rigid links form a loop through node {}", model.node_label(node)), node);
    }
    return r;
  };

  std::vector<bool> fixed(static_cast<std::size_t>(n_full_), false);
  for (const FixedDofs& f : model.fixed) {
    for (int d = 0; d < dofs_per_node; ++d) {
      if (!f.dofs[static_cast<std::size_t>(d)]) continue;
      if (leader[static_cast<std::size_t>(f.node)] >= 0)
        throw ModelStructureError(fmt::format("node {} follows a rigid link, so its DOFs cannot be fixed; fix the "
                                              "link's first node instead",
                                              model.node_label(f.node)),
                                  f.node);
      fixed[static_cast<std::size_t>(dofs_per_node * f.node + d)] = true;
    }
  }

  // Independent DOFs: every DOF of a non-follower node that is not fixed.
  full_to_reduced_.assign(static_cast<std::size_t>(n_full_), -1);
  std::vector<Row> rows(static_cast<std::size_t>(n_full_));
  for (Index node = 0; node < n_nodes; ++node) {
    if (leader[static_cast<std::size_t>(node)] >= 0) continue;
    for (int d = 0; d < dofs_per_node; ++d) {
      const Index full = dofs_per_node * node + d;
      if (fixed[static_cast<std::size_t>(full)]) continue;
      full_to_reduced_[static_cast<std::size_t>(full)] = static_cast<Index>(reduced_to_full_.size());
      rows[static_cast<std::size_t>(full)].emplace_back(static_cast<Index>(reduced_to_full_.size()), 1.0);
      reduced_to_full_.push_back(full);
    }
  }
  // Followers: rigid-body kinematics of their ultimate leader.
  for (Index node = 0; node < n_nodes; ++node) {
    if (leader[static_cast<std::size_t>(node)] < 0) continue;
    const Index l = root(node);
    const Real d = model.nodes[static_cast<std::size_t>(node)].x - model.nodes[static_cast<std::size_t>(l)].x;
    auto row_of = [&](Index n, Dof dof) -> const Row& { return rows[static_cast<std::size_t>(global_dof(n, dof))]; };
    auto& r = rows;
    auto at = [&](Dof dof) -> Row& { return r[static_cast<std::size_t>(global_dof(node, dof))]; };
    for (Dof dof : {Dof::u, Dof::v, Dof::w, Dof::rx, Dof::ry, Dof::rz}) at(dof) = row_of(l, dof);
    add_scaled(at(Dof::v), row_of(l, Dof::rz), d);
    add_scaled(at(Dof::w), row_of(l, Dof::ry), -d);
  }

  std::vector<Eigen::Triplet<Real>> triplets;
  for (Index full = 0; full < n_full_; ++full)
    for (const auto& [col, value] : rows[static_cast<std::size_t>(full)]) triplets.emplace_back(full, col, value);
  T_.resize(n_full_, n_reduced());
  T_.setFromTriplets(triplets.begin(), triplets.end());
}

ComplexVector DofMap::expand(const ComplexVector& reduced) const { return T_.cast<Complex>() * reduced; }

}  // namespace feran

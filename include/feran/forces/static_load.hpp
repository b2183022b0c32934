#pragma once
/// @file
/// A constant load at a node.

#include <array>
#include <string_view>
#include <vector>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// Forces [N] along x, y, z and moments [N m] about x, y, z, indexed by Dof. Used by
/// the static analysis, and by run-ups that ask for the static loads.
struct StaticLoad {
  Index node = 0;
  std::array<Real, dofs_per_node> load{};

  std::string_view kind() const { return "static_load"; }
  std::vector<Index> nodes() const { return {node}; }
  void add_static(Vector& f) const {
    for (int d = 0; d < dofs_per_node; ++d) f(dofs_per_node * node + d) += load[static_cast<std::size_t>(d)];
  }
};

}  // namespace feran

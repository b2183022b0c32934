#include <feran/model/model.hpp>

#include <fmt/format.h>

namespace feran {

std::size_t Model::n_forces(std::string_view kind) const {
  std::size_t n = 0;
  for (const Force& f : forces) n += f.kind() == kind ? 1 : 0;
  return n;
}

Index Model::find_node(int number) const {
  for (Index i = 0; i < n_nodes(); ++i)
    if (nodes[static_cast<std::size_t>(i)].number == number) return i;
  return -1;
}

Index Model::find_node(const std::string& node_name) const {
  if (node_name.empty()) return -1;
  for (Index i = 0; i < n_nodes(); ++i)
    if (nodes[static_cast<std::size_t>(i)].name == node_name) return i;
  return -1;
}

std::string Model::node_label(Index index) const {
  const Node& n = nodes.at(static_cast<std::size_t>(index));
  return n.name.empty() ? fmt::format("{}", n.number) : fmt::format("{} ({})", n.number, n.name);
}

}  // namespace feran

#include "suggestions.hpp"

namespace feran::detail {

std::vector<std::string> node_names(const Model& model) {
  std::vector<std::string> names;
  for (const Node& node : model.nodes)
    if (!node.name.empty()) names.push_back(node.name);
  return names;
}

std::vector<int> node_numbers(const Model& model) {
  std::vector<int> numbers;
  for (const Node& node : model.nodes) numbers.push_back(node.number);
  return numbers;
}

std::optional<std::string> closest_node_name(const Model& model, std::string_view text,
                                             const std::vector<std::string>& extra) {
  std::vector<std::string> candidates = node_names(model);
  candidates.insert(candidates.end(), extra.begin(), extra.end());
  return closest_match(text, candidates, node_name_distance);
}

}  // namespace feran::detail

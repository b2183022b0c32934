#pragma once
/// @file
/// "Did you mean …?" support for node references of a built model (private to io/).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <feran/core/suggestions.hpp>
#include <feran/model/model.hpp>

namespace feran::detail {

/// The names of the named nodes of @p model, in node order.
std::vector<std::string> node_names(const Model& model);
/// The numbers of the nodes of @p model, in node order.
std::vector<int> node_numbers(const Model& model);

/// The node name (or word of @p extra, such as "ground") that @p text was most
/// likely meant to be: closest_match() with distance node_name_distance.
std::optional<std::string> closest_node_name(const Model& model, std::string_view text,
                                             const std::vector<std::string>& extra = {});

}  // namespace feran::detail

#pragma once
/// @file
/// "Did you mean …?" support for messages about misspelt names (private to io/).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace feran::detail {

/// Levenshtein distance (insertions, deletions, substitutions) between @p a and @p b.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate @p word was most likely meant to be: a case-insensitive match if
/// there is one, else the candidate at the smallest edit distance when that distance
/// is at most @p max_distance (the first such candidate on ties); std::nullopt
/// otherwise or when @p word is itself a candidate.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates,
                                         std::size_t max_distance);

/// "a, b or c" (or "a, b and c" with @p conjunction "and"); each item quoted with
/// @p quote when it is not '\0'.
std::string join_list(const std::vector<std::string>& items, std::string_view conjunction = "or",
                      char quote = '\0');

}  // namespace feran::detail

#pragma once
/// @file
/// "Did you mean …?" support for messages about misspelt names, and list phrasing.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace feran::detail {

/// Largest edit distance at which a node name is suggested for a misspelt one.
inline constexpr std::size_t node_name_distance = 2;

/// Levenshtein distance (insertions, deletions, substitutions) between @p a and @p b.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// edit_distance(a, b) when it is at most @p limit, else limit + 1; in time
/// O(limit·max(|a|, |b|)) (a diagonal band of the table), so that long names cost
/// little.
std::size_t edit_distance_at_most(std::string_view a, std::string_view b, std::size_t limit);

/// The candidate @p word was most likely meant to be: a case-insensitive match if
/// there is one, else the candidate at the smallest edit distance when that distance
/// is at most @p max_distance (the first such candidate on ties); std::nullopt
/// otherwise or when @p word is itself a candidate.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates,
                                         std::size_t max_distance);

/// "a, b or c" (or "a, b and c" with @p conjunction "and"); each item quoted with
/// @p quote when it is not '\0'.
std::string join_list(const std::vector<std::string>& items, std::string_view conjunction = "or", char quote = '\0');

/// "1-8, 20 and 21": @p numbers sorted, runs of consecutive numbers joined.
std::string number_ranges(std::vector<int> numbers);

/// True when @p s is non-empty and holds only the digits 0-9.
bool all_digits(std::string_view s);

}  // namespace feran::detail

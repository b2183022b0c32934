// "Did you mean" suggestions: the banded edit distance against the full table, and
// names far longer than any real one.
#include <feran/core/suggestions.hpp>

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace feran::detail {
namespace {

// The band gives the full Levenshtein distance wherever that is within the limit,
// and limit + 1 otherwise: checked on 20,000 random pairs over a three-letter
// alphabet (many near matches), lengths 0 to 12, limits 0 to 4.
TEST(Suggestions, BandedDistanceEqualsTheFullOneWithinItsLimit) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> length(0, 12), letter(0, 2), limit(0, 4);
  auto word = [&] {
    std::string w(static_cast<std::size_t>(length(rng)), 'a');
    for (char& c : w) c = static_cast<char>('a' + letter(rng));
    return w;
  };
  for (int k = 0; k < 20000; ++k) {
    const std::string a = word(), b = word();
    const auto l = static_cast<std::size_t>(limit(rng));
    const std::size_t full = edit_distance(a, b);
    EXPECT_EQ(edit_distance_at_most(a, b, l), full <= l ? full : l + 1) << a << " / " << b << " limit " << l;
  }
}

// A 100 kB node name (a hostile or generated file) took over two minutes through the
// full table for every candidate; in the band it is a few hundred thousand steps.
TEST(Suggestions, LongNamesGetSuggestionsToo) {
  const std::string name(100000, 'n');
  std::string typo = name;
  typo[50000] = 'm';
  const std::vector<std::string> candidates = {std::string(99000, 'n'), name, "disk"};
  EXPECT_EQ(closest_match(typo, candidates, node_name_distance), name);
  EXPECT_EQ(closest_match("disc", candidates, node_name_distance), "disk");
  EXPECT_FALSE(closest_match(std::string(100000, 'x'), candidates, node_name_distance));
}

}  // namespace
}  // namespace feran::detail

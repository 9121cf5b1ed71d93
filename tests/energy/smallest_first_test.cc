// PlaceSmallestFirst against a full sort of seeded random lists, with ties and a comparator.
#include "energy/smallest_first.h"

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

TEST(PlaceSmallestFirst, PutsTheCountSmallestInOrderAheadOfTheRest) {
  std::mt19937_64 random(1);
  std::uniform_int_distribution<int> value(0, 50);  // many ties
  for (size_t count : {size_t{0}, size_t{1}, size_t{17}, size_t{300}}) {
    std::vector<std::pair<int, int>> values;
    for (int i = 0; i < 300; ++i) values.emplace_back(value(random), i);
    std::vector<std::pair<int, int>> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::pair<int, int>> placed = values;
    PlaceSmallestFirst(&placed, count, [](const std::pair<int, int>& v) { return v.first; });
    EXPECT_TRUE(std::equal(sorted.begin(), sorted.begin() + count, placed.begin()));
    std::sort(placed.begin(), placed.end());
    EXPECT_EQ(placed, sorted);  // nothing lost or repeated
  }
}

TEST(PlaceSmallestFirst, FollowsTheComparator) {
  std::vector<int> values = {4, 9, 1, 7, 3, 8};
  PlaceSmallestFirst(&values, 3, [](int v) { return -v; }, [](int a, int b) { return a > b; });
  EXPECT_EQ(std::vector<int>(values.begin(), values.begin() + 3), (std::vector<int>{9, 8, 7}));
}

}  // namespace
}  // namespace lpd::energy

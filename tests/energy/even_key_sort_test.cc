// SortByEvenKeys against std::sort of seeded lists: even keys (the squared distances of a
// disc's points), bunched and far keys (buckets past the insertion sort's size), ties broken by
// a second field, a comparator that orders by descending value, and all keys equal.
#include "energy/even_key_sort.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

using Entry = std::pair<int, double>;  // (index, squared distance), as the k-nearest search

bool Closer(const Entry& a, const Entry& b) {
  return a.second < b.second || (a.second == b.second && a.first < b.first);
}

double Distance(const Entry& e) { return e.second; }

void ExpectSortedAsStdSort(std::vector<Entry> values) {
  std::vector<Entry> expected = values;
  std::sort(expected.begin(), expected.end(), Closer);
  SortByEvenKeys(values.data(), values.size(), Distance, Closer);
  ASSERT_EQ(values, expected);
}

TEST(SortByEvenKeys, OrdersTheSquaredDistancesOfADiscAsStdSort) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int size : {0, 1, 2, 3, 17, 131, 1500}) {
    std::vector<Entry> values;
    while (static_cast<int>(values.size()) < size) {
      const double x = unit(random), y = unit(random);
      if (x * x + y * y <= 1.0) values.emplace_back(static_cast<int>(values.size()), x * x + y * y);
    }
    ExpectSortedAsStdSort(values);
  }
}

TEST(SortByEvenKeys, OrdersBunchedFarAndTiedKeysAsStdSort) {
  std::mt19937_64 random(2);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> coarse(0, 9);
  std::vector<Entry> bunched, far, tied;
  for (int i = 0; i < 400; ++i) {
    bunched.emplace_back(i, std::abs(normal(random)) * 1e-3);
    far.emplace_back(i, std::abs(normal(random)));
    tied.emplace_back(399 - i, coarse(random));  // ties ordered by index, which runs down
  }
  bunched.back().second = 1e6;  // all but one key in the first bucket
  far[17].second = 1e300;
  ExpectSortedAsStdSort(bunched);
  ExpectSortedAsStdSort(far);
  ExpectSortedAsStdSort(tied);
  std::vector<Entry> equal;
  for (int i = 0; i < 50; ++i) equal.emplace_back((i * 37) % 50, 0.25);
  ExpectSortedAsStdSort(equal);
}

// `count` standard normal values, seeded.
std::vector<double> NormalValues(int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> values(count);
  for (double& v : values) v = normal(random);
  return values;
}

TEST(SortByEvenKeys, FollowsADescendingComparatorWithANegatedKey) {
  std::vector<double> values = NormalValues(200, 3);
  std::vector<double> expected = values;
  std::sort(expected.begin(), expected.end(), std::greater<double>());
  SortByEvenKeys(values.data(), values.size(), [](double v) { return -v; },
                 std::greater<double>());
  EXPECT_EQ(values, expected);
}

TEST(SortByEvenKeys, SortsPlainValuesAscending) {
  std::vector<double> values = NormalValues(128, 4);
  std::vector<double> expected = values;
  std::sort(expected.begin(), expected.end());
  SortByEvenKeys(values.data(), values.size());
  EXPECT_EQ(values, expected);
}

TEST(SortByEvenKeys, FallsBackToStdSortOnKeysNotFinite) {
  std::vector<Entry> values = {{0, 3.0}, {1, HUGE_VAL}, {2, 1.0}, {3, 2.0}};
  SortByEvenKeys(values.data(), values.size(), Distance, Closer);
  EXPECT_EQ(values, (std::vector<Entry>{{2, 1.0}, {3, 2.0}, {0, 3.0}, {1, HUGE_VAL}}));
}

}  // namespace
}  // namespace lpd::energy

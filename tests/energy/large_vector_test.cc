// LargeVector holds what std::vector holds; large arrays start on a huge-page boundary.
#include "energy/large_vector.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

bool OnHugePageBoundary(const void* data) {
  return reinterpret_cast<std::uintptr_t>(data) % kHugePageBytes == 0;
}

TEST(LargeVector, HoldsWhatAStdVectorHolds) {
  for (const size_t size : {size_t{0}, size_t{7}, size_t{3} << 20}) {
    std::vector<int64_t> expected(size);
    std::iota(expected.begin(), expected.end(), -5);
    LargeVector<int64_t> values(expected.begin(), expected.end());
    ASSERT_EQ(values.size(), size);
    EXPECT_TRUE(std::equal(values.begin(), values.end(), expected.begin()));
    // Growing keeps the old elements; the copy and the assignment compare equal.
    values.resize(size + 100);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), values.begin()));
    values.push_back(42);
    EXPECT_EQ(values.back(), 42);
    const LargeVector<int64_t> copy = values;
    EXPECT_EQ(copy, values);
    values.assign(size, 9);
    EXPECT_EQ(std::count(values.begin(), values.end(), 9), static_cast<long>(size));
  }
}

TEST(LargeVector, LargeArraysStartOnAHugePage) {
  const LargeVector<double> large(kHugePageBytes / sizeof(double));
  EXPECT_TRUE(OnHugePageBoundary(large.data()));
  LargeVector<int> grown;
  for (int i = 0; i < (3 << 20); ++i) grown.push_back(i);  // regrows past the bar
  EXPECT_TRUE(OnHugePageBoundary(grown.data()));
  EXPECT_EQ(grown[(3 << 20) - 1], (3 << 20) - 1);
}

TEST(AdviseHugePages, LeavesTheContentsAsTheyWere) {
  // An unaligned range of ordinary heap memory, partly written before the advice.
  std::vector<double> values(3 * kHugePageBytes / sizeof(double) + 13);
  std::iota(values.begin(), values.begin() + 1000, 1.0);
  AdviseHugePages(values.data() + 1, sizeof(double) * (values.size() - 1));
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(values[i], i + 1.0);
  EXPECT_EQ(values.back(), 0.0);
  AdviseHugePages(nullptr, 0);
  AdviseHugePages(values.data(), 1);
}

}  // namespace
}  // namespace lpd::energy

#include "energy/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lpd::energy {
namespace {

constexpr int kBitsPerAxis = 21;

// Spreads the low 21 bits of v so that bit b lands on bit 3b.
uint64_t SpreadBits(uint32_t v) {
  uint64_t x = v & ((1u << kBitsPerAxis) - 1);
  x = (x | (x << 32)) & 0x1f00000000ffffULL;
  x = (x | (x << 16)) & 0x1f0000ff0000ffULL;
  x = (x | (x << 8)) & 0x100f00f00f00f00fULL;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ULL;
  x = (x | (x << 2)) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

uint64_t MortonCode(uint32_t x, uint32_t y, uint32_t z) {
  return SpreadBits(x) | (SpreadBits(y) << 1) | (SpreadBits(z) << 2);
}

std::vector<int> MortonOrder(const PointList& points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (n == 0) return order;
  Point3 low = Point3::Constant(HUGE_VAL), high = Point3::Constant(-HUGE_VAL);
  for (const Point3& p : points) {
    if (!p.allFinite()) continue;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = (high - low).maxCoeff();
  const double cells = static_cast<double>((1u << kBitsPerAxis) - 1);
  const double scale = extent > 0.0 && std::isfinite(extent) ? cells / extent : 0.0;
  std::vector<uint64_t> codes(n, 0);
  for (int i = 0; i < n; ++i) {
    const Point3 cell = (points[i] - low) * scale;
    if (!cell.allFinite()) continue;  // code 0
    codes[i] = MortonCode(static_cast<uint32_t>(cell.x()), static_cast<uint32_t>(cell.y()),
                          static_cast<uint32_t>(cell.z()));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&codes](int a, int b) { return codes[a] < codes[b]; });
  return order;
}

}  // namespace lpd::energy

// The k-nearest search of every point of a cloud (the probe's, the k-NN graph's, the final
// steps'), nanoflann's own search against NearestNeighbors::ForEach, which from
// kRadiusFirstMinK on selects the k nearest from a guessed radius (docs/performance.md,
// "Time against the first benchmark's build"); and the 1,500 nearest of every 96th point. The cloud: a unit sphere of 50,000 points
// with Gaussian noise of a third of their spacing, in Morton order as the solver's points.
#include <random>

#include <benchmark/benchmark.h>

#include "energy/nearest_neighbors.h"
#include "energy/spatial_order.h"

namespace lpd::energy {
namespace {

const PointList& NoisySphere() {
  static const PointList points = [] {
    constexpr int kPoints = 50000;
    std::mt19937_64 random(1);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double spacing = std::sqrt(4.0 * M_PI / kPoints);
    PointList sphere;
    for (int i = 0; i < kPoints; ++i) {
      const Point3 direction = Point3(normal(random), normal(random), normal(random)).normalized();
      sphere.push_back(direction * (1.0 + spacing / 3.0 * normal(random)));
    }
    PointList ordered;
    for (int i : MortonOrder(sphere)) ordered.push_back(sphere[i]);
    return ordered;
  }();
  return points;
}

void BM_NanoflannSearch(benchmark::State& state) {
  const PointList& points = NoisySphere();
  const int k = static_cast<int>(state.range(0));
  PointListAdaptor adaptor{points};
  L2PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(kKdTreeLeafSize));
  tree.buildIndex();
  std::vector<int> nearest(k);
  std::vector<double> squared_distances(k);
  for (auto _ : state) {
    for (const Point3& p : points) {
      tree.knnSearch(p.data(), k, nearest.data(), squared_distances.data());
      benchmark::DoNotOptimize(nearest.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * points.size());
}

void BM_NearestNeighborsForEach(benchmark::State& state) {
  const PointList& points = NoisySphere();
  const int k = static_cast<int>(state.range(0));
  const NearestNeighbors search(points);
  for (auto _ : state) {
    search.ForEach(static_cast<int>(points.size()), k, 1, [&](int q) { return points[q]; },
                   [](int, const int* nearest, const double*, int) {
                     benchmark::DoNotOptimize(nearest);
                   });
  }
  state.SetItemsProcessed(state.iterations() * points.size());
}

// The merged sides' regions (solvers/merged_sides.h): the 1,500 nearest of every 96th point.
// Few queries of many neighbours, where setting up the grid (the k-th distances of 32 sample
// queries) weighs as much as the queries.
void BM_NearestNeighborsForEachRegions(benchmark::State& state) {
  const PointList& points = NoisySphere();
  constexpr int kRegionPoints = 1500, kStride = 96;
  const int queries = static_cast<int>(points.size()) / kStride;
  const NearestNeighbors search(points);
  for (auto _ : state) {
    search.ForEach(queries, kRegionPoints, 1, [&](int q) { return points[q * kStride]; },
                   [](int, const int* nearest, const double*, int) {
                     benchmark::DoNotOptimize(nearest);
                   });
  }
  state.SetItemsProcessed(state.iterations() * queries);
}

void NeighborCounts(benchmark::internal::Benchmark* benchmark) {
  for (int k : {20, 32, 48, 64, 131, 261, 400}) benchmark->Arg(k);
}

BENCHMARK(BM_NanoflannSearch)->Apply(NeighborCounts)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NearestNeighborsForEach)->Apply(NeighborCounts)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NearestNeighborsForEachRegions)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lpd::energy

BENCHMARK_MAIN();

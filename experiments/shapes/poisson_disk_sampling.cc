#include "experiments/shapes/poisson_disk_sampling.h"

#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "energy/point_kd_tree.h"

namespace lpd::experiments {
namespace {

// Candidates per kept sample (Yuksel's and Open3D's choice).
constexpr int kCandidatesPerSample = 5;

}  // namespace

SurfaceSamples EliminateSamples(const SurfaceSamples& dense, int count, double area) {
  const int n = static_cast<int>(dense.points.size());
  if (count <= 0 || count > n) {
    throw std::invalid_argument("Poisson-disk sampling: cannot keep " + std::to_string(count) +
                                " of " + std::to_string(n) + " samples");
  }
  if (!(area > 0.0)) throw std::invalid_argument("Poisson-disk sampling: the surface has no area");
  const double r_max = std::sqrt(area / (2.0 * std::sqrt(3.0) * count));
  const double reach = 2.0 * r_max;
  energy::PointListAdaptor adaptor{dense.points};
  energy::L2PointKdTree tree(3, adaptor,
                             nanoflann::KDTreeSingleIndexAdaptorParams(energy::kKdTreeLeafSize));
  tree.buildIndex();
  auto weight = [reach](double squared_distance) {
    return std::pow(1.0 - std::sqrt(squared_distance) / reach, 8);
  };
  // Each sample's neighbours within reach (itself excluded) and its crowding.
  std::vector<std::vector<std::pair<int, double>>> neighbors(n);
  std::vector<double> crowding(n, 0.0);
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<int, double>> found;
    tree.radiusSearch(dense.points[i].data(), reach * reach, found, nanoflann::SearchParams());
    for (const auto& item : found) {
      if (item.first == i) continue;
      const double w = weight(item.second);
      neighbors[i].emplace_back(item.first, w);
      crowding[i] += w;
    }
  }
  // Max-heap on (crowding, -index); stale entries are skipped when popped.
  using Entry = std::pair<double, int>;
  auto after = [](const Entry& a, const Entry& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(after)> heap(after);
  for (int i = 0; i < n; ++i) heap.emplace(crowding[i], i);
  std::vector<bool> removed(n, false);
  for (int remaining = n; remaining > count;) {
    const auto [value, i] = heap.top();
    heap.pop();
    if (removed[i] || value != crowding[i]) continue;
    removed[i] = true;
    --remaining;
    for (const auto& [j, w] : neighbors[i]) {
      if (removed[j]) continue;
      crowding[j] -= w;
      heap.emplace(crowding[j], j);
    }
  }
  SurfaceSamples kept;
  kept.points.reserve(count);
  kept.normals.reserve(count);
  for (int i = 0; i < n; ++i) {
    if (removed[i]) continue;
    kept.points.push_back(dense.points[i]);
    kept.normals.push_back(dense.normals[i]);
  }
  return kept;
}

double SurfaceArea(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const energy::Point3& a = mesh.vertices.at(t[0]);
    area += 0.5 * (mesh.vertices.at(t[1]) - a).cross(mesh.vertices.at(t[2]) - a).norm();
  }
  return area;
}

SurfaceSamples PoissonDiskSample(const TriangleMesh& mesh, int count, uint64_t seed) {
  return EliminateSamples(SampleTriangleMesh(mesh, kCandidatesPerSample * count, seed), count,
                          SurfaceArea(mesh));
}

SurfaceSamples PoissonDiskSample(const ProceduralShape& shape, int count, uint64_t seed) {
  return EliminateSamples(shape.Sample(kCandidatesPerSample * count, seed), count, shape.Area());
}

}  // namespace lpd::experiments

#include "solvers/feature_snapping.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <Eigen/Dense>

#include "energy/plane_projection.h"
#include "solvers/dbscan.h"

namespace lpd::solvers {
namespace {

constexpr int kMaxClusters = 3;  // Sec. 3.4: "a maximum of three clusters"
// Below this |n_1 x n_2| (about 0.6 degrees) two planes have no usable intersection line.
constexpr double kMinIntersectionSine = 1e-2;
constexpr double kPi = 3.14159265358979323846;

// A plane n^T x + d = 0 with |n| = 1, from a 4-vector t = (n, d) up to scale.
Eigen::Vector4d UnitNormalPlane(const Eigen::Vector4d& t) { return t / t.head<3>().norm(); }

// The point of the line {n_a^T x + d_a = 0, n_b^T x + d_b = 0} closest to p: p minus the
// least-norm correction in span(n_a, n_b) that satisfies both plane equations.
Eigen::Vector3d ProjectOntoIntersection(const Eigen::Vector4d& a, const Eigen::Vector4d& b,
                                        const Eigen::Vector3d& p) {
  Eigen::Matrix<double, 3, 2> normals;
  normals << a.head<3>(), b.head<3>();
  const Eigen::Vector2d residuals(a.head<3>().dot(p) + a(3), b.head<3>().dot(p) + b(3));
  const Eigen::Matrix2d gram = normals.transpose() * normals;
  return p - normals * gram.ldlt().solve(residuals);
}

}  // namespace

bool FeatureSnappingOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!(cluster_angle_deg > 0.0 && cluster_angle_deg < 90.0)) {
    out << "snap_cluster_angle_deg must be in (0, 90), got " << cluster_angle_deg;
  } else if (min_cluster_planes < 1) {
    out << "snap_min_cluster_planes must be >= 1, got " << min_cluster_planes;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

SnappingCounts SnapFeaturePoints(const energy::Problem& problem, const energy::Variables& v,
                                 const std::vector<uint8_t>& is_feature,
                                 const FeatureSnappingOptions& options,
                                 energy::PointList* projected) {
  const energy::NeighborGraph& graph = problem.graph;
  const double cos_radius = std::cos(options.cluster_angle_deg * kPi / 180.0);
  SnappingCounts counts;
  std::vector<Eigen::Vector4d> planes;
  for (int i = 0; i < problem.num_points(); ++i) {
    if (!is_feature[i]) continue;
    planes.clear();
    for (int e = graph.incident_offsets[i]; e < graph.incident_offsets[i + 1]; ++e) {
      const auto& pair = graph.pairs[graph.incident_pairs[e]];
      const Eigen::Vector4d t = v.t.row(pair[0] == i ? pair[1] : pair[0]).transpose();
      if (t.head<3>().squaredNorm() > energy::kMinPlaneNormalSquaredNorm) {
        planes.push_back(UnitNormalPlane(t));
      }
    }
    // DBSCAN distance 1 - |cos| of the angle between normals: monotone in the angle, blind
    // to orientation.
    const int m = static_cast<int>(planes.size());
    Eigen::MatrixXd distances(m, m);
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) {
        distances(a, b) = 1.0 - std::abs(planes[a].head<3>().dot(planes[b].head<3>()));
      }
    }
    const DbscanClusters clusters =
        Dbscan(distances, 1.0 - cos_radius, options.min_cluster_planes);

    // Cluster planes: members aligned with the cluster's first member, then averaged.
    std::vector<Eigen::Vector4d> sums(clusters.num_clusters, Eigen::Vector4d::Zero());
    std::vector<int> sizes(clusters.num_clusters, 0);
    for (int a = 0; a < m; ++a) {
      const int c = clusters.labels[a];
      if (c == kDbscanNoise) continue;
      const bool flip = sizes[c] > 0 && sums[c].head<3>().dot(planes[a].head<3>()) < 0.0;
      sums[c] += flip ? Eigen::Vector4d(-planes[a]) : planes[a];
      ++sizes[c];
    }
    std::vector<int> largest(clusters.num_clusters);
    std::iota(largest.begin(), largest.end(), 0);
    std::stable_sort(largest.begin(), largest.end(),
                     [&](int a, int b) { return sizes[a] > sizes[b]; });
    largest.resize(std::min<int>(largest.size(), kMaxClusters));
    if (largest.size() < 2) {
      ++counts.left_on_plane;
      continue;
    }
    const Eigen::Vector3d p = problem.frame.ToNormalized((*projected)[i]);
    std::vector<Eigen::Vector4d> cluster_planes;
    for (int c : largest) cluster_planes.push_back(UnitNormalPlane(sums[c]));
    if (cluster_planes.size() == 3) {  // keep the two planes nearest to p
      auto distance = [&](const Eigen::Vector4d& plane) {
        return std::abs(plane.head<3>().dot(p) + plane(3));
      };
      std::stable_sort(cluster_planes.begin(), cluster_planes.end(),
                       [&](const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
                         return distance(a) < distance(b);
                       });
    }
    const Eigen::Vector4d& a = cluster_planes[0];
    const Eigen::Vector4d& b = cluster_planes[1];
    const Eigen::Vector3d snapped = ProjectOntoIntersection(a, b, p);
    const energy::Point3& q = problem.points[i];
    const double reach = (problem.points[graph.NeighborsOf(i)[graph.k - 1]] - q).norm();
    if (a.head<3>().cross(b.head<3>()).norm() < kMinIntersectionSine ||
        (snapped - p).norm() > reach) {
      ++counts.left_on_plane;
      continue;
    }
    (*projected)[i] = problem.frame.ToInput(snapped);
    ++(largest.size() == 2 ? counts.snapped_to_edge : counts.snapped_at_corner);
  }
  return counts;
}

}  // namespace lpd::solvers

#include "solvers/dbscan.h"

namespace lpd::solvers {

DbscanClusters Dbscan(const Eigen::MatrixXd& distances, double radius, int min_points) {
  const int m = static_cast<int>(distances.rows());
  std::vector<char> is_core(m);
  for (int a = 0; a < m; ++a) {
    is_core[a] = (distances.row(a).array() <= radius).count() >= min_points;
  }
  DbscanClusters clusters;
  clusters.labels.assign(m, kDbscanNoise);
  std::vector<int> frontier;
  for (int seed = 0; seed < m; ++seed) {
    if (!is_core[seed] || clusters.labels[seed] != kDbscanNoise) continue;
    const int cluster = clusters.num_clusters++;
    clusters.labels[seed] = cluster;
    frontier.assign(1, seed);
    while (!frontier.empty()) {  // grow through core items only
      const int a = frontier.back();
      frontier.pop_back();
      for (int b = 0; b < m; ++b) {
        if (clusters.labels[b] != kDbscanNoise || distances(a, b) > radius) continue;
        clusters.labels[b] = cluster;
        if (is_core[b]) frontier.push_back(b);
      }
    }
  }
  return clusters;
}

}  // namespace lpd::solvers

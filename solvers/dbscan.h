// lpd: DBSCAN clustering (Ester et al. 1996) of a small item set given its distance matrix.
//
// Item a is a core item if at least `min_points` items (a itself included) lie within `radius`
// of it. Clusters are the connected components of core items under "within radius", each
// joined by the non-core items within radius of one of its core items (a border item reached
// from two clusters goes to the first one found). Every other item is noise. Brute force,
// O(m^2): meant for neighbourhoods of tens of items, such as the planes around one sample
// (the feature improvement of Sec. 3.4).
#ifndef LPD_SOLVERS_DBSCAN_H_
#define LPD_SOLVERS_DBSCAN_H_

#include <vector>

#include <Eigen/Core>

namespace lpd::solvers {

constexpr int kDbscanNoise = -1;

struct DbscanClusters {
  std::vector<int> labels;  // per item: its cluster in [0, num_clusters) or kDbscanNoise
  int num_clusters = 0;     // numbered in the order of their first core item
};

// `distances` is a symmetric m x m matrix. Requires radius >= 0 and min_points >= 1.
DbscanClusters Dbscan(const Eigen::MatrixXd& distances, double radius, int min_points);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_DBSCAN_H_

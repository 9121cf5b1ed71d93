// lpd: the optional feature improvement of Sec. 3.4.
//
// A point i flagged as near a feature is moved from its own tangent plane t_i onto the most
// likely position of the feature: the planes t_j of its pairs (i, j) in M are clustered by
// DBSCAN on the angle between their normals (sign-blind, since t_j and -t_j are one plane).
// With two clusters, p_i' (the projection onto t_i) is projected onto the intersection line
// of the two cluster planes; with three (a corner), onto the line of the two cluster planes
// nearest to p_i'. A cluster plane is the mean of its members, orientations aligned, scaled
// to a unit normal. DBSCAN may find more clusters than the paper's three; the three largest
// are kept. Points are left on t_i when fewer than two clusters are found, when the two
// planes are nearly parallel, or when the line lies farther from p_i' than i's k-th
// neighbour lies from p_i (the neighbourhood cannot vouch for such a feature).
#ifndef LPD_SOLVERS_FEATURE_SNAPPING_H_
#define LPD_SOLVERS_FEATURE_SNAPPING_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

struct FeatureSnappingOptions {
  // DBSCAN radius: two neighbouring planes are close when their normals are at most this
  // many degrees apart (either orientation).
  double cluster_angle_deg = 10.0;
  // DBSCAN density: a plane with this many planes within the radius (itself included) is a
  // core plane. The paper does not give its DBSCAN parameters; these are ours.
  int min_cluster_planes = 4;

  bool IsValid(std::string* error) const;
};

struct SnappingCounts {
  int snapped_to_edge = 0;     // two clusters
  int snapped_at_corner = 0;   // three or more clusters
  int left_on_plane = 0;       // feature points not moved (see the header comment)
};

// Moves the feature points of `projected` (the projections onto t_i, in input frame and in
// the problem's point order) onto their feature lines. `is_feature` is in the same order.
SnappingCounts SnapFeaturePoints(const energy::Problem& problem, const energy::Variables& v,
                                 const std::vector<uint8_t>& is_feature,
                                 const FeatureSnappingOptions& options,
                                 energy::PointList* projected);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_FEATURE_SNAPPING_H_

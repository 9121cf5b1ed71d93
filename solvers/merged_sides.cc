#include "solvers/merged_sides.h"

#include <algorithm>
#include <cmath>

#include "energy/nearest_neighbors.h"
#include "energy/sheet_split.h"

namespace lpd::solvers {

double MaxMergedKurtosis(int region_points) {
  return 3.0 - kSidesKurtosisStandardErrors * std::sqrt(24.0 / region_points);
}

bool EstimateTwoSides(double m2, double m4, double max_kurtosis, TwoSides* sides) {
  if (!(m2 > 0.0) || !(m4 < max_kurtosis * m2 * m2)) return false;
  if (!(m4 > energy::kMinTwoSidesKurtosis * m2 * m2)) return false;
  const double excess = 3.0 * m2 * m2 - m4;  // 2 a^4
  if (!(excess > 0.0)) return false;
  const double half_gap = std::pow(0.5 * excess, 0.25);
  const double sigma_squared = m2 - half_gap * half_gap;
  if (!(sigma_squared > 0.0)) return false;
  sides->half_gap = half_gap;
  sides->sigma_squared = sigma_squared;
  return true;
}

bool SidesMayHaveMerged(const NeighborhoodSize& estimates) {
  return estimates.thin_candidate_fraction >= kThinShareForNoWidening;
}

energy::PointList SeparateMergedSides(const energy::PointList& inputs,
                                      const energy::PointList& outputs,
                                      const energy::PointList& normals,
                                      const std::vector<uint8_t>& movable, int num_threads,
                                      int* moved) {
  if (moved) *moved = 0;
  energy::PointList result = outputs;
  std::vector<int> anchors;  // the movable points with a normal
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (movable[i] && normals[i].squaredNorm() > 0.0) anchors.push_back(static_cast<int>(i));
  }
  const int n = static_cast<int>(outputs.size());
  if (static_cast<int>(anchors.size()) < kSidesRegionPoints) return result;

  // Every point's offset from its anchor's plane: its own, or its nearest anchor's.
  std::vector<int> anchor_of(n, -1);
  for (int i : anchors) anchor_of[i] = i;
  energy::PointList anchor_points(anchors.size());
  for (size_t r = 0; r < anchors.size(); ++r) anchor_points[r] = outputs[anchors[r]];
  std::vector<int> others;
  for (int i = 0; i < n; ++i) {
    if (anchor_of[i] < 0) others.push_back(i);
  }
  if (!others.empty()) {
    const energy::NearestNeighbors anchor_search(anchor_points);
    anchor_search.ForEach(static_cast<int>(others.size()), 1, num_threads,
                          [&](int r) { return inputs[others[r]]; },
                          [&](int r, const int* nearest, const double*, int) {
                            anchor_of[others[r]] = anchors[nearest[0]];
                          });
  }
  energy::PointList positions(n);
  std::vector<double> offset(n);
  for (int i = 0; i < n; ++i) {
    const int a = anchor_of[i];
    positions[i] = outputs[a];
    offset[i] = normals[a].dot(inputs[i] - outputs[a]);
  }

  // The regions' moments about 0, around every kSidesRegionCentreStride-th anchor.
  std::vector<int> centres;
  for (size_t r = 0; r < anchors.size(); r += kSidesRegionCentreStride) {
    centres.push_back(anchors[r]);
  }
  const int num_centres = static_cast<int>(centres.size());
  std::vector<TwoSides> sides(num_centres);
  std::vector<uint8_t> merged(num_centres, 0);
  const double max_kurtosis = MaxMergedKurtosis(kSidesRegionPoints);
  const energy::NearestNeighbors region_search(positions);
  region_search.ForEach(num_centres, kSidesRegionPoints, num_threads,
                        [&](int c) { return positions[centres[c]]; },
                        [&](int c, const int* nearest, const double*, int found) {
                          double m2 = 0.0, m4 = 0.0;
                          for (int j = 0; j < found; ++j) {
                            const double z2 = offset[nearest[j]] * offset[nearest[j]];
                            m2 += z2;
                            m4 += z2 * z2;
                          }
                          merged[c] = EstimateTwoSides(m2 / found, m4 / found, max_kurtosis,
                                                       &sides[c]);
                        });

  const auto num_merged = std::count(merged.begin(), merged.end(), 1);
  if (num_merged < kMinMergedRegionShare * num_centres) return result;

  // Each anchor moves to its expected side in its nearest centre's region.
  energy::PointList centre_points(num_centres);
  for (int c = 0; c < num_centres; ++c) centre_points[c] = positions[centres[c]];
  std::vector<uint8_t> shifted(anchors.size(), 0);
  const energy::NearestNeighbors centre_search(centre_points);
  centre_search.ForEach(
      static_cast<int>(anchors.size()), 1, num_threads,
      [&](int r) { return outputs[anchors[r]]; },
      [&](int r, const int* nearest, const double*, int) {
        const int c = nearest[0];
        if (!merged[c]) return;
        const int i = anchors[r];
        const TwoSides& s = sides[c];
        const double side = s.half_gap * std::tanh(s.half_gap * offset[i] / s.sigma_squared);
        result[i] = outputs[i] + side * normals[i];
        shifted[r] = 1;
      });
  if (moved) *moved = static_cast<int>(std::count(shifted.begin(), shifted.end(), 1));
  return result;
}

}  // namespace lpd::solvers

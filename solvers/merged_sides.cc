#include "solvers/merged_sides.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "energy/nearest_neighbors.h"
#include "energy/sheet_split.h"
#include "solvers/median.h"

namespace lpd::solvers {

double MaxMergedKurtosis(int region_points) {
  return 3.0 - kSidesKurtosisStandardErrors * std::sqrt(24.0 / region_points);
}

double MaxGrowthKurtosis(int region_points) {
  return 3.0 - kSidesGrowthStandardErrors * std::sqrt(24.0 / region_points);
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

bool SideRegions::MergedEnough() const {
  const auto num_seeds = std::count(seed.begin(), seed.end(), 1);
  return !seed.empty() && num_seeds >= kMinMergedRegionShare * seed.size();
}

std::vector<int> SideRegions::MergedRegionOf(const energy::PointList& points,
                                             int num_threads) const {
  std::vector<int> region_of(points.size(), -1);
  if (centres.empty()) return region_of;
  const energy::NearestNeighbors centre_search(centres);
  centre_search.ForEach(static_cast<int>(points.size()), 1, num_threads,
                        [&](int r) { return points[r]; },
                        [&](int r, const int* nearest, const double*, int) {
                          if (merged[nearest[0]]) region_of[r] = nearest[0];
                        });
  return region_of;
}

SideRegions MeasureSideRegions(const energy::PointList& positions,
                               const std::vector<double>& offsets, const std::vector<int>& pool,
                               int num_threads) {
  SideRegions regions;
  if (static_cast<int>(positions.size()) < kSidesRegionPoints) return regions;
  std::vector<int> centres;
  for (size_t r = 0; r < pool.size(); r += kSidesRegionCentreStride) centres.push_back(pool[r]);
  const int num_centres = static_cast<int>(centres.size());
  regions.centres.resize(num_centres);
  for (int c = 0; c < num_centres; ++c) regions.centres[c] = positions[centres[c]];
  regions.sides.resize(num_centres);
  regions.merged.assign(num_centres, 0);
  regions.seed.assign(num_centres, 0);
  regions.median_abs_offset.resize(num_centres);
  const double seed_kurtosis = MaxMergedKurtosis(kSidesRegionPoints);
  const double growth_kurtosis = MaxGrowthKurtosis(kSidesRegionPoints);
  std::vector<uint8_t> may_grow(num_centres, 0);
  const energy::NearestNeighbors region_search(positions);
  region_search.ForEach(
      num_centres, kSidesRegionPoints, num_threads,
      [&](int c) { return regions.centres[c]; },
      [&](int c, const int* nearest, const double*, int found) {
        double m2 = 0.0, m4 = 0.0;
        std::vector<double> magnitudes(found);
        for (int j = 0; j < found; ++j) {
          const double z = offsets[nearest[j]];
          m2 += z * z;
          m4 += z * z * z * z;
          magnitudes[j] = std::abs(z);
        }
        m2 /= found;
        m4 /= found;
        may_grow[c] = EstimateTwoSides(m2, m4, growth_kurtosis, &regions.sides[c]);
        regions.seed[c] = may_grow[c] && m4 < seed_kurtosis * m2 * m2;
        regions.median_abs_offset[c] = Median(&magnitudes);
      });
  // Growth from the seeds through neighbouring regions under the growth bar: the regions
  // connected to a seed through such regions, whatever the order of the centres.
  const int neighbors = std::min(num_centres, kSidesGrowthNeighbors + 1);
  std::vector<int> adjacent(static_cast<size_t>(num_centres) * neighbors);
  const energy::NearestNeighbors centre_search(regions.centres);
  centre_search.ForEach(num_centres, neighbors, num_threads,
                        [&](int c) { return regions.centres[c]; },
                        [&](int c, const int* nearest, const double*, int found) {
                          std::copy_n(nearest, found,
                                      adjacent.data() + static_cast<size_t>(c) * neighbors);
                        });
  std::vector<int> front;
  for (int c = 0; c < num_centres; ++c) {
    if (regions.seed[c]) {
      regions.merged[c] = 1;
      front.push_back(c);
    }
  }
  if (front.size() < kMinGrowthSeedShare * num_centres) front.clear();
  while (!front.empty()) {
    const int c = front.back();
    front.pop_back();
    for (int a = 0; a < neighbors; ++a) {
      const int d = adjacent[static_cast<size_t>(c) * neighbors + a];
      if (regions.merged[d] || !may_grow[d]) continue;
      regions.merged[d] = 1;
      front.push_back(d);
    }
  }
  return regions;
}

double OffsetDeviation(const energy::PointList& inputs, const energy::PointList& outputs,
                       const energy::PointList& normals, const std::vector<int>& anchors) {
  if (anchors.empty()) return 0.0;
  std::vector<double> magnitudes(anchors.size());
  for (size_t r = 0; r < anchors.size(); ++r) {
    const int i = anchors[r];
    magnitudes[r] = std::abs(normals[i].dot(inputs[i] - outputs[i]));
  }
  return kMedianAbsToSigma * Median(&magnitudes);
}

energy::PointList SidesReference(const energy::PointList& outputs,
                                 const energy::PointList& normals,
                                 const std::vector<int>& anchors, double band, int num_threads) {
  energy::PointList reference = outputs;
  const int count = static_cast<int>(anchors.size());
  if (!(band > 0.0) || count < 2) return reference;
  energy::PointList anchor_points(count);
  for (int r = 0; r < count; ++r) anchor_points[r] = outputs[anchors[r]];
  const double min_cosine = std::cos(kSidesReferenceMaxAngleDegrees * M_PI / 180.0);
  const energy::NearestNeighbors search(anchor_points);
  search.ForEach(count, std::min(kSidesReferenceSearched * kSidesReferenceNeighbors, count),
                 num_threads, [&](int r) { return anchor_points[r]; },
                 [&](int r, const int* nearest, const double*, int found) {
                   const int i = anchors[r];
                   const energy::Point3& n = normals[i];
                   // (distance across n squared, height along n) of the candidates
                   thread_local std::vector<std::pair<double, double>> candidates;
                   candidates.clear();
                   for (int b = 0; b < found; ++b) {
                     if (std::abs(n.dot(normals[anchors[nearest[b]]])) < min_cosine) continue;
                     const energy::Point3 step = anchor_points[nearest[b]] - outputs[i];
                     const double height = n.dot(step);
                     if (!(std::abs(height) < band)) continue;
                     candidates.emplace_back(step.squaredNorm() - height * height, height);
                   }
                   const size_t used =
                       std::min(candidates.size(), static_cast<size_t>(kSidesReferenceNeighbors));
                   std::partial_sort(candidates.begin(), candidates.begin() + used,
                                     candidates.end());
                   double sum = 0.0;
                   for (size_t b = 0; b < used; ++b) sum += candidates[b].second;
                   if (used > 0) reference[i] = outputs[i] + (sum / used) * n;
                 });
  return reference;
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

  // Every point's offset from its anchor's reference plane: its own, or its nearest anchor's.
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
  const double band =
      kSidesReferenceBandDeviations * OffsetDeviation(inputs, outputs, normals, anchors);
  const energy::PointList reference = SidesReference(outputs, normals, anchors, band, num_threads);
  energy::PointList positions(n);
  std::vector<double> offset(n);
  for (int i = 0; i < n; ++i) {
    const int a = anchor_of[i];
    positions[i] = outputs[a];
    offset[i] = normals[a].dot(inputs[i] - reference[a]);
  }

  const SideRegions regions = MeasureSideRegions(positions, offset, anchors, num_threads);
  if (!regions.MergedEnough()) return result;
  const std::vector<int> region_of = regions.MergedRegionOf(anchor_points, num_threads);
  // Each anchor of a merged region moves to the side its offset's sign picks.
  int count = 0;
  for (size_t r = 0; r < anchors.size(); ++r) {
    if (region_of[r] < 0) continue;
    const int i = anchors[r];
    const double half_gap = regions.sides[region_of[r]].half_gap;
    result[i] = reference[i] + (offset[i] >= 0.0 ? half_gap : -half_gap) * normals[i];
    ++count;
  }
  if (moved) *moved = count;
  return result;
}

}  // namespace lpd::solvers

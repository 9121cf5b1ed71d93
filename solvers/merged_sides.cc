#include "solvers/merged_sides.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>

#include "energy/nearest_neighbors.h"
#include "energy/sheet_split.h"
#include "energy/smallest_first.h"
#include "solvers/median.h"
#include "solvers/movable_rows.h"

namespace lpd::solvers {

double MaxMergedKurtosis(int region_points) {
  return 3.0 - kSidesKurtosisStandardErrors * std::sqrt(24.0 / region_points);
}

double MaxGrowthKurtosis(int region_points) {
  return 3.0 - kSidesGrowthStandardErrors * std::sqrt(24.0 / region_points);
}

double ChanceShareUnder(double standard_errors) {
  return 0.5 * std::erfc(standard_errors / std::sqrt(2.0));  // Phi(-standard_errors)
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
  return estimates.thin_candidate_fraction >= kThinCloudShare;
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
                               int num_threads, const std::vector<uint8_t>* split) {
  SideRegions regions;
  if (static_cast<int>(positions.size()) < kSidesRegionPoints) return regions;
  std::vector<int> centres;
  for (size_t r = 0; r < pool.size(); r += kSidesRegionCentreStride) centres.push_back(pool[r]);
  const int num_centres = static_cast<int>(centres.size());
  regions.centres.resize(num_centres);
  for (int c = 0; c < num_centres; ++c) regions.centres[c] = positions[centres[c]];
  regions.sides.resize(num_centres);
  regions.growable.assign(num_centres, 0);
  regions.seed.assign(num_centres, 0);
  regions.merged.assign(num_centres, 0);
  regions.median_abs_offset.resize(num_centres);
  regions.unsplit_only.assign(num_centres, 0);
  regions.counted.assign(num_centres, 1);
  const energy::NearestNeighbors region_search(positions);
  region_search.ForEach(
      num_centres, kSidesRegionPoints, num_threads,
      [&](int c) { return regions.centres[c]; },
      [&](int c, const int* nearest, const double*, int found) {
        // The moments over all the region's points and over those that see no other layer.
        double m2 = 0.0, m4 = 0.0, unsplit_m2 = 0.0, unsplit_m4 = 0.0;
        int split_points = 0;
        std::vector<double> magnitudes(found);
        for (int j = 0; j < found; ++j) {
          const double z = offsets[nearest[j]];
          m2 += z * z;
          m4 += z * z * z * z;
          magnitudes[j] = std::abs(z);
          if (split && (*split)[nearest[j]]) {
            ++split_points;
          } else {
            unsplit_m2 += z * z;
            unsplit_m4 += z * z * z * z;
          }
        }
        int used = found;
        if (split_points >= kSidesSplitRegionShare * found) {
          regions.unsplit_only[c] = 1;
          used = found - split_points;
          regions.counted[c] = used >= kMinUnsplitRegionPoints;
          m2 = unsplit_m2;
          m4 = unsplit_m4;
        }
        regions.median_abs_offset[c] = Median(&magnitudes);
        if (!regions.counted[c]) return;
        m2 /= used;
        m4 /= used;
        regions.growable[c] = EstimateTwoSides(m2, m4, MaxGrowthKurtosis(used), &regions.sides[c]);
        regions.seed[c] = regions.growable[c] && m4 < MaxMergedKurtosis(used) * m2 * m2;
      });
  for (size_t i = 0; i < offsets.size(); ++i) {
    if (split && (*split)[i]) continue;
    const double z2 = offsets[i] * offsets[i];
    regions.pooled_m2_sum += z2;
    regions.pooled_m4_sum += z2 * z2;
    ++regions.pooled_count;
  }
  return regions;
}

namespace {

// Each region's kSidesGrowthNeighbors nearest centres (itself among them), `width` a row.
struct CentreNeighbors {
  int width = 0;
  std::vector<int> nearest;
  const int* Of(int c) const { return nearest.data() + static_cast<size_t>(c) * width; }
};

CentreNeighbors NearestCentres(const SideRegions& regions, int num_threads) {
  const int num_centres = static_cast<int>(regions.centres.size());
  CentreNeighbors neighbors;
  neighbors.width = std::min(num_centres, kSidesGrowthNeighbors + 1);
  neighbors.nearest.resize(static_cast<size_t>(num_centres) * neighbors.width);
  const energy::NearestNeighbors centre_search(regions.centres);
  centre_search.ForEach(num_centres, neighbors.width, num_threads,
                        [&](int c) { return regions.centres[c]; },
                        [&](int c, const int* nearest, const double*, int found) {
                          std::copy_n(nearest, found,
                                      neighbors.nearest.data() +
                                          static_cast<size_t>(c) * neighbors.width);
                        });
  return neighbors;
}

// The growable regions connected to a merged one through growable regions among each other's
// nearest centres, merged too.
void GrowMergedRegions(const CentreNeighbors& neighbors, SideRegions* regions) {
  const int num_centres = static_cast<int>(regions->centres.size());
  std::vector<int> front;
  for (int c = 0; c < num_centres; ++c) {
    if (regions->merged[c]) front.push_back(c);
  }
  while (!front.empty()) {
    const int c = front.back();
    front.pop_back();
    for (int a = 0; a < neighbors.width; ++a) {
      const int d = neighbors.Of(c)[a];
      if (regions->merged[d] || !regions->growable[d]) continue;
      regions->merged[d] = 1;
      front.push_back(d);
    }
  }
}

// The counted regions with kSidesFillNeighbors or more merged regions among their nearest
// centres, merged too with those neighbours' mean sides, round after round (each round from
// the last one's marks) until none joins. A later round tests only the regions one of whose
// nearest centres joined in the last, so the rounds cost what joins.
void FillMergedHoles(const CentreNeighbors& neighbors, SideRegions* regions) {
  const int num_centres = static_cast<int>(regions->centres.size());
  // The regions among whose nearest centres each one is.
  std::vector<std::vector<int>> nearest_to(num_centres);
  for (int c = 0; c < num_centres; ++c) {
    for (int a = 0; a < neighbors.width; ++a) nearest_to[neighbors.Of(c)[a]].push_back(c);
  }
  std::vector<int> tested(num_centres);
  std::iota(tested.begin(), tested.end(), 0);
  std::vector<std::pair<int, TwoSides>> joining;
  std::vector<uint8_t> marked(num_centres, 0);
  while (!tested.empty()) {
    joining.clear();
    for (const int c : tested) {
      if (regions->merged[c] || !regions->counted[c]) continue;
      int merged = 0;
      TwoSides mean;
      for (int a = 0; a < neighbors.width; ++a) {
        const int d = neighbors.Of(c)[a];
        if (d == c || !regions->merged[d]) continue;
        ++merged;
        mean.half_gap += regions->sides[d].half_gap;
        mean.sigma_squared += regions->sides[d].sigma_squared;
      }
      if (merged < kSidesFillNeighbors) continue;
      mean.half_gap /= merged;
      mean.sigma_squared /= merged;
      joining.emplace_back(c, mean);
    }
    tested.clear();
    for (const auto& [c, sides] : joining) {
      regions->merged[c] = 1;
      regions->sides[c] = sides;
      for (const int d : nearest_to[c]) {
        if (!marked[d]) tested.push_back(d);
        marked[d] = 1;
      }
    }
    for (const int c : tested) marked[c] = 0;
  }
}

}  // namespace

bool MarkMergedRegions(const std::vector<SideRegions*>& parts, int num_threads) {
  size_t num_regions = 0, num_seeds = 0;
  for (const SideRegions* regions : parts) {
    num_regions += std::count(regions->counted.begin(), regions->counted.end(), 1);
    num_seeds += std::count(regions->seed.begin(), regions->seed.end(), 1);
  }
  double m2 = 0.0, m4 = 0.0, count = 0.0;
  for (const SideRegions* regions : parts) {
    m2 += regions->pooled_m2_sum;
    m4 += regions->pooled_m4_sum;
    count += static_cast<double>(regions->pooled_count);
  }
  const double total = static_cast<double>(num_regions);
  const bool merged_as_a_whole =
      num_seeds >= kMinSeedChanceMultiple * ChanceShareUnder(kSidesKurtosisStandardErrors) *
                       total &&
      count > 0.0 &&
      m4 * count < (3.0 - kPooledKurtosisStandardErrors * std::sqrt(24.0 / count)) * m2 * m2;
  const bool merged =
      num_regions > 0 && (num_seeds >= kMinMergedRegionShare * total || merged_as_a_whole);
  const bool grow = num_seeds >= kMinGrowthSeedShare * total || merged_as_a_whole;
  for (SideRegions* regions : parts) {
    regions->merged.assign(regions->seed.size(), 0);
    if (!merged) continue;
    regions->merged = regions->seed;
    if (!grow || regions->centres.empty()) continue;
    const CentreNeighbors neighbors = NearestCentres(*regions, num_threads);
    GrowMergedRegions(neighbors, regions);
    FillMergedHoles(neighbors, regions);
  }
  return merged;
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
                                 const std::vector<int>& anchors, double band, int num_threads,
                                 std::vector<uint8_t>* other_layer) {
  energy::PointList reference = outputs;
  if (other_layer) other_layer->assign(outputs.size(), 0);
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
                   int facing = 0;
                   for (int b = 0; b < found; ++b) {
                     if (std::abs(n.dot(normals[anchors[nearest[b]]])) < min_cosine) continue;
                     ++facing;
                     const energy::Point3 step = anchor_points[nearest[b]] - outputs[i];
                     const double height = n.dot(step);
                     if (!(std::abs(height) < band)) continue;
                     candidates.emplace_back(step.squaredNorm() - height * height, height);
                   }
                   if (other_layer && facing > 0 &&
                       facing - static_cast<int>(candidates.size()) >=
                           kSidesOtherLayerShare * facing) {
                     (*other_layer)[i] = 1;
                   }
                   const size_t used =
                       std::min(candidates.size(), static_cast<size_t>(kSidesReferenceNeighbors));
                   // the nearest, in order, for the same sum
                   energy::PlaceSmallestFirst(
                       &candidates, used,
                       [](const std::pair<double, double>& c) { return c.first; });
                   double sum = 0.0;
                   for (size_t b = 0; b < used; ++b) sum += candidates[b].second;
                   if (used > 0) reference[i] = outputs[i] + (sum / used) * n;
                 });
  return reference;
}

void FlagOtherLayerWithinReach(const energy::PointList& outputs,
                               const energy::PointList& normals,
                               const std::vector<int>& anchors, double band, int num_threads,
                               std::vector<uint8_t>* other_layer) {
  const int count = static_cast<int>(anchors.size());
  if (!(band > 0.0) || count < 2) return;
  energy::PointList anchor_points(count);
  for (int r = 0; r < count; ++r) anchor_points[r] = outputs[anchors[r]];
  const double min_cosine = std::cos(kSidesReferenceMaxAngleDegrees * M_PI / 180.0);
  const double reach = kSidesOtherLayerReachBands * band;
  // The share is read over every stride-th anchor (the points are in Morton order, so an
  // even spread), the stride such that about kSidesOtherLayerSampled of them lie within the
  // reach: the median count over kSidesOtherLayerStrideProbes anchors spread over the list.
  const energy::NearestNeighbors all(anchor_points);
  const int probes = std::min(count, kSidesOtherLayerStrideProbes);
  std::vector<double> within_counts(probes);
  all.ForEachWithin(probes, num_threads,
                    [&](int q) { return anchor_points[q * (count / probes)]; },
                    [reach](int) { return reach * reach; },
                    [&](int q, const std::vector<int>& within) {
                      within_counts[q] = static_cast<double>(within.size());
                    });
  const int stride =
      std::max(1, static_cast<int>(Median(&within_counts) / kSidesOtherLayerSampled));
  energy::PointList sampled;
  std::optional<energy::NearestNeighbors> sampled_search;
  if (stride > 1) {
    sampled.resize((count + stride - 1) / stride);
    for (size_t s = 0; s < sampled.size(); ++s) sampled[s] = anchor_points[s * stride];
    sampled_search.emplace(sampled);
  }
  const energy::NearestNeighbors& search = stride > 1 ? *sampled_search : all;
  search.ForEachWithin(count, num_threads, [&](int r) { return anchor_points[r]; },
                       [reach](int) { return reach * reach; },
                       [&](int r, const std::vector<int>& within) {
                         const int i = anchors[r];
                         if ((*other_layer)[i]) return;
                         const energy::Point3& n = normals[i];
                         int facing = 0, beyond = 0;
                         for (int s : within) {
                           const int b = s * stride;
                           if (std::abs(n.dot(normals[anchors[b]])) < min_cosine) continue;
                           ++facing;
                           beyond += !(std::abs(n.dot(anchor_points[b] - outputs[i])) < band);
                         }
                         if (facing > 0 && beyond >= kSidesOtherLayerShare * facing) {
                           (*other_layer)[i] = 1;
                         }
                       });
}

namespace {

// A part's anchors (its movable points with a normal), its reference and band, every point's
// anchor (its own or its nearest), its offset from that anchor's reference plane, and whether
// that anchor sees another layer, with the regions they give.
struct MeasuredPart {
  std::vector<int> anchors;
  energy::PointList anchor_points;
  energy::PointList reference;
  double band = 0.0;
  std::vector<int> anchor_of;
  energy::PointList positions;
  std::vector<double> offset;
  std::vector<uint8_t> other_layer;
  SideRegions regions;
};

// The part's regions, a point counting as split where its anchor sees another layer.
void MeasureRegions(int num_threads, MeasuredPart* measured) {
  const int n = static_cast<int>(measured->positions.size());
  std::vector<uint8_t> split(n);
  for (int i = 0; i < n; ++i) split[i] = measured->other_layer[measured->anchor_of[i]];
  measured->regions = MeasureSideRegions(measured->positions, measured->offset,
                                         measured->anchors, num_threads, &split);
}

MeasuredPart MeasurePart(const SidesPart& part, int num_threads) {
  MeasuredPart measured;
  std::vector<int>& anchors = measured.anchors;
  anchors = MovableRowsWithNormal(part.movable, part.normals);
  const energy::PointList& outputs = part.outputs;
  const int n = static_cast<int>(outputs.size());
  if (static_cast<int>(anchors.size()) < kSidesRegionPoints) return measured;

  // Every point's offset from its anchor's reference plane: its own, or its nearest anchor's.
  std::vector<int>& anchor_of = measured.anchor_of;
  anchor_of.assign(n, -1);
  for (int i : anchors) anchor_of[i] = i;
  measured.anchor_points.resize(anchors.size());
  for (size_t r = 0; r < anchors.size(); ++r) measured.anchor_points[r] = outputs[anchors[r]];
  std::vector<int> others;
  for (int i = 0; i < n; ++i) {
    if (anchor_of[i] < 0) others.push_back(i);
  }
  if (!others.empty()) {
    const energy::NearestNeighbors anchor_search(measured.anchor_points);
    anchor_search.ForEach(static_cast<int>(others.size()), 1, num_threads,
                          [&](int r) { return part.inputs[others[r]]; },
                          [&](int r, const int* nearest, const double*, int) {
                            anchor_of[others[r]] = anchors[nearest[0]];
                          });
  }
  measured.band = kSidesReferenceBandDeviations *
                 OffsetDeviation(part.inputs, outputs, part.normals, anchors);
  measured.reference = SidesReference(outputs, part.normals, anchors, measured.band,
                                      num_threads, &measured.other_layer);
  measured.positions.resize(n);
  measured.offset.resize(n);
  for (int i = 0; i < n; ++i) {
    const int a = anchor_of[i];
    measured.positions[i] = outputs[a];
    measured.offset[i] = part.normals[a].dot(part.inputs[i] - measured.reference[a]);
  }
  MeasureRegions(num_threads, &measured);
  return measured;
}

// Each anchor of a merged region moved to the side its offset's sign picks, but for those that
// see another layer in a region read without them.
energy::PointList MoveToSides(const SidesPart& part, const MeasuredPart& measured,
                              int num_threads, int* moved) {
  energy::PointList result = part.outputs;
  const std::vector<int> region_of =
      measured.regions.MergedRegionOf(measured.anchor_points, num_threads);
  for (size_t r = 0; r < region_of.size(); ++r) {
    if (region_of[r] < 0) continue;
    const int i = measured.anchors[r];
    if (measured.regions.unsplit_only[region_of[r]] && measured.other_layer[i]) continue;
    const double half_gap = measured.regions.sides[region_of[r]].half_gap;
    const double side = measured.offset[i] >= 0.0 ? half_gap : -half_gap;
    result[i] = measured.reference[i] + side * part.normals[i];
    ++*moved;
  }
  return result;
}

}  // namespace

std::vector<energy::PointList> SeparateMergedSides(const std::vector<SidesPart>& parts,
                                                   int num_threads, int* moved) {
  std::vector<MeasuredPart> measured;
  std::vector<SideRegions*> regions;
  for (const SidesPart& part : parts) measured.push_back(MeasurePart(part, num_threads));
  for (MeasuredPart& m : measured) regions.push_back(&m.regions);
  bool merged = MarkMergedRegions(regions, num_threads);
  if (merged) {
    // The outputs that see another layer within the reach as well. More such outputs only
    // take seeds and growable regions away, so where nothing merges without them, nothing
    // would with them: the wider search runs only here.
    for (size_t p = 0; p < parts.size(); ++p) {
      if (static_cast<int>(measured[p].anchors.size()) < kSidesRegionPoints) continue;
      FlagOtherLayerWithinReach(parts[p].outputs, parts[p].normals, measured[p].anchors,
                                measured[p].band, num_threads, &measured[p].other_layer);
      MeasureRegions(num_threads, &measured[p]);
    }
    merged = MarkMergedRegions(regions, num_threads);
  }
  int count = 0;
  std::vector<energy::PointList> result;
  for (size_t p = 0; p < parts.size(); ++p) {
    result.push_back(merged ? MoveToSides(parts[p], measured[p], num_threads, &count)
                            : parts[p].outputs);
  }
  if (moved) *moved = count;
  return result;
}

energy::PointList SeparateMergedSides(const energy::PointList& inputs,
                                      const energy::PointList& outputs,
                                      const energy::PointList& normals,
                                      const std::vector<uint8_t>& movable, int num_threads,
                                      int* moved) {
  return SeparateMergedSides({SidesPart{inputs, outputs, normals, movable}}, num_threads,
                             moved)[0];
}

}  // namespace lpd::solvers

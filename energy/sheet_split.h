// lpd: the two sides of a thin part, told apart in a neighbourhood.
//
// Where a part is thinner than the neighbourhood (a wall, a plate, a petal), a plane fitted
// through the neighbourhood lies between the two sides, and the signed offsets of the points
// from it form two clusters, one per side. The best split of the sorted offsets into two runs
// of kMinSheetPoints or more (one-dimensional 2-means, exact) measures it by its separation:
// the distance between the runs' means over their pooled within-run deviation. For n
// Gaussian offsets of one sheet the separation is about 2.7-2.9 (its 99.9% point 4.51 at
// n = 25, 3.36 at 100, 3.02 at 300, simulated); two sheets 4 noise deviations apart give
// about 4. A split whose two runs are not parallel planes (their normals more than
// kMaxSheetAngleDegrees apart: the two faces of a sharp edge) has separation 0; a run of
// fewer than kMinPointsForNormal points (the other side's cap near a thin part's rim) has no
// reliable normal, and is not tested.
//
// One neighbourhood decides poorly (two sheets 4 deviations apart pass the 99.9% point in
// 31-53% of neighbourhoods of 25-35 points); a thin part is a region, so a neighbourhood is
// split where the mean separation over its points' own neighbourhoods passes
// kThinRegionSeparation. That mean has medians 2.75-2.93 and 99th percentiles 3.0-3.4 on
// one sheet (sphere, beetle, lilium, FANDISK and JOINT samples; the top on sharp edges),
// 3.9-5.1 on plates and sheets 4-8 noise deviations apart (docs/method.md).
//
// Sides about 3 deviations apart pass kThinRegionSeparation in a few regions only, but the
// region means of their whole part sit above one sheet's (medians 2.97-3.20 against
// 2.71-2.87). Where a split region is found, it may therefore grow through the neighbouring
// regions whose mean passes kThinRegionGrowthSeparation (3.0, one sheet's 99th percentile at
// noise as wide as the spacing). At narrower noise the 128-point regions span more than
// sqrt(128 / pi) = 6.4 noise deviations and curved parts split as well as two sides do
// (2.1-2.9% of the points of the paper's CAD inputs at their lower noise), so there the
// regions grow only where the split ones are kThinGrowthSeedShare of the points or more (a
// thin-walled part: 11-96% on hollow boxes, tubes and plates; docs/method.md).
//
// Noise with a flat top (uniform across a slab, as from coarse depth quantization) also
// splits far apart: the halves of a uniform slab have separation sqrt(12) = 3.46, above
// kThinRegionSeparation, and a plane with such noise came out as two layers. Two sides are
// told from it by the shape of each run: the offsets from their own run's mean have kurtosis
// 1.8 in the halves of a uniform slab, about 3 on well-apart sides and 2.4-2.7 on sides 3-4
// noise deviations apart, whose runs the split truncates. So a region counts as two sides
// only where its neighbourhoods' mean within-run kurtosis also passes
// kMinTwoSidesKurtosis (region means: 1.83-2.07 on a uniform slab, 2.30-2.96 on plates and
// sheets 2.8-4 noise deviations apart, 2.3 and up on the layered tool scan; docs/method.md),
// or where its mean separation passes kClearSidesSeparation, which no slab reaches (its
// region means: at most 3.9-4.0): sides with flat-topped noise and a gap between them.
//
// Noise much narrower than the spacing splits curved and edged parts of one sheet: a
// 128-point neighbourhood then spans tens of noise deviations, and the height a cylinder, a
// saddle or a shallow edge takes across it parts the points into runs as far apart as two
// sides (exact bunny and FANDISK samples: 20% and 59% of the probes split, the output up to
// 4% farther from the surface than without the split). Such runs cover different parts of
// the plane: the middle and the rim, two opposite sectors, the two sides of the edge line.
// Two sides of a thin part cover the same footprint. The footprint difference, |C_l - C_u|
// (Frobenius) plus |m_l - m_u|^2 over the mean of trace C_l and trace C_u, with m and C the
// mean and covariance of each run's points within the plane, has region means 0.58-0.84
// and up (10th percentiles) on those low-noise regions and at most 0.42 (90th percentiles)
// on plates and sheets 2.8-4.2 noise deviations apart (docs/method.md). So below
// kClearSidesSeparation a region also needs its mean footprint difference under
// kMaxTwoSidesFootprintDifference.
//
// Where a thin part meets another (a wall standing on a floor, a fin on a plate), a
// neighbourhood near the junction holds both parts: its plane lies between them and its
// offsets do not part into two runs. So where the whole neighbourhood does not pass
// kThinRegionSeparation, the graph (neighbor_graph.h) also splits its slab: its points within
// kJunctionBandDeviations RMS offsets of the plane through its kJunctionPlanePoints nearest
// (the part p_i lies on), where that leaves out kJunctionLeftOutShare of them or more. The
// slab's split is kept where it passes kJunctionSeparation, above one sheet's 99.9% point at
// 100 points; the better of two splits would otherwise be the larger of two draws of one
// sheet's separation. The noise probe judges the whole neighbourhoods only: a rod's slab
// parts into its near and far sides, and counted as nearly split regions they turned off
// the noise's widening there (docs/method.md, "Junctions of thin parts").
#ifndef LPD_ENERGY_SHEET_SPLIT_H_
#define LPD_ENERGY_SHEET_SPLIT_H_

#include <vector>

#include <Eigen/Core>

#include "energy/point3.h"

namespace lpd::energy {

constexpr int kMinSheetPoints = 4;
// The neighbourhood a split is judged on: at least this many points (docs/method.md: with
// 64 / 96 / 128, a plate 4 noise deviations thick comes out 0.91 / 0.60 / 0.39 times its
// input's distance from the true surface).
constexpr int kSheetSplitPoints = 128;
constexpr double kMaxSheetAngleDegrees = 25.0;
constexpr int kMinPointsForNormal = 24;  // in each run, for the angle test
constexpr double kThinRegionSeparation = 3.3;
constexpr double kThinRegionGrowthSeparation = 3.0;
constexpr double kThinGrowthSeedShare = 0.1;
constexpr double kMinTwoSidesKurtosis = 2.2;
constexpr double kClearSidesSeparation = 4.5;
constexpr double kMaxTwoSidesFootprintDifference = 0.5;
constexpr int kJunctionPlanePoints = 24;
constexpr double kJunctionBandDeviations = 3.0;
constexpr double kJunctionSeparation = 3.5;
constexpr double kJunctionLeftOutShare = 0.1;

struct SheetSplit {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // of the least-squares plane
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();    // the neighbourhood's centroid
  double separation = 0.0;  // (upper_mean - lower_mean) / pooled within-run deviation
  double threshold = 0.0;   // offsets below it form the lower run
  double lower_mean = 0.0;
  double upper_mean = 0.0;
  // Of the offsets from their own run's mean: E[r^4] / E[r^2]^2 (3 where not split).
  double within_kurtosis = 3.0;
  // How differently the two runs cover the plane (above; 0 where not split).
  double footprint_difference = 0.0;

  double Offset(const Point3& p) const { return normal.dot(p - mean); }
  // The run of an offset: 0 lower, 1 upper.
  int Side(double offset) const { return offset < threshold ? 0 : 1; }
  // The offset of p from the mean of its own run.
  double OwnRunOffset(const Point3& p) const {
    const double offset = Offset(p);
    return offset - (Side(offset) == 0 ? lower_mean : upper_mean);
  }
};

// The split of points[members[0 .. count)] (count >= 2 kMinSheetPoints, else separation 0).
SheetSplit SplitSheets(const PointList& points, const int* members, int count);

// `whole`, SplitSheets of the same members, where it passes kThinRegionSeparation; else the
// split of the slab around the plane of the kJunctionPlanePoints nearest (a thin part's
// junction, above) where it passes kJunctionSeparation; else `whole`. The members are the
// nearest of members[0], nearest first.
SheetSplit SplitNearJunction(const PointList& points, const int* members, int count,
                             const SheetSplit& whole);

// The exact one-dimensional 2-means of a sorted list: the lower run sorted[0 .. lower_size)
// and the upper run, each of min_run values or more, whose values have the least sum of
// squared offsets from their own run's mean.
struct TwoRuns {
  int lower_size = 0;  // 0 where no split lowers that sum under the whole list's
  double within = 0.0;  // the sum, over both runs
  double lower_mean = 0.0;
  double upper_mean = 0.0;
};
TwoRuns BestTwoRuns(const std::vector<double>& sorted, int min_run);

// The footprint difference (above) of the runs offsets[a] < threshold and >= threshold, with
// offsets[a] the offset of points[a] along the unit `normal` from `origin`; 0 where a run is
// empty or the points do not spread within the plane.
double FootprintDifference(const std::vector<Point3>& points, const std::vector<double>& offsets,
                           const Eigen::Vector3d& normal, const Eigen::Vector3d& origin,
                           double threshold);

// The evidence for two sides over a region: its neighbourhoods' splits, averaged.
class RegionSplits {
 public:
  void Add(const SheetSplit& split) {
    Add(split.separation, split.within_kurtosis, split.footprint_difference);
  }
  void Add(double separation, double within_kurtosis, double footprint_difference) {
    separation_sum_ += separation;
    kurtosis_sum_ += within_kurtosis;
    footprint_sum_ += footprint_difference;
    ++count_;
  }
  // The mean separation passes `bar`, and the runs are too far apart to be anything but two
  // sides, or they are neither the halves of a flat-topped noise nor one sheet's middle and
  // rim (or sectors, or the two sides of an edge line).
  bool TwoSides(double bar) const {
    return count_ > 0 && separation_sum_ > bar * count_ &&
           (separation_sum_ > kClearSidesSeparation * count_ ||
            (kurtosis_sum_ > kMinTwoSidesKurtosis * count_ &&
             footprint_sum_ < kMaxTwoSidesFootprintDifference * count_));
  }

 private:
  double separation_sum_ = 0.0;
  double kurtosis_sum_ = 0.0;
  double footprint_sum_ = 0.0;
  int count_ = 0;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SHEET_SPLIT_H_

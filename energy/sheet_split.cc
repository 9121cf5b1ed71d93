#include "energy/sheet_split.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "energy/even_key_sort.h"
#include "energy/scatter_sum.h"

namespace lpd::energy {
namespace {

// The unit normal of the least-squares plane through points[0 .. count) (the centroid in
// *mean); false for fewer than 3 points.
bool PlaneNormal(const Point3* points, int count, Eigen::Vector3d* normal,
                 Eigen::Vector3d* mean) {
  if (count < 3) return false;
  *normal = LeastSquaresPlaneNormal(count, [points](int a) -> const Point3& { return points[a]; },
                                    mean);
  return true;
}

// The unit normals of the least-squares planes through the two runs (side 0 and 1 of each
// offset), each run's points added in their order, both in one pass over the points.
void RunNormals(const std::vector<Point3>& points, const std::vector<double>& offsets,
                const SheetSplit& split, Eigen::Vector3d normal[2]) {
  Eigen::Vector3d sum[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  int size[2] = {0, 0};
  for (size_t a = 0; a < points.size(); ++a) {
    const int side = split.Side(offsets[a]);
    sum[side] += points[a];
    ++size[side];
  }
  const Eigen::Vector3d mean[2] = {sum[0] / size[0], sum[1] / size[1]};
  ScatterSum scatter[2];
  for (size_t a = 0; a < points.size(); ++a) {
    const int side = split.Side(offsets[a]);
    scatter[side].Add(points[a] - mean[side]);
  }
  for (int side = 0; side < 2; ++side) {
    normal[side] = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter[side].Matrix())
                       .eigenvectors()
                       .col(0);
  }
}

}  // namespace

double FootprintDifference(const std::vector<Point3>& points, const std::vector<double>& offsets,
                           const Eigen::Vector3d& normal, const Eigen::Vector3d& origin,
                           double threshold) {
  Eigen::Vector3d sum[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  ScatterSum moment[2];
  int size[2] = {0, 0};
  for (size_t a = 0; a < offsets.size(); ++a) {
    const Eigen::Vector3d in_plane = points[a] - origin - offsets[a] * normal;
    const int side = offsets[a] < threshold ? 0 : 1;
    sum[side] += in_plane;
    moment[side].Add(in_plane);
    ++size[side];
  }
  if (size[0] == 0 || size[1] == 0) return 0.0;
  Eigen::Vector3d mean[2];
  Eigen::Matrix3d covariance[2];
  for (int side = 0; side < 2; ++side) {
    mean[side] = sum[side] / size[side];
    covariance[side] = moment[side].Matrix() / size[side] - mean[side] * mean[side].transpose();
  }
  const double spread = 0.5 * (covariance[0].trace() + covariance[1].trace());
  if (!(spread > 0.0)) return 0.0;
  return ((covariance[0] - covariance[1]).norm() + (mean[0] - mean[1]).squaredNorm()) / spread;
}

TwoRuns BestTwoRuns(const std::vector<double>& sorted, int min_run) {
  const int count = static_cast<int>(sorted.size());
  double sum = 0.0, squares = 0.0;
  for (double o : sorted) {
    sum += o;
    squares += o * o;
  }
  // Prefix sums over the lower run, which holds min_run or more.
  TwoRuns runs;
  runs.within = squares - sum * sum / count;
  double lower_sum = 0.0, lower_squares = 0.0, best_lower_sum = 0.0;
  for (int a = 0; a < min_run - 1; ++a) {
    lower_sum += sorted[a];
    lower_squares += sorted[a] * sorted[a];
  }
  for (int m = min_run; m <= count - min_run; ++m) {
    lower_sum += sorted[m - 1];
    lower_squares += sorted[m - 1] * sorted[m - 1];
    const double upper_sum = sum - lower_sum, upper_squares = squares - lower_squares;
    const double run_squares = lower_squares - lower_sum * lower_sum / m + upper_squares -
                               upper_sum * upper_sum / (count - m);
    if (run_squares < runs.within) {
      runs.within = run_squares;
      runs.lower_size = m;
      best_lower_sum = lower_sum;
    }
  }
  if (runs.lower_size > 0) {
    runs.lower_mean = best_lower_sum / runs.lower_size;
    runs.upper_mean = (sum - best_lower_sum) / (count - runs.lower_size);
  }
  return runs;
}

namespace {

// The split of the gathered neighbourhood `local` (sheet_split.h, SplitSheets); the size of
// its smaller run in *smaller_run (0 where not split).
SheetSplit SplitGathered(const std::vector<Point3>& local, int* smaller_run) {
  SheetSplit split;
  *smaller_run = 0;
  const int count = static_cast<int>(local.size());
  if (count < 2 * kMinSheetPoints) return split;
  if (!PlaneNormal(local.data(), count, &split.normal, &split.mean)) return split;
  thread_local std::vector<double> offsets, sorted;
  offsets.resize(count);
  for (int a = 0; a < count; ++a) offsets[a] = split.Offset(local[a]);
  sorted = offsets;
  SortByEvenKeys(sorted.data(), sorted.size());
  const TwoRuns runs = BestTwoRuns(sorted, kMinSheetPoints);
  const int best_size = runs.lower_size;
  const double best = runs.within;
  if (best_size == 0 || !(best > 0.0)) return split;
  *smaller_run = std::min(best_size, count - best_size);
  split.threshold = 0.5 * (sorted[best_size - 1] + sorted[best_size]);
  split.lower_mean = runs.lower_mean;
  split.upper_mean = runs.upper_mean;
  const double within_deviation = std::sqrt(best / (count - 2));
  double fourth = 0.0;
  for (double o : offsets) {
    const double r = o - (split.Side(o) == 0 ? split.lower_mean : split.upper_mean);
    fourth += r * r * r * r;
  }
  split.within_kurtosis = fourth * count / (best * best);
  // Two sides of a thin part are parallel; the two faces of a sharp edge are not. (A run of
  // few points has no reliable normal: the other side's cap near a thin part's rim.)
  if (*smaller_run >= kMinPointsForNormal) {
    Eigen::Vector3d run_normal[2];
    RunNormals(local, offsets, split, run_normal);
    if (std::abs(run_normal[0].dot(run_normal[1])) <
        std::cos(kMaxSheetAngleDegrees * M_PI / 180.0)) {
      return split;
    }
  }
  split.separation = (split.upper_mean - split.lower_mean) / within_deviation;
  split.footprint_difference =
      FootprintDifference(local, offsets, split.normal, split.mean, split.threshold);
  return split;
}

// points[members[0 .. count)], gathered once: every pass reads them in member order.
const std::vector<Point3>& Gather(const PointList& points, const int* members, int count) {
  thread_local std::vector<Point3> local;
  local.resize(count);
  for (int a = 0; a < count; ++a) local[a] = points[members[a]];
  return local;
}

}  // namespace

SheetSplit SplitSheets(const PointList& points, const int* members, int count) {
  int smaller_run = 0;
  return SplitGathered(Gather(points, members, count), &smaller_run);
}

SheetSplit SplitNearJunction(const PointList& points, const int* members, int count,
                             const SheetSplit& whole) {
  if (whole.separation >= kThinRegionSeparation || count < 2 * kJunctionPlanePoints) {
    return whole;
  }
  const std::vector<Point3>& local = Gather(points, members, count);
  // The slab of the part p_i lies on: the points within kJunctionBandDeviations RMS offsets of
  // the plane through its nearest.
  Eigen::Vector3d normal, mean;
  PlaneNormal(local.data(), kJunctionPlanePoints, &normal, &mean);
  double squares = 0.0;
  for (int a = 0; a < kJunctionPlanePoints; ++a) {
    const double offset = normal.dot(local[a] - mean);
    squares += offset * offset;
  }
  const double band = kJunctionBandDeviations * std::sqrt(squares / kJunctionPlanePoints);
  thread_local std::vector<Point3> slab;
  slab.clear();
  for (const Point3& p : local) {
    if (std::abs(normal.dot(p - mean)) < band) slab.push_back(p);
  }
  // Where it leaves out few points (the noise's tails), no other part is near.
  if (count - static_cast<int>(slab.size()) < kJunctionLeftOutShare * count) return whole;
  // Its runs must both be large enough to be tested for parallel sides (a few points of
  // another face within the slab, beside a sharp edge, are not a side), and they must stand
  // apart as one sheet's runs hardly do: the better of two splits is otherwise the larger of
  // two draws of one sheet's separation.
  int smaller_run = 0;
  const SheetSplit slab_split = SplitGathered(slab, &smaller_run);
  return smaller_run >= kMinPointsForNormal && slab_split.separation > kJunctionSeparation
             ? slab_split
             : whole;
}

}  // namespace lpd::energy

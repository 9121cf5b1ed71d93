#include "solvers/neighborhood_size.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "energy/coordinate_quantization.h"
#include "energy/normalization.h"
#include "energy/nearest_neighbors.h"
#include "energy/scatter_sum.h"
#include "energy/problem.h"
#include "energy/sheet_split.h"
#include "energy/split_search.h"
#include "energy/large_vector.h"
#include "solvers/median.h"
#include "solvers/merged_sides.h"

namespace lpd::solvers {

bool NeighborhoodSizeOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (probe_k < 4) {
    out << "probe_k must be >= 4, got " << probe_k;
  } else if (!(radius_in_sigmas > 0.0) || !std::isfinite(radius_in_sigmas)) {
    out << "k_radius_sigmas must be finite and > 0, got " << radius_in_sigmas;
  } else if (!(max_problem_size >= kSmallestProblemSize) || !std::isfinite(max_problem_size)) {
    out << "max_problem_size must be finite and >= " << kSmallestProblemSize << ", got "
        << max_problem_size;
  } else if (min_k < 3) {
    out << "min_k must be >= 3, got " << min_k;
  } else if (max_k < min_k) {
    out << "max_k must be >= " << min_k << " (the smallest k chosen), got " << max_k;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

namespace {

// At most this many probe neighbourhoods: their medians are then stable to about 0.5%.
constexpr int kMaxProbeQueries = 1 << 17;

// The probe's reading on a plane with Gaussian noise: sigma / spacing as read, and the read
// sigma over the true one (20,000 Poisson-disk points on two unit squares half a unit apart,
// scripts/probe_calibration.sh; tests/solvers/neighborhood_size_test.cc checks it).
struct PlaneReading {
  double read_ratio;  // read sigma / read spacing
  double fraction;    // read sigma / true sigma
};
constexpr PlaneReading kPlaneReadings[] = {
    {0.145, 1.000}, {0.285, 0.993}, {0.417, 0.983}, {0.538, 0.969}, {0.647, 0.952},
    {0.743, 0.931}, {0.825, 0.907}, {0.895, 0.881}, {0.954, 0.854}, {1.001, 0.826},
    {1.042, 0.799}, {1.077, 0.773}, {1.103, 0.747}, {1.127, 0.722}, {1.167, 0.679},
    {1.197, 0.641}, {1.219, 0.607}, {1.256, 0.538}, {1.274, 0.485}, {1.305, 0.414},
};

// Sides of a thin part too close to split (split_probe[q] false) read, from the plane
// through both, as two Gaussians at +-a with the noise's deviation s (merged_sides.h): their
// residuals' median reads the mixture's spread (1.34 s on a plate 2 s thick). Where a tenth of
// the regions around the probed points read so, `residuals` with each merged region's rows
// scaled so that the median of its probed points' own residuals reads s; else empty.
template <typename PointOf>
std::vector<double> SideResiduals(const energy::PointList& normalized,
                                  const energy::LargeVector<double>& offsets,
                                  const std::vector<uint8_t>& split_probe, int k,
                                  int num_threads, const PointOf& point_of,
                                  const std::vector<double>& residuals) {
  const int queries = static_cast<int>(split_probe.size());
  energy::PointList probed(queries);
  std::vector<double> own_offset(queries);
  std::vector<int> pool(queries);
  for (int query = 0; query < queries; ++query) {
    probed[query] = normalized[point_of(query)];
    own_offset[query] = offsets[static_cast<size_t>(query) * (k + 1)];
    pool[query] = query;
  }
  SideRegions regions = MeasureSideRegions(probed, own_offset, pool, num_threads);
  if (!MarkMergedRegions({&regions}, num_threads)) return {};
  const std::vector<int> region_of = regions.MergedRegionOf(probed, num_threads);
  std::vector<double> scaled = residuals;
  for (int query = 0; query < queries; ++query) {
    const int r = region_of[query];
    if (r < 0 || split_probe[query] || !(regions.median_abs_offset[r] > 0.0)) continue;
    // 1.4826 median |z| = s.
    const double scale = std::sqrt(regions.sides[r].sigma_squared) /
                         (kMedianAbsToSigma * regions.median_abs_offset[r]);
    const size_t row = static_cast<size_t>(query) * (k + 1);
    for (int a = 0; a <= k; ++a) scaled[row + a] *= scale;
  }
  return scaled;
}

// 1.4826 median |residual|: sigma for Gaussian residuals (residual_statistics.h), with the
// three degrees of freedom a plane through k + 1 points absorbs given back; NaN entries (the
// other side's points) left out.
double NoiseFromResiduals(std::vector<double> residuals, int k, double floor) {
  residuals.erase(std::remove_if(residuals.begin(), residuals.end(),
                                 [](double r) { return std::isnan(r); }),
                  residuals.end());
  return std::max(kMedianAbsToSigma * Median(&residuals) * std::sqrt((k + 1.0) / (k - 2.0)),
                  floor);
}

}  // namespace

double PlaneReadFraction(double read_ratio) {
  const auto* first = std::begin(kPlaneReadings);
  const auto* last = std::end(kPlaneReadings) - 1;
  if (read_ratio <= first->read_ratio) return first->fraction;
  if (read_ratio >= last->read_ratio) return last->fraction;
  const auto* upper = std::find_if(first, last, [read_ratio](const PlaneReading& r) {
    return r.read_ratio >= read_ratio;
  });
  const auto* lower = upper - 1;
  const double t = (read_ratio - lower->read_ratio) / (upper->read_ratio - lower->read_ratio);
  return lower->fraction + t * (upper->fraction - lower->fraction);
}

double LastPlaneReadRatio() { return std::end(kPlaneReadings)[-1].read_ratio; }

double PlaneReadingWeight(double thin_candidate_fraction) {
  return std::clamp((kThinCloudShare - thin_candidate_fraction) /
                        (kThinCloudShare - kThinShareForPlaneReadings),
                    0.0, 1.0);
}

double WideNoiseFactor(double read_ratio) {
  if (!(read_ratio > kCalibratedReadRatio)) return 1.0;
  return PlaneReadFraction(kCalibratedReadRatio) / PlaneReadFraction(read_ratio);
}

double NoiseEstimate(double read_sigma, double spacing, double thin_candidate_fraction) {
  const double fraction = PlaneReadFraction(read_sigma / spacing);
  return read_sigma /
         (1.0 + PlaneReadingWeight(thin_candidate_fraction) * (fraction - 1.0));
}

NeighborhoodSize ChooseNeighborhoodSize(const energy::PointList& points,
                                        const NeighborhoodSizeOptions& options,
                                        int num_threads) {
  const int n = static_cast<int>(points.size());
  if (n < options.min_k + 1) {
    throw std::invalid_argument("need at least " + std::to_string(options.min_k + 1) +
                                " points to choose k from the data, got " + std::to_string(n) +
                                " (give a smaller --k)");
  }
  const energy::Frame frame = energy::ComputeNormalizingFrame(points);
  energy::PointList normalized(n);
  for (int i = 0; i < n; ++i) normalized[i] = frame.ToNormalized(points[i]);
  const energy::NearestNeighbors search(normalized);
  const int k = std::min(options.probe_k, n - 1);
  const int queries = std::min(n, kMaxProbeQueries);
  // Signed distances of each probe neighbourhood's points from its plane.
  energy::LargeVector<double> offsets(static_cast<size_t>(queries) * (k + 1));
  energy::LargeVector<int> members(offsets.size());
  std::vector<double> alpha(queries);
  // The split of each probe's wider neighbourhood into the two sides of a thin part.
  std::vector<energy::SheetSplit> splits(options.split_sheets ? queries : 0);
  const int split_points =
      options.split_sheets ? std::min(n, std::max(k + 1, energy::kSheetSplitPoints)) : k + 1;
  // Query q probes input point i(q), spread evenly over the (Morton-ordered) points.
  auto point_of = [n, queries](int query) {
    return static_cast<int>(static_cast<int64_t>(query) * n / queries);
  };
  // With every point probed, the wider searches and their splits are kept for the graph,
  // searched as far as the graph may need (up to 2 kSheetSplitPoints, 1 KB a point): the
  // first split_points of them are what a search of split_points finds.
  std::shared_ptr<energy::SplitSearch> kept;
  int searched = split_points;
  if (options.split_sheets && queries == n) {
    searched = std::max(split_points,
                        std::min({n, options.max_k + 1, 2 * energy::kSheetSplitPoints}));
    kept = std::make_shared<energy::SplitSearch>();
    kept->searched = searched;
    kept->split_points = split_points;
    kept->nearest.resize(static_cast<size_t>(n) * searched);
  }
  auto probe = [&](int query, const int* nearest, const double*, int found) {
    const int i = point_of(query);
    if (kept) std::copy_n(nearest, found, kept->nearest.data() + static_cast<size_t>(i) * searched);
    found = std::min(found, split_points);
    // N(i) u {i}: the search finds i itself first (or a duplicate of it at distance 0).
    const auto member = [&](int a) -> const energy::Point3& { return normalized[nearest[a]]; };
    Eigen::Vector3d mean;
    const Eigen::Vector3d normal = energy::LeastSquaresPlaneNormal(k + 1, member, &mean);
    double squared_sum = 0.0;
    for (int a = 0; a <= k; ++a) squared_sum += (member(a) - normalized[i]).squaredNorm();
    for (int a = 0; a <= k; ++a) {
      offsets[static_cast<size_t>(query) * (k + 1) + a] =
          normal.dot(normalized[nearest[a]] - mean);
      members[static_cast<size_t>(query) * (k + 1) + a] = nearest[a];
    }
    alpha[query] = squared_sum / k;
    if (options.split_sheets) splits[query] = energy::SplitSheets(normalized, nearest, found);
  };
  search.ForEach(
      queries, searched, num_threads, [&](int query) { return normalized[point_of(query)]; },
      probe);
  NeighborhoodSize size;
  // Where a part is thinner than the neighbourhood, its two sides are measured each from its
  // own side's mean (energy/sheet_split.h): a probe counts as split when the splits over it
  // and the probed points among its probe_k nearest show two sides (RegionSplits::TwoSides).
  std::vector<int> query_of(options.split_sheets ? n : 0, -1);
  for (int query = 0; query < queries && options.split_sheets; ++query) {
    query_of[point_of(query)] = query;
  }
  std::vector<double> residuals(offsets.size());
  std::vector<uint8_t> split_probe(queries, 0);
  int thin = 0, candidates = 0;
#pragma omp parallel for schedule(static) num_threads(num_threads) reduction(+ : thin, candidates)
  for (int query = 0; query < queries; ++query) {
    const size_t row = static_cast<size_t>(query) * (k + 1);
    energy::RegionSplits region;
    for (int a = 0; a <= k && options.split_sheets; ++a) {
      const int other = query_of[members[row + a]];
      if (other >= 0) region.Add(splits[other]);
    }
    const bool two_sheets = region.TwoSides(energy::kThinRegionSeparation);
    thin += two_sheets;
    split_probe[query] = two_sheets;
    candidates += region.TwoSides(energy::kThinRegionGrowthSeparation);
    if (!two_sheets) {
      for (int a = 0; a <= k; ++a) residuals[row + a] = std::abs(offsets[row + a]);
      continue;
    }
    // Split, the probe's own side (by the wider neighbourhood's split) gets a plane of its
    // own, which the other side's points neither move nor tilt; the other side's points are
    // left out (NaN).
    const energy::SheetSplit& split = splits[query];
    const int own_side = split.Side(split.Offset(normalized[members[row]]));
    std::vector<int> own;
    for (int a = 0; a <= k; ++a) {
      residuals[row + a] = NAN;
      if (split.Side(split.Offset(normalized[members[row + a]])) == own_side) own.push_back(a);
    }
    const int m = static_cast<int>(own.size());
    if (m < 4) continue;
    Eigen::Vector3d mean;
    const Eigen::Vector3d normal = energy::LeastSquaresPlaneNormal(
        m, [&](int b) -> const energy::Point3& { return normalized[members[row + own[b]]]; },
        &mean);
    // The plane of m points absorbs three degrees of freedom, the probe's k + 1 as many:
    // scaled so that the correction below, made for k + 1, fits.
    const double dof = std::sqrt((m / (m - 3.0)) / ((k + 1.0) / (k - 2.0)));
    for (int a : own) {
      residuals[row + a] = dof * std::abs(normal.dot(normalized[members[row + a]] - mean));
    }
  }
  size.two_sheet_fraction = static_cast<double>(thin) / queries;
  size.thin_candidate_fraction = static_cast<double>(candidates) / queries;
  std::vector<double> side_residuals;
  if (options.split_sheets && SidesMayHaveMerged(size)) {
    side_residuals =
        SideResiduals(normalized, offsets, split_probe, k, num_threads, point_of, residuals);
  }
  const double floor = energy::QuantizationNoise(points) / frame.scale;
  size.read_sigma = NoiseFromResiduals(std::move(residuals), k, floor);
  size.merged_sides = !side_residuals.empty();
  if (kept) {
    kept->splits = std::move(splits);
    size.split_search = std::move(kept);
  }
  size.spacing = energy::SpacingFromMedianAlpha(Median(&alpha), k);
  if (!(size.spacing > 0.0)) {
    throw std::invalid_argument(
        "most points coincide with their " + std::to_string(k) +
        " nearest neighbours: no spacing to choose k from (remove the duplicates or give --k)");
  }
  size.noise_sigma =
      size.merged_sides
          ? NoiseFromResiduals(std::move(side_residuals), k, floor)
          : NoiseEstimate(size.read_sigma, size.spacing, size.thin_candidate_fraction);
  // Past the calibrated range the probe reads the noise ever lower (WideNoiseFactor).
  size.radius_in_sigmas = options.radius_in_sigmas;
  if (options.wide_noise) size.radius_in_sigmas *= WideNoiseFactor(size.read_sigma / size.spacing);
  const int largest = std::min<int>(options.max_k, n - 1);
  const auto k_at = [&](double radius_in_sigmas) {
    const double radius_in_spacings = radius_in_sigmas * size.read_sigma / size.spacing;
    const double chosen = M_PI * radius_in_spacings * radius_in_spacings;
    return static_cast<int>(std::lround(
        std::clamp(chosen, double(options.min_k), double(std::max(options.min_k, largest)))));
  };
  size.k = k_at(size.radius_in_sigmas);
  size.smoothing_scale =
      1.0 + PlaneReadingWeight(size.thin_candidate_fraction) *
                (double(k_at(options.radius_in_sigmas)) / size.k - 1.0);
  return size;
}

}  // namespace lpd::solvers

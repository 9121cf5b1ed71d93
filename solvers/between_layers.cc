#include "solvers/between_layers.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "energy/nearest_neighbors.h"
#include "energy/scatter_sum.h"
#include "energy/sheet_split.h"
#include "energy/smallest_first.h"
#include "solvers/median.h"
#include "solvers/merged_sides.h"
#include "solvers/movable_rows.h"
#include "solvers/two_layer_mixture.h"

namespace lpd::solvers {
namespace {

// The median of sorted[begin, end) and kMedianAbsToSigma times the median absolute
// deviation about it.
void RobustSpread(const std::vector<double>& sorted, int begin, int end, double* median,
                  double* deviation) {
  *median = sorted[begin + (end - begin) / 2];
  thread_local std::vector<double> distances;
  distances.resize(end - begin);
  for (int a = begin; a < end; ++a) distances[a - begin] = std::abs(sorted[a] - *median);
  *deviation = kMedianAbsToSigma * Median(&distances);
}

// A layer's height along the layers' normal over the plane across it, in the scaled in-plane
// coordinates (x, y): h = c . (1, x, y, x^2, x y, y^2).
using HeightField = Eigen::Matrix<double, 6, 1>;
constexpr double kFieldRefitDeviations = 2.5;

HeightField Monomials(double x, double y) {
  HeightField monomials;
  monomials << 1.0, x, y, x * x, x * y, y * y;
  return monomials;
}

// The largest principal curvature of a height field, in scaled coordinates.
double LargestCurvature(const HeightField& field) {
  Eigen::Matrix2d hessian;
  hessian << 2.0 * field(3), field(4), field(4), 2.0 * field(5);
  const Eigen::Vector2d curvatures =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian).eigenvalues();
  return curvatures.cwiseAbs().maxCoeff();
}

// Two layers read around a centre: heights along `normal` from `origin`.
struct Layers {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  energy::Point3 origin = energy::Point3::Zero();
  // The plane across `normal`: unit axes, and the in-plane distance that scales them to 1.
  Eigen::Vector3d axis[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double scale = 1.0;
  HeightField height[2] = {HeightField::Zero(), HeightField::Zero()};  // lower, upper run
  double spread[2] = {0.0, 0.0};  // robust deviations about the heights
  // The two-layer mixture fitted to the inputs (flat layers), where its means lie
  // kMinMixtureSeparation of its deviations apart (mixture_apart): its deviation, and each
  // run's move to the mixture's mean and that mean's variance.
  bool mixture_apart = false;
  double mixture_deviation = 0.0;
  double mixture_move[2] = {0.0, 0.0};
  double mixture_variance[2] = {0.0, 0.0};
  // How far each run's outputs move to the inputs' layer (0 where the mixture does not read as
  // two layers of noise; SetLayerCorrections).
  double correction[2] = {0.0, 0.0};
  double gap = 0.0;
  // The in-plane distance of the read outputs' centroid from the centre, over the farthest
  // of them across the normal: near 0 inside two layers, 0.42 where a straight rim crosses
  // the centre.
  double asymmetry = 0.0;
  bool curved = false;
  bool found = false;

  // Two layers no noise draw spans, read over a balanced footprint (between_layers.h).
  bool ClearlyApart(double deviation) const {
    return found && gap >= kClearLayerGapDeviations * deviation &&
           asymmetry < kMaxClearLayerAsymmetry;
  }

  // (x, y) of a point in the scaled plane across the normal.
  Eigen::Vector2d Across(const energy::Point3& point) const {
    const Eigen::Vector3d step = point - origin;
    return Eigen::Vector2d(axis[0].dot(step), axis[1].dot(step)) / scale;
  }
  double HeightAt(int run, const energy::Point3& point) const {
    if (!curved) return height[run](0) + correction[run];
    const Eigen::Vector2d xy = Across(point);
    return height[run].dot(Monomials(xy.x(), xy.y()));
  }
  // The correction of the run an output o lies nearer to.
  double Correction(const energy::Point3& o) const {
    const double h = normal.dot(o - origin);
    return correction[std::abs(h - height[0](0)) < std::abs(h - height[1](0)) ? 0 : 1];
  }
};

// The quadratic height field of the points a of one run (side[a] == run), with monomials[a]
// their monomials across the normal, fitted by least squares and again over the points
// within kFieldRefitDeviations robust deviations of the first fit (a run holds points left
// between the layers, too), and the robust deviation of the run's heights about it; false
// where it is not finite.
bool FitHeightField(const std::vector<HeightField>& monomials, const std::vector<double>& heights,
                    const std::vector<uint8_t>& side, int run, HeightField* field,
                    double* deviation) {
  thread_local std::vector<double> residuals;
  for (int round = 0; round < 2; ++round) {
    Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
    HeightField right = HeightField::Zero();
    int used = 0;
    for (size_t a = 0; a < monomials.size(); ++a) {
      if (side[a] != run) continue;
      if (round == 1 && !(std::abs(heights[a] - field->dot(monomials[a])) <=
                          kFieldRefitDeviations * *deviation)) {
        continue;
      }
      normal_matrix += monomials[a] * monomials[a].transpose();
      right += heights[a] * monomials[a];
      ++used;
    }
    if (used < HeightField::RowsAtCompileTime) return false;
    *field = normal_matrix.ldlt().solve(right);
    if (!field->allFinite()) return false;
    residuals.clear();
    for (size_t a = 0; a < monomials.size(); ++a) {
      if (side[a] == run) residuals.push_back(std::abs(heights[a] - field->dot(monomials[a])));
    }
    *deviation = kMedianAbsToSigma * Median(&residuals);
  }
  return true;
}

// Where the runs bend by more than kMaxFlatLayerBend times their gap, their fitted height
// fields and the deviations about them replace the medians (between_layers.h).
// `farthest_squared`: the largest squared distance across the normal of the points `local`.
void ReadCurvature(const std::vector<energy::Point3>& local, const std::vector<double>& heights,
                   double threshold, double farthest_squared, Layers* layers) {
  if (!(farthest_squared > 0.0)) return;
  layers->axis[0] = layers->normal.unitOrthogonal();
  layers->axis[1] = layers->normal.cross(layers->axis[0]);
  layers->scale = std::sqrt(farthest_squared);
  thread_local std::vector<uint8_t> side;
  thread_local std::vector<HeightField> monomials;
  side.resize(local.size());
  monomials.resize(local.size());
  for (size_t a = 0; a < local.size(); ++a) {
    side[a] = heights[a] < threshold ? 0 : 1;
    const Eigen::Vector2d xy = layers->Across(local[a]);
    monomials[a] = Monomials(xy.x(), xy.y());
  }
  HeightField field[2];
  double deviation[2];
  for (int run = 0; run < 2; ++run) {
    if (!FitHeightField(monomials, heights, side, run, &field[run], &deviation[run])) return;
  }
  const double curvature = std::max(LargestCurvature(field[0]), LargestCurvature(field[1])) /
                           farthest_squared;
  if (!(curvature * layers->gap > kMaxFlatLayerBend)) return;
  layers->curved = true;
  for (int run = 0; run < 2; ++run) {
    layers->height[run] = field[run];
    layers->spread[run] = deviation[run];
  }
}

// The two-layer mixture fitted to the inputs of the outputs `across[0, found)` (distance
// across the normal, output index) of flat layers, where its means lie apart
// (between_layers.h).
void FitInputLayers(const energy::PointList& inputs,
                    const std::vector<std::pair<double, int>>& across, int found,
                    double deviation, Layers* layers) {
  thread_local std::vector<double> input_heights;
  input_heights.resize(found);
  for (int b = 0; b < found; ++b) {
    input_heights[b] = layers->normal.dot(inputs[across[b].second] - layers->origin);
  }
  const double median[2] = {layers->height[0](0), layers->height[1](0)};
  TwoLayerMixture fit;
  if (!FitTwoLayerMixture(input_heights, median[0], median[1], deviation, &fit)) return;
  if (!(fit.mean[1] - fit.mean[0] > kMinMixtureSeparation * fit.deviation)) return;
  layers->mixture_apart = true;
  layers->mixture_deviation = fit.deviation;
  for (int run = 0; run < 2; ++run) {
    layers->mixture_move[run] = fit.mean[run] - median[run];
    layers->mixture_variance[run] = fit.mean_variance[run];
  }
}

// The corrections of the layers of the centres `read` (between_layers.h): each run of a
// mixture that reads as two layers of noise moves by d = the mixture's mean less the run's
// median, shrunk to d^3 / (d^2 + (kMixtureMoveStandardErrors se)^2). A mixture apart reads so
// where its deviation is under kMaxMixtureDeviationRatio times the median of the mixtures'
// deviations, where kMinMixtureShare of the centres read mixtures apart, else times the
// inputs' offsets' `deviation`.
void SetLayerCorrections(const std::vector<int>& read, double deviation,
                         std::vector<Layers>* layers) {
  std::vector<double> deviations;
  for (int c : read) {
    if ((*layers)[c].mixture_apart) deviations.push_back((*layers)[c].mixture_deviation);
  }
  const double reference = deviations.size() >= kMinMixtureShare * read.size()
                               ? Median(&deviations)
                               : deviation;
  for (int c : read) {
    Layers& l = (*layers)[c];
    for (int run = 0; run < 2; ++run) {
      l.correction[run] = 0.0;
      if (!(l.mixture_apart && l.mixture_deviation < kMaxMixtureDeviationRatio * reference)) {
        continue;
      }
      const double move = l.mixture_move[run];
      const double uncertainty =
          kMixtureMoveStandardErrors * kMixtureMoveStandardErrors * l.mixture_variance[run];
      l.correction[run] = move * move * move / (move * move + uncertainty);
    }
  }
}

// The dominant direction of the normals of the outputs `nearest[0, found)`.
Eigen::Vector3d LayerNormal(const energy::PointList& normals, const int* nearest, int found) {
  energy::ScatterSum normal_moment;
  for (int b = 0; b < found; ++b) normal_moment.Add(normals[nearest[b]]);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normal_moment.Matrix())
      .eigenvectors()
      .col(2);
}

// The layers along `normal` around `origin` of the kLayerNeighbors outputs nearest across it
// among `candidates` (between_layers.h).
Layers ReadLayers(const energy::PointList& inputs, const energy::PointList& outputs,
                  const std::vector<int>& candidates, const Eigen::Vector3d& normal,
                  const energy::Point3& origin, double deviation) {
  Layers layers;
  layers.origin = origin;
  layers.normal = normal;
  // (distance across the normal squared, output), ties by the output's index.
  thread_local std::vector<std::pair<double, int>> across;
  across.resize(candidates.size());
  for (size_t b = 0; b < candidates.size(); ++b) {
    const energy::Point3 step = outputs[candidates[b]] - origin;
    const double height = normal.dot(step);
    across[b] = {step.squaredNorm() - height * height, candidates[b]};
  }
  const int found = std::min(static_cast<int>(across.size()), kLayerNeighbors);
  if (found == 0) return layers;
  // the `found` nearest, in order
  energy::PlaceSmallestFirst(&across, found,
                             [](const std::pair<double, int>& a) { return a.first; });
  thread_local std::vector<energy::Point3> local;
  thread_local std::vector<double> heights, sorted;
  local.resize(found);
  heights.resize(found);
  Eigen::Vector3d in_plane_sum = Eigen::Vector3d::Zero();
  for (int b = 0; b < found; ++b) {
    local[b] = outputs[across[b].second];
    heights[b] = normal.dot(local[b] - origin);
    in_plane_sum += (local[b] - origin) - heights[b] * normal;
  }
  layers.asymmetry = in_plane_sum.norm() / found / std::sqrt(across[found - 1].first);
  sorted = heights;
  energy::SortByEvenKeys(sorted.data(), sorted.size());
  const int min_run = std::max(1, static_cast<int>(std::ceil(kMinLayerShare * found)));
  const energy::TwoRuns runs = energy::BestTwoRuns(sorted, min_run);
  const int lower_size = runs.lower_size;
  const double within = runs.within;
  if (lower_size == 0 || !(within > 0.0)) return layers;
  layers.gap = runs.upper_mean - runs.lower_mean;
  if (!(layers.gap > kMinLayerGapDeviations * deviation &&
        layers.gap < kMaxLayerGapDeviations * deviation)) {
    return layers;
  }
  if (!(layers.gap > kMinLayerSeparation * std::sqrt(within / found))) return layers;
  const double threshold = 0.5 * (sorted[lower_size - 1] + sorted[lower_size]);
  if (!(energy::FootprintDifference(local, heights, layers.normal, origin, threshold) <
        kMaxLayerFootprintDifference)) {
    return layers;
  }
  double median[2];
  RobustSpread(sorted, 0, lower_size, &median[0], &layers.spread[0]);
  RobustSpread(sorted, lower_size, found, &median[1], &layers.spread[1]);
  layers.height[0](0) = median[0];
  layers.height[1](0) = median[1];
  ReadCurvature(local, heights, threshold, across[found - 1].first, &layers);
  if (!layers.curved) FitInputLayers(inputs, across, found, deviation, &layers);
  layers.found = true;
  return layers;
}

// The height along layers.normal by which the output o (input p) moves onto the layer nearer
// to p, where o lies between the two layers; false where it does not.
bool MoveOntoLayer(const Layers& layers, const energy::Point3& o, const energy::Point3& p,
                   double* move) {
  const double level[2] = {layers.HeightAt(0, o), layers.HeightAt(1, o)};
  const double gap = layers.curved ? level[1] - level[0] : layers.gap;
  if (layers.curved && !(gap > kMinCurvedLayerGapShare * layers.gap)) return false;
  const double height = layers.normal.dot(o - layers.origin);
  const double off[2] = {level[0] - height, level[1] - height};
  const int nearer = std::abs(off[0]) < std::abs(off[1]) ? 0 : 1;
  const double margin =
      std::max(kBetweenLayerSpreads * layers.spread[nearer], kBetweenLayerGapShare * gap);
  if (!(std::abs(off[nearer]) > margin)) return false;
  const double input_height = layers.normal.dot(p - layers.origin);
  const int side =
      std::abs(input_height - level[0]) < std::abs(input_height - level[1]) ? 0 : 1;
  *move = off[side];
  return true;
}

// The centres (of `centres`, each with its squared reach) whose reach holds one of `points`.
std::vector<int> CentresReaching(const energy::PointList& centres,
                                 const std::vector<double>& reach,
                                 const energy::PointList& points, int num_threads) {
  std::vector<uint8_t> reaches(centres.size(), 0);
  const energy::NearestNeighbors search(points);
  search.ForEachWithin(static_cast<int>(centres.size()), num_threads,
                       [&](int c) { return centres[c]; }, [&](int c) { return reach[c]; },
                       [&](int c, const std::vector<int>& within) {
                         reaches[c] = !within.empty();
                       });
  std::vector<int> reaching;
  for (size_t c = 0; c < centres.size(); ++c) {
    if (reaches[c]) reaching.push_back(static_cast<int>(c));
  }
  return reaching;
}

}  // namespace

energy::PointList MoveBetweenLayerPointsOntoLayers(const energy::PointList& inputs,
                                                   const energy::PointList& outputs,
                                                   const energy::PointList& normals,
                                                   const std::vector<uint8_t>& movable,
                                                   bool move_between, int num_threads,
                                                   int* moved) {
  if (moved) *moved = 0;
  energy::PointList result = outputs;
  const std::vector<int> anchors = MovableRowsWithNormal(movable, normals);
  const int count = static_cast<int>(anchors.size());
  if (count < kLayerNeighbors) return result;
  // The layers around every kLayerCentreStride-th anchor.
  const int num_centres = (count + kLayerCentreStride - 1) / kLayerCentreStride;
  // Each centre's layer normal from its kLayerNeighbors nearest anchors, and the reach within
  // which its layers are read, sqrt(kLayerReachSquared) times the farthest of them: read on
  // the first pass and kept (the normals do not move, and the moves are short).
  std::vector<Eigen::Vector3d> normal(num_centres);
  std::vector<double> reach(num_centres);
  energy::PointList anchor_points(count), centre_points(num_centres);
  std::vector<Layers> layers(num_centres);
  double last_deviation = 0.0;
  energy::PointList last_moves;  // where the last pass's moved outputs were and are
  for (int pass = 0; pass < kBetweenLayerPasses; ++pass) {
    const energy::PointList before = result;  // this pass reads its layers from these
    const double deviation = OffsetDeviation(inputs, before, normals, anchors);
    if (!(deviation > 0.0)) break;
    for (int r = 0; r < count; ++r) anchor_points[r] = before[anchors[r]];
    for (int c = 0; c < num_centres; ++c) {
      centre_points[c] = anchor_points[c * kLayerCentreStride];
    }
    const energy::NearestNeighbors search(anchor_points);
    if (pass == 0) {
      search.ForEach(num_centres, kLayerNeighbors, num_threads,
                     [&](int c) { return centre_points[c]; },
                     [&](int c, const int* nearest, const double* squared_distances, int found) {
                       thread_local std::vector<int> neighbors;
                       neighbors.resize(found);
                       for (int b = 0; b < found; ++b) neighbors[b] = anchors[nearest[b]];
                       normal[c] = LayerNormal(normals, neighbors.data(), found);
                       reach[c] = kLayerReachSquared * squared_distances[found - 1];
                     });
    }
    // A later pass reads again only the centres whose reach held or holds an output the last
    // pass moved, where the deviation stayed: the others would read the same outputs. Where
    // the last pass moved more outputs than there are centres, it reads them all.
    std::vector<int> read(num_centres);
    std::iota(read.begin(), read.end(), 0);
    if (pass > 0 && deviation == last_deviation &&
        last_moves.size() < 2 * static_cast<size_t>(num_centres)) {
      read = CentresReaching(centre_points, reach, last_moves, num_threads);
    }
    search.ForEachWithin(static_cast<int>(read.size()), num_threads,
                         [&](int r) { return centre_points[read[r]]; },
                         [&](int r) { return reach[read[r]]; },
                         [&](int r, const std::vector<int>& within) {
                           thread_local std::vector<int> candidates;
                           candidates.resize(within.size());
                           for (size_t b = 0; b < within.size(); ++b) {
                             candidates[b] = anchors[within[b]];
                           }
                           const int c = read[r];
                           layers[c] = ReadLayers(inputs, before, candidates, normal[c],
                                                  centre_points[c], deviation);
                         });
    SetLayerCorrections(read, deviation, &layers);
    // Below the read ratio, the points between layers clearly apart, where enough centres
    // read such layers (between_layers.h).
    const int clear_centres = static_cast<int>(std::count_if(
        layers.begin(), layers.end(), [&](const Layers& l) { return l.ClearlyApart(deviation); }));
    const bool move_clear = clear_centres >= kMinClearLayerShare * num_centres;
    // Each anchor against the layers of its nearest centre, all read before any move.
    const energy::NearestNeighbors centre_search(centre_points);
    centre_search.ForEach(count, 1, num_threads, [&](int r) { return anchor_points[r]; },
                          [&](int r, const int* nearest, const double*, int) {
                            const Layers& around = layers[nearest[0]];
                            const int i = anchors[r];
                            if (!around.found) return;
                            double move = 0.0;
                            const bool may_move =
                                move_between || (move_clear && around.ClearlyApart(deviation));
                            if (!(may_move && MoveOntoLayer(around, before[i], inputs[i], &move))) {
                              move = around.Correction(before[i]);
                            }
                            result[i] = before[i] + move * around.normal;
                          });
    if (result == before) break;  // the next pass would read the same layers
    last_deviation = deviation;
    last_moves.clear();
    for (int r = 0; r < count; ++r) {
      const int i = anchors[r];
      if (result[i] == before[i]) continue;
      last_moves.push_back(before[i]);
      last_moves.push_back(result[i]);
    }
  }
  if (moved) {
    for (size_t i = 0; i < outputs.size(); ++i) *moved += result[i] != outputs[i];
  }
  return result;
}

}  // namespace lpd::solvers

// lpd: the input's mean offset from the output, fed back (twicing: Tukey, "Exploratory Data
// Analysis", 1977: smooth the residuals and add them back).
//
// The output of a wide neighbourhood lies inside curved parts: a plane fitted over a curved
// patch and smoothed with its neighbours sits below it by about the patch's sagitta, and
// the sphere fitted to those planes keeps part of it (docs/method.md, "Where the error is
// at 10K 3%"). The noise has mean zero, so the input points' mean offset from their outputs
// measures that bias. Each output point o_i with normal n_i moves along n_i by
//   m_i tau_i^2 / (tau_i^2 + v_i),
// m_i the mean of n_j.(p_j - o_j) (signed to agree with n_i) over its kFeedbackNeighbors
// nearest output points whose normals lie within kFeedbackMaxAngleDegrees of its own (the
// other face of an edge does not count), v_i the squared standard error of that mean, and
// tau_i^2 = mean over the same nearest points j of max(0, m_j^2 - v_j), the local spread of
// the bias: the posterior mean of the bias (empirical Bayes), which moves a point by little
// where the means around it are no larger than their errors.
//
// It needs the neighbourhood k to be as wide as the noise asks: where the probe reads sigma
// above kCalibratedReadRatio spacings it reads low (neighborhood_size.h), k is narrower, the
// output follows the noise over these neighbours (on the bunny at 50K and 3% their mean
// noise is 3x what independent noise would leave), and the feedback returns that noise; the
// caller applies it only below that reading (docs/method.md, "The mean offset fed back").
#ifndef LPD_SOLVERS_OFFSET_FEEDBACK_H_
#define LPD_SOLVERS_OFFSET_FEEDBACK_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

constexpr int kFeedbackNeighbors = 120;
constexpr double kFeedbackMaxAngleDegrees = 20.0;
// The default cap on the kept neighbour lists (120 ints a point: 64 MiB holds 139,810
// points), which spare the second pass its search.
constexpr size_t kMaxKeptNeighborBytes = size_t{64} << 20;

// `outputs` (the projections of `inputs`, same order, with unit or zero `normals`) after the
// feedback above. Only points with movable[i] and a nonzero normal take part (outliers are
// left out). The first pass's neighbour lists are kept for the second where they take at
// most `max_kept_neighbor_bytes`, and searched again otherwise; the same result either way,
// and for any thread count.
energy::PointList FeedBackMeanOffsets(const energy::PointList& inputs,
                                      const energy::PointList& outputs,
                                      const energy::PointList& normals,
                                      const std::vector<uint8_t>& movable, int num_threads,
                                      size_t max_kept_neighbor_bytes = kMaxKeptNeighborBytes);

// In a run on a subsample (subsample_extension.h), the feedback the solved points took
// (`fed_back` - `solved`, along `solved_normals`) carried to the other points `outputs` (with
// `normals`, same frame): each movable one moves along its normal by the shift of its nearest
// movable solved point, as that shift projects on it, where their normals lie within
// kFeedbackMaxAngleDegrees. The shifts vary over kFeedbackNeighbors solved points, so the
// nearest one stands for its neighbourhood; the search is one neighbour per point where
// feeding the whole output back would be kFeedbackNeighbors.
energy::PointList CarryFeedback(const energy::PointList& solved,
                                const energy::PointList& fed_back,
                                const energy::PointList& solved_normals,
                                const std::vector<uint8_t>& solved_movable,
                                const energy::PointList& outputs,
                                const energy::PointList& normals,
                                const std::vector<uint8_t>& movable, int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_OFFSET_FEEDBACK_H_

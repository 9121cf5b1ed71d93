// lpd: the final denoising of Sec. 3.4: indicators, projection onto t_i, outlier removal.
//
//   outlier score of i = 1 - (1 / (k + 1)) sum_{j in N(i) u {i}} support_j l(h_j, q_i), with
//                        l(h, q) = (mu_l / (mu_l + (h^T q)^2))^2 the fitting line process
//                        (Eq. 6) plane h_j gives q_i, and support_j = mean_a l_ja the share of
//                        its own neighbourhood h_j explains; i is an outlier if the score >=
//                        outlier_fraction (paper preset 0.9, default 0.65). For j = i and every
//                        j with i in N(j), l(h_j, q_i) is the l_ji of Eq. (5): Sec. 4.3 and
//                        Fig. 6 read outliers off the points the neighbouring fits reject.
//                        Asking every neighbour j (an outlier off the surface is rarely among
//                        its neighbours' nearest) and weighting by support (a plane fitted to
//                        scattered outliers passes through a few of them and explains little)
//                        is ours: on cad_part with 20% uniform outliers, recall 0.23 with the
//                        plain 90% vote over l_ji, 0.91 at precision 0.99 this way
//                        (docs/method.md).
//                        Each plane reads residuals against its region's noise (ours too): with
//                        s_j the robust residual scale of h_j's own neighbourhood and sigma_j
//                        the median of s_j' over j' in N(j) u {j}, h_j's l and support use
//                        mu_l (sigma_j / median_j sigma_j)^2, the ratio capped at
//                        local_noise_ratio, where it is at least 1.5 and h_j's neighbourhood
//                        is about as dense as the surface's: a scan's noisier bands and
//                        overlapping layers are kept, a point off the surface is still far
//                        from every plane.
//   feature score of i = fraction of pairs (i, j) in M with m_ij < feature_line_threshold;
//                        i is near a feature if the score > feature_fraction (paper: 70%, 0.5;
//                        default 30%: with data-scaled weights the planes on either side of
//                        an edge stay sharp, so a point at the edge has about half its pairs
//                        cut, not 70%; box / cad_part precision 0.49 / 0.66 at recall 0.73 /
//                        0.59, against 0.62 / 0.63 at 0.23 / 0.06 for the paper preset)
//   p_i' = p_i - n_i (t_i^T q_i) / |n_i|^2,  n_i = first three coordinates of t_i
#ifndef LPD_SOLVERS_FINAL_DENOISING_H_
#define LPD_SOLVERS_FINAL_DENOISING_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/feature_snapping.h"
#include "solvers/isolated_points.h"

namespace lpd::solvers {

// Where each point goes: onto its plane t_i (Sec. 3.4) or onto the local algebraic sphere
// fitted to its neighbours' planes (sphere_projection.h).
enum class Projection { kPlane, kSphere };
const char* ProjectionName(Projection projection);  // "plane", "sphere"
bool ParseProjection(const std::string& name, Projection* projection);

struct FinalDenoisingOptions {
  Projection projection = Projection::kSphere;
  // A point moves to the mean of its projections onto the surfaces of itself and its nearest
  // neighbours, this many in all at least, at most k + 1 (paper: 1, its own plane).
  int blended_surfaces = 30;
  // ... or this share of the cloud's distinct points when that is more (paper: 0): a denser
  // cloud blends the surfaces of a patch of the same share of the shape (docs/method.md,
  // "The count grows with the cloud"; 0.3% breaks the convergence bound on JOINT 0.03).
  double blended_share = 0.001;
  // Settle each point on the blend: project it once more from where the blend put it, along
  // the normal (ProjectOntoSettledBlend; paper: off, one surface). Lowers the mean distance
  // on all seven rows of Table 1 (JOINT 0.03 4.31 -> 4.12e-3; docs/method.md).
  bool settled_blend = true;
  // Rounds of Lloyd's relaxation of the output points within their tangent planes, each
  // point then following its own surface (even_spacing.h; 0: off; paper: off). 10 rounds
  // lower CD and P2M on 77 of the learned denoisers' 78 benchmark cells (docs/method.md).
  int even_spacing_rounds = 10;
  // Move each output point by its neighbourhood's mean input offset, shrunk
  // (offset_feedback.h; paper: off). Applied where the probe read sigma / spacing at most
  // kCalibratedReadRatio.
  bool offset_feedback = true;
  // Move each output point of a region whose input offsets read as two merged sides to the
  // side its offset's sign picks (merged_sides.h; paper: off).
  bool separate_merged_sides = true;
  // Pairs of rounds (lambda, mu) smoothing the output's heights along its normals over its
  // nearest outputs, after the steps above (height_smoothing.h; 0: off; paper: off).
  int height_smoothing_pairs = 2;
  // Refit each output's height at the widest scale its neighbours agree on, after the steps
  // above, where the probe reads the noise narrower than the spacing (adaptive_heights.h;
  // paper: off).
  bool adaptive_heights = true;
  double outlier_fraction = 0.65;        // outlier score that makes an outlier, in (0, 1]
  // Largest factor by which a plane's region noise may widen its line process (above; 1:
  // the global mu_l only, as in the paper).
  double local_noise_ratio = 3.0;
  double feature_line_threshold = 0.5;   // m_ij below this votes "feature"
  double feature_fraction = 0.3;         // share of votes above which i is a feature point
  bool remove_outliers = true;           // drop outliers from the output
  // Removal is skipped (and reported) when more than this share of all points is flagged:
  // then mu_l is below the noise level and the indicator no longer separates outliers.
  double max_removed_fraction = 0.5;
  // Denoising passes at most: when a pass removes more than rerun_removed_fraction of its
  // points, the next pass starts over on the points it kept (their input coordinates), so
  // that neither the removed outliers nor their planes shape the rest (paper: 1 pass).
  int outlier_passes = 2;
  double rerun_removed_fraction = 0.05;
  // After the passes, kept points far from every other kept point are outliers too
  // (isolated_points.h; paper preset: off).
  IsolationOptions isolation;
  // The optional feature improvement of Sec. 3.4 (off by default, as in the paper's runs).
  bool snap_features = false;
  FeatureSnappingOptions snapping;

  // These options for a cloud of `points` points: blended_surfaces the larger of the two
  // counts above, blended_share 0 (so that a part of the cloud, a tile or a later pass,
  // blends as the whole cloud does).
  FinalDenoisingOptions ForCloudOf(size_t points) const;
  bool IsValid(std::string* error) const;
};

struct PointIndicators {
  std::vector<double> outlier_score;  // in [0, 1]
  std::vector<double> feature_score;  // in [0, 1]
  std::vector<uint8_t> is_outlier;
  std::vector<uint8_t> is_feature;
};

// What each plane h_j brings to the outlier scores (above): the selectivity mu_j of the line
// process it gives a point, and its support, the mean line process over its own
// neighbourhood at mu_j (where h_j is not widened: mu_l and the optimizer's l_ja).
struct PlaneEvidence {
  std::vector<double> mu;
  std::vector<double> support;
};
PlaneEvidence ComputePlaneEvidence(const energy::Problem& problem, const energy::Variables& v,
                                   double mu_l, const FinalDenoisingOptions& options,
                                   int num_threads = 1);

// The outlier score of the point p (normalized frame) asked of the planes h_j of `planes`
// (above; `count` of them).
double OutlierScore(const energy::Point3& p, const int* planes, int count,
                    const energy::Variables& v, const PlaneEvidence& evidence);

// `mu_l`: the selectivity the fitting line processes were computed with. The same result
// for any `num_threads`.
PointIndicators ComputeIndicators(const energy::Problem& problem, const energy::Variables& v,
                                  double mu_l, const FinalDenoisingOptions& options,
                                  int num_threads = 1);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_FINAL_DENOISING_H_

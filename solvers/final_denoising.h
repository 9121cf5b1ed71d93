// lpd: the final denoising of Sec. 3.4: indicators, projection onto t_i, outlier removal.
//
//   outlier score of i = fraction of the line processes with q_i as data point (l_ii, and
//                        l_ji for every j with i in N(j)) below outlier_line_threshold;
//                        i is an outlier if the score >= outlier_fraction (paper: 90%, 0.5).
//                        Sec. 3.4 speaks of "l_ij, j in N(i)"; read as l_ij scored on i's
//                        own plane h_i, an isolated outlier whose plane follows the nearby
//                        surface is never flagged, so we use the reading of Sec. 4.3 and
//                        Fig. 6: the points the neighbouring fits reject.
//   feature score of i = fraction of pairs (i, j) in M with m_ij < feature_line_threshold;
//                        i is near a feature if the score > feature_fraction (paper: 70%, 0.5)
//   p_i' = p_i - n_i (t_i^T q_i) / |n_i|^2,  n_i = first three coordinates of t_i
#ifndef LPD_SOLVERS_FINAL_DENOISING_H_
#define LPD_SOLVERS_FINAL_DENOISING_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/feature_snapping.h"

namespace lpd::solvers {

struct FinalDenoisingOptions {
  double outlier_line_threshold = 0.5;   // l_ij below this votes "outlier"
  double outlier_fraction = 0.9;         // share of votes that makes an outlier, in (0, 1]
  double feature_line_threshold = 0.5;   // m_ij below this votes "feature"
  double feature_fraction = 0.7;         // share of votes above which i is a feature point
  bool remove_outliers = true;           // drop outliers from the output
  // Removal is skipped (and reported) when more than this share of all points is flagged:
  // then mu_l is below the noise level and the indicator no longer separates outliers.
  double max_removed_fraction = 0.5;
  // The optional feature improvement of Sec. 3.4 (off by default, as in the paper's runs).
  bool snap_features = false;
  FeatureSnappingOptions snapping;

  bool IsValid(std::string* error) const;
};

struct PointIndicators {
  std::vector<double> outlier_score;  // in [0, 1]
  std::vector<double> feature_score;  // in [0, 1]
  std::vector<uint8_t> is_outlier;
  std::vector<uint8_t> is_feature;
};

PointIndicators ComputeIndicators(const energy::Problem& problem, const energy::Variables& v,
                                  const FinalDenoisingOptions& options);

// p_i projected onto the plane t_i, in the input frame, and the unit normal n_i / |n_i|.
// Where |n_i| vanishes (no plane was found) p_i is kept and the normal is zero.
void ProjectOntoTangentPlanes(const energy::Problem& problem, const energy::Variables& v,
                              energy::PointList* points, energy::PointList* normals);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_FINAL_DENOISING_H_

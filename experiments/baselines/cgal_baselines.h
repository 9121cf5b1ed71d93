// lpd: the classical baselines of the paper's comparisons, from CGAL's
// Point_set_processing_3 (the implementations the paper used, [AGJ*22]).
//
//   bilateral  bilateral smoothing of Huang et al. 2013 ([HWG*13]): needs oriented normals,
//              estimated here by PCA or jet fitting over k neighbours and oriented by a
//              minimum spanning tree (Hoppe et al. 1992); then `iterations` passes, each
//              moving points and updating normals (the paper: 3 passes)
//   jet        jet smoothing (Cazals and Pouget 2005): each point projected onto the
//              degree-2 jet fitted to its k neighbours, `iterations` times
//   wlop       weighted locally optimal projection (Huang et al. 2009): resamples the input
//              to `select_percentage` percent of its points, regularly spread
//
// All run sequentially (Debian's CGAL is built without TBB). Inputs are never modified.
// Each throws std::invalid_argument on invalid options and std::runtime_error on failure.
#ifndef LPD_EXPERIMENTS_BASELINES_CGAL_BASELINES_H_
#define LPD_EXPERIMENTS_BASELINES_CGAL_BASELINES_H_

#include <string>

#include "energy/point3.h"

namespace lpd::experiments {

enum class NormalEstimator { kPca, kJet };
std::string ToString(NormalEstimator estimator);                // "pca", "jet"
NormalEstimator ParseNormalEstimator(const std::string& name);  // throws on other names

struct BilateralOptions {
  int k = 60;                          // neighbours of the smoothing and of the normals
  double sharpness_angle_deg = 25.0;   // CGAL's default; the paper tuned 10-15 on FANDISK
  int iterations = 3;
  NormalEstimator normals = NormalEstimator::kPca;
};

struct JetOptions {
  int k = 32;
  int iterations = 1;
};

struct WlopOptions {
  double select_percentage = 20.0;     // output size, percent of the input's
  double radius_spacings = 8.0;        // neighbourhood radius in average spacings (CGAL: 8)
  int iterations = 35;                 // CGAL's default
};

energy::PointList BilateralSmooth(const energy::PointList& points,
                                  const BilateralOptions& options);
energy::PointList JetSmooth(const energy::PointList& points, const JetOptions& options);
energy::PointList WlopResample(const energy::PointList& points, const WlopOptions& options);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_BASELINES_CGAL_BASELINES_H_

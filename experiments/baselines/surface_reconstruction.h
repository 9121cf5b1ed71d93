// lpd: the paper's two "neutral" interpolating reconstructions (Sec. 4.1), from CGAL, used to
// show the flaws of denoised point sets (Figs. 1, 12-14).
//
//   advancing_front  Advancing Front surface reconstruction (Cohen-Steiner and Da 2004,
//                    [DCS22]): a Delaunay-based greedy surface through the points themselves
//   scale_space      Scale Space reconstruction (Digne et al. 2011, [vL22]): the points are
//                    smoothed `scale_iterations` times by jet fitting, meshed by advancing
//                    front, and the mesh's connectivity is put back on the original points,
//                    so the surface interpolates them (robust to remaining noise)
//
// The mesh's vertices are the input points, in input order (some may be unused).
#ifndef LPD_EXPERIMENTS_BASELINES_SURFACE_RECONSTRUCTION_H_
#define LPD_EXPERIMENTS_BASELINES_SURFACE_RECONSTRUCTION_H_

#include <string>

#include "energy/point3.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {

enum class Reconstruction { kAdvancingFront, kScaleSpace };
std::string ToString(Reconstruction method);                 // "advancing_front", "scale_space"
Reconstruction ParseReconstruction(const std::string& name);  // throws on other names

struct ReconstructionOptions {
  Reconstruction method = Reconstruction::kAdvancingFront;
  int scale_iterations = 4;  // scale_space: smoothing passes (CGAL's example uses 4)
};

// Throws std::invalid_argument on fewer than 4 points, collinear or coincident points or bad
// options, std::runtime_error if no triangle could be made.
TriangleMesh ReconstructSurface(const energy::PointList& points,
                                const ReconstructionOptions& options);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_BASELINES_SURFACE_RECONSTRUCTION_H_

// lpd: a run on a subsample of the input extended to every input point.
//
// On a cloud much denser than its noise, a neighbourhood wide enough to average the noise holds
// hundreds of points. Denoising a random subsample at a proportionally smaller k gives the
// same neighbourhoods at a fraction of the cost (thinning.h says when). Every point q
// then takes, from its k + 1 nearest subsample points j (k of the subsample's problem):
//   - its position and normal: q projected onto the blend (sphere_projection.h) of the
//     surfaces of its nearest subsample points, as many as a subsample point blends;
//   - its outlier score: that of final_denoising.h, asked of the planes h_j;
//   - its feature score: that of its nearest subsample point.
// A subsample point's k + 1 nearest subsample points are itself and N(i), so its position
// and its outlier score are its own.
#ifndef LPD_SOLVERS_SUBSAMPLE_EXTENSION_H_
#define LPD_SOLVERS_SUBSAMPLE_EXTENSION_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"
#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/final_denoising.h"
#include "solvers/sphere_projection.h"

namespace lpd::solvers {

// `count` of the indices 0 .. n - 1, chosen uniformly at random (seeded), in increasing order.
std::vector<int> ChooseSubsample(int n, int count, uint64_t seed);

// What the points `queries` (input frame) get from the subsample's `problem`, its final
// variables `v`, the local `surfaces` of its points (blended at `agreement_scale`, as in
// ProjectOntoBlendedSurfaces) and its `indicators` (problem order);
// `mu_l` as in ComputeIndicators. Outputs are in the order of `queries`,
// positions in the input frame.
void ExtendToPoints(const energy::Problem& problem, const energy::Variables& v,
                    const std::vector<LocalSurface>& surfaces, double agreement_scale,
                    const PointIndicators& indicators, double mu_l,
                    const FinalDenoisingOptions& options, const energy::PointList& queries,
                    int num_threads,
                    energy::PointList* projected, energy::PointList* normals,
                    PointIndicators* query_indicators);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SUBSAMPLE_EXTENSION_H_

// lpd: Poisson-disk samples of a surface by weighted sample elimination (Yuksel, "Sample
// Elimination for Generating Poisson Disk Sample Sets", Eurographics 2015), the sampling
// of the learned denoisers' benchmark (their clean sets come from Poisson-disk samples of
// each mesh, as Open3D's sample_points_poisson_disk draws them).
//
// From 5 count area-uniform samples, the sample with the most crowded neighbourhood is removed
// until `count` remain. Crowding is sum_j (1 - d_ij / (2 r_max))^8 over the samples j within
// 2 r_max, where r_max = sqrt(A / (2 sqrt(3) count)) is the disk radius of `count` samples
// packed hexagonally over the area A. Ties fall to the lower index: deterministic.
#ifndef LPD_EXPERIMENTS_SHAPES_POISSON_DISK_SAMPLING_H_
#define LPD_EXPERIMENTS_SHAPES_POISSON_DISK_SAMPLING_H_

#include <cstdint>

#include "experiments/shapes/procedural_shape.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {

// Keeps `count` of `dense` (in their order), a surface of area `area`. Throws
// std::invalid_argument unless 0 < count <= dense.points.size() and area > 0.
SurfaceSamples EliminateSamples(const SurfaceSamples& dense, int count, double area);

// `count` Poisson-disk samples: the same (count, seed) always gives the same samples.
SurfaceSamples PoissonDiskSample(const TriangleMesh& mesh, int count, uint64_t seed);
SurfaceSamples PoissonDiskSample(const ProceduralShape& shape, int count, uint64_t seed);

// The area of the mesh's triangles.
double SurfaceArea(const TriangleMesh& mesh);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_POISSON_DISK_SAMPLING_H_

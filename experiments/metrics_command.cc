// lpd metrics POINTS --mesh=MESH: exact distances from a point set to a clean mesh.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gflags/gflags.h>

#include "experiments/commands.h"
#include "experiments/denoise_flags.h"
#include "experiments/mesh_distance.h"
#include "experiments/point_cloud_io.h"

DEFINE_string(mesh, "", "ground-truth triangle mesh (.off, .obj, .ply)");

namespace lpd::experiments {

int RunMetricsCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() != 1) throw std::invalid_argument("metrics takes one POINTS file");
  if (FLAGS_mesh.empty()) throw std::invalid_argument("missing --mesh=MESH (the ground truth)");
  const energy::PointList points = ReadPoints(arguments[0]);
  const MeshDistance mesh(FLAGS_mesh);
  const std::vector<double> d = mesh.Distances(points, FLAGS_threads);
  double sum = 0.0, sum_squared = 0.0, max = 0.0;
  for (double x : d) {
    sum += x;
    sum_squared += x * x;
    max = std::max(max, x);
  }
  const double n = static_cast<double>(d.size());
  const double diagonal = mesh.BoundingBoxDiagonal();
  std::printf("points %zu, mesh triangles %d, mesh bounding-box diagonal %.6g\n", d.size(),
              mesh.num_triangles(), diagonal);
  std::printf("point-to-mesh distance: mean %.6e  rms %.6e  max %.6e\n", sum / n,
              std::sqrt(sum_squared / n), max);
  std::printf("divided by the diagonal: mean %.4e  rms %.4e  max %.4e\n", sum / n / diagonal,
              std::sqrt(sum_squared / n) / diagonal, max / diagonal);
  return 0;
}

}  // namespace lpd::experiments

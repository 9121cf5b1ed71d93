// lpd reconstruct INPUT -o MESH.off: the paper's neutral interpolating reconstruction of a
// (denoised) point set, for renderings like Figs. 1 and 12-14.
#include <cstdio>
#include <stdexcept>

#include <gflags/gflags.h>

#include "energy/wall_clock.h"
#include "experiments/baselines/surface_reconstruction.h"
#include "cli/commands.h"
#include "io/atomic_output_file.h"
#include "io/point_cloud_io.h"

DECLARE_string(output);
DECLARE_bool(overwrite);

DEFINE_string(reconstruction, "advancing_front",
              "advancing_front (Delaunay-based, through the points; for low noise and CAD "
              "models) or scale_space (meshed at a smoothed scale, then put back on the "
              "points; for remaining noise)");
DEFINE_int32(scale_iterations, 4, "scale_space: jet-smoothing passes before meshing");

namespace lpd::cli {

int RunReconstructCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() != 1) throw std::invalid_argument("give exactly one INPUT point file");
  if (FLAGS_output.empty()) throw std::invalid_argument("missing output file: give -o MESH.off");
  if (FLAGS_output == arguments[0]) {
    throw std::invalid_argument("OUTPUT must differ from INPUT (refusing to overwrite input)");
  }
  experiments::CheckTriangleMeshPath(FLAGS_output);
  io::RefuseExistingOutput(FLAGS_output, FLAGS_overwrite);
  experiments::ReconstructionOptions options;
  options.method = experiments::ParseReconstruction(FLAGS_reconstruction);
  options.scale_iterations = FLAGS_scale_iterations;
  const io::PointCloud cloud = io::ReadPointCloud(arguments[0]);
  const Clock::time_point start = Clock::now();
  const experiments::TriangleMesh mesh = experiments::ReconstructSurface(cloud.points, options);
  const double seconds =
      SecondsSince(start);
  experiments::WriteTriangleMesh(FLAGS_output, mesh, FLAGS_overwrite);
  std::printf("%s: %zu points, %zu triangles, %.2f s\nwrote %s\n",
              ToString(options.method).c_str(), mesh.vertices.size(), mesh.triangles.size(),
              seconds, FLAGS_output.c_str());
  return 0;
}

}  // namespace lpd::cli

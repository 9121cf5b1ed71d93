// lpd noise [INPUT] -o NOISY.ply [--clean_output=CLEAN.ply]: a labelled noisy point set from a procedural shape, a mesh
// or a clean point file, for experiments and for `lpd metrics --input`.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <gflags/gflags.h>

#include "cli/commands.h"
#include "io/atomic_output_file.h"
#include "io/point_cloud_io.h"
#include "experiments/shapes/noise.h"
#include "experiments/shapes/poisson_disk_sampling.h"
#include "experiments/shapes/shape_catalog.h"
#include "experiments/shapes/triangle_mesh.h"

DECLARE_string(output);
DECLARE_string(output_format);
DECLARE_bool(overwrite);
DECLARE_uint64(seed);

DEFINE_string(shape, "", "sample this procedural shape: NAME[:key=value,...], e.g. cone:apex_angle=30");
DEFINE_string(mesh, "", "sample this triangle mesh (.off, .obj, .ply, .stl) uniformly by area");
DEFINE_int32(points, 25000, "number of clean samples drawn from --shape or --mesh");
DEFINE_double(sigma, 0.01, "noise standard deviation as a fraction of --noise_scale");
DEFINE_string(noise_model, "gaussian",
              "gaussian (isotropic), normal (along the clean normal only) or varying "
              "(isotropic, 0.5 to 1.5 sigma along the longest axis)");
DEFINE_string(noise_scale, "bbox_diagonal",
              "length that sigma is a fraction of: bbox_diagonal, fps_diameter (the paper's "
              "farthest-point-sampling diameter) or unit_sphere_radius (the learned "
              "denoisers' benchmark)");
DEFINE_string(sampling, "uniform",
              "how --shape or --mesh is sampled: uniform (area-uniform random) or "
              "poisson_disk (the learned denoisers' benchmark)");
DEFINE_string(clean_output, "",
              "also write the clean samples here (for `lpd metrics --clean`)");
DEFINE_int32(outlier_count, 0, "number of uniform outliers added in the enlarged bounding box");
DEFINE_double(outlier_ratio, 0.0, "more outliers, as a fraction of the clean point count");
DEFINE_double(outlier_margin, 0.05,
              "the outlier box is the bounding box enlarged by this fraction of its diagonal");

namespace lpd::cli {

int RunNoiseCommand(const std::vector<std::string>& arguments) {
  const int sources = !FLAGS_shape.empty() + !FLAGS_mesh.empty() + !arguments.empty();
  if (sources != 1 || arguments.size() > 1) {
    throw std::invalid_argument("give exactly one source: --shape=NAME, --mesh=FILE or INPUT");
  }
  if (FLAGS_output.empty()) throw std::invalid_argument("missing output file: give -o OUTPUT");
  if (!arguments.empty() && FLAGS_output == arguments[0]) {
    throw std::invalid_argument("OUTPUT must differ from INPUT (refusing to overwrite input)");
  }
  io::OutputFormat(FLAGS_output, FLAGS_output_format);  // refused before any sampling
  if (FLAGS_points < 1) throw std::invalid_argument("points must be >= 1");
  if (FLAGS_sampling != "uniform" && FLAGS_sampling != "poisson_disk") {
    throw std::invalid_argument("unknown --sampling '" + FLAGS_sampling +
                                "' (expected uniform or poisson_disk)");
  }
  const bool poisson_disk = FLAGS_sampling == "poisson_disk";
  if (poisson_disk && !arguments.empty()) {
    throw std::invalid_argument("--sampling is for --shape or --mesh, not a point file");
  }
  if (!FLAGS_clean_output.empty() &&
      (FLAGS_clean_output == FLAGS_output ||
       (!arguments.empty() && FLAGS_clean_output == arguments[0]))) {
    throw std::invalid_argument("--clean_output must differ from INPUT and OUTPUT");
  }
  experiments::NoiseOptions options;
  options.model = experiments::ParseNoiseModel(FLAGS_noise_model);
  options.scale = experiments::ParseNoiseScale(FLAGS_noise_scale);
  options.sigma = FLAGS_sigma;
  options.outlier_count = FLAGS_outlier_count;
  options.outlier_ratio = FLAGS_outlier_ratio;
  options.outlier_margin = FLAGS_outlier_margin;
  options.seed = FLAGS_seed + 1;  // the clean samples use FLAGS_seed itself
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);

  std::string source;
  experiments::SurfaceSamples clean;
  std::unique_ptr<experiments::ProceduralShape> shape;
  if (!FLAGS_shape.empty()) {
    shape = std::make_unique<experiments::ProceduralShape>(experiments::MakeShape(experiments::ParseShapeSpec(FLAGS_shape)));
    clean = poisson_disk ? experiments::PoissonDiskSample(*shape, FLAGS_points, FLAGS_seed)
                         : shape->Sample(FLAGS_points, FLAGS_seed);
    source = "shape " + shape->description();
  } else if (!FLAGS_mesh.empty()) {
    const experiments::TriangleMesh mesh = experiments::ReadTriangleMesh(FLAGS_mesh);
    clean = poisson_disk ? experiments::PoissonDiskSample(mesh, FLAGS_points, FLAGS_seed)
                         : experiments::SampleTriangleMesh(mesh, FLAGS_points, FLAGS_seed);
    source = "mesh " + FLAGS_mesh;
  } else {
    io::PointCloud input = io::ReadPointCloud(arguments[0]);
    clean.points = std::move(input.points);
    clean.normals = std::move(input.normals);
    source = "points " + arguments[0];
  }
  const experiments::NoisyPointSet noisy = experiments::ApplyNoise(clean.points, clean.normals, options);

  io::PointCloud cloud;
  cloud.points = noisy.points;
  const size_t num_clean = clean.points.size();
  if (!clean.normals.empty()) {
    cloud.normals = clean.normals;
    cloud.normals.resize(noisy.points.size(), energy::Point3::Zero());  // outliers: none
  }
  cloud.attributes.push_back(
      {"is_outlier", "float", std::vector<double>(noisy.is_outlier.begin(), noisy.is_outlier.end())});
  if (shape && shape->has_features()) {
    std::vector<double> distance(noisy.points.size(), -1.0);  // -1: outlier, no clean point
    for (size_t i = 0; i < num_clean; ++i) {
      distance[i] = static_cast<float>(shape->DistanceToFeatures(clean.points[i]));
    }
    cloud.attributes.push_back({"feature_distance", "float", distance});
  }
  std::ostringstream description;
  description << "source " << source << ", " << num_clean << " clean points ("
              << FLAGS_sampling << "), seed " << FLAGS_seed;
  cloud.comments.push_back(description.str());
  description.str("");
  description << "noise " << ToString(options.model) << " sigma " << options.sigma << " of "
              << ToString(options.scale) << " " << noisy.scale_length << " = "
              << noisy.sigma_absolute << ", outliers " << noisy.points.size() - num_clean;
  cloud.comments.push_back(description.str());
  if (!FLAGS_clean_output.empty()) {
    io::PointCloud clean_cloud;
    clean_cloud.points = clean.points;
    clean_cloud.normals = clean.normals;
    clean_cloud.comments.push_back(cloud.comments.front());
    io::WritePointCloud(FLAGS_clean_output, clean_cloud, FLAGS_overwrite);
  }
  io::WritePointCloud(FLAGS_output, cloud, FLAGS_overwrite, FLAGS_output_format);
  // The summary on stdout, or on stderr when stdout carries the cloud ("-o -").
  std::FILE* report = FLAGS_output == io::kStandardStream ? stderr : stdout;
  for (const std::string& line : cloud.comments) std::fprintf(report, "%s\n", line.c_str());
  std::fprintf(report, "wrote %s (%zu points)\n", FLAGS_output.c_str(), cloud.points.size());
  return 0;
}

}  // namespace lpd::cli

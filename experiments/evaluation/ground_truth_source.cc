#include "experiments/evaluation/ground_truth_source.h"

#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "io/point_cloud_io.h"
#include "experiments/shapes/shape_catalog.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {
namespace {

// True if the PLY header declares a non-empty "face" element.
bool PlyHasFaces(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open file (missing or unreadable)");
  std::string line;
  while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
    std::istringstream tokens(line);
    std::string keyword, name;
    long count = 0;
    if (tokens >> keyword >> name >> count && keyword == "element" && name == "face") {
      return count > 0;
    }
  }
  return false;
}

}  // namespace

GroundTruth LoadGroundTruth(const std::string& source, int num_samples, uint64_t seed) {
  if (source.rfind("shape:", 0) == 0) {
    auto shape = std::make_shared<const ProceduralShape>(
        MakeShape(ParseShapeSpec(source.substr(6))));
    return ShapeGroundTruth(shape, num_samples, seed);
  }
  const std::string extension = io::FileExtension(source);
  if (extension == "off" || extension == "obj" || extension == "stl" ||
      (extension == "ply" && PlyHasFaces(source))) {
    return MeshGroundTruth(ReadTriangleMesh(source), source, num_samples, seed);
  }
  return PointSetGroundTruth(io::ReadPoints(source), source + " (clean point set)");
}

}  // namespace lpd::experiments

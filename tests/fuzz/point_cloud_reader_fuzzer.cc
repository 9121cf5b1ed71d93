// Fuzz target: the point-cloud reader of one format (LPD_FUZZ_FORMAT: "xyz", "ply", "off",
// "obj", "las" or "pcd") on arbitrary bytes. Refusing a file with std::runtime_error is the
// expected outcome; any other exception, a crash, a sanitizer report, a non-finite
// coordinate or attribute arrays of the wrong length is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/point_cloud_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const lpd::io::PointCloud cloud =
        lpd::io::ReadPointCloud(in, LPD_FUZZ_FORMAT, "fuzz-input");
    for (const auto& p : cloud.points) {
      if (!p.allFinite()) std::abort();
    }
    if (!cloud.normals.empty() && cloud.normals.size() != cloud.points.size()) std::abort();
    for (const auto& attribute : cloud.attributes) {
      if (attribute.values.size() != cloud.points.size()) std::abort();
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}

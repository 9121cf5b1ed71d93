// lpd: the output point cloud of a run: the kept points, denoised, with their normals, every
// attribute of the input (colours, intensities, classes, ... with their types) and lpd's own
// fields (outlier and feature flags and scores, the input index).
#ifndef LPD_CLI_OUTPUT_CLOUD_H_
#define LPD_CLI_OUTPUT_CLOUD_H_

#include <vector>

#include "io/point_cloud_io.h"
#include "solvers/denoise_point_set.h"

namespace lpd::cli {

// lpd's fields, in the order they are written.
const std::vector<const char*>& LpdFieldNames();

enum class OutputKind {
  kPly,   // the normals and lpd's fields beside the input's attributes (PLY, PCD)
  kText,  // the input's attributes only (XYZ columns)
  kLas,   // the input's fields, with class 7 (low noise, as PDAL marks outliers) on every
          // flagged point that is in the output (--outliers=mark)
};

// The kept points of `result` with `input` (the input cloud's attributes, one value per input
// point, and its LAS header). An input attribute named as one of lpd's fields is renamed
// input_NAME (input_input_NAME, ...) in a PLY, so that neither is lost.
io::PointCloud MakeOutputCloud(const solvers::DenoiseResult& result, const io::PointCloud& input,
                               OutputKind kind);

}  // namespace lpd::cli

#endif  // LPD_CLI_OUTPUT_CLOUD_H_

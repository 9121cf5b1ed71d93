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

// The kept points of `result` with `input_attributes` (one value per input point) and, when
// `with_lpd_fields` (PLY outputs), the normals and lpd's fields. An input attribute named as
// one of lpd's fields is renamed input_NAME (input_input_NAME, ...), so that neither is lost.
io::PointCloud MakeOutputCloud(const solvers::DenoiseResult& result,
                               const std::vector<io::PointAttribute>& input_attributes,
                               bool with_lpd_fields);

}  // namespace lpd::cli

#endif  // LPD_CLI_OUTPUT_CLOUD_H_

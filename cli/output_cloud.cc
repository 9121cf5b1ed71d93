#include "cli/output_cloud.h"

#include <algorithm>
#include <string>

namespace lpd::cli {
namespace {

bool IsTaken(const std::string& name, const std::vector<io::PointAttribute>& attributes) {
  const std::vector<const char*>& lpd = LpdFieldNames();
  return std::any_of(lpd.begin(), lpd.end(), [&](const char* field) { return name == field; }) ||
         std::any_of(attributes.begin(), attributes.end(),
                     [&](const io::PointAttribute& a) { return a.name == name; });
}

}  // namespace

const std::vector<const char*>& LpdFieldNames() {
  static const std::vector<const char*> names = {"outlier", "outlier_score", "feature",
                                                 "feature_score", "source_index"};
  return names;
}

io::PointCloud MakeOutputCloud(const solvers::DenoiseResult& result, const io::PointCloud& input,
                               OutputKind kind) {
  const bool with_lpd_fields = kind == OutputKind::kPly;
  std::vector<size_t> rows;
  for (size_t i = 0; i < result.projected.size(); ++i) {
    if (result.kept[i]) rows.push_back(i);
  }
  io::PointCloud cloud;
  cloud.float_coordinates = input.float_coordinates;
  for (size_t i : rows) cloud.points.push_back(result.projected[i]);
  for (const io::PointAttribute& attribute : input.attributes) {
    io::PointAttribute kept{attribute.name, attribute.type, {}};
    while (with_lpd_fields && IsTaken(kept.name, cloud.attributes)) {
      kept.name = "input_" + kept.name;
    }
    for (size_t i : rows) kept.values.push_back(attribute.values[i]);
    cloud.attributes.push_back(std::move(kept));
  }
  if (kind == OutputKind::kLas) {
    cloud.las = input.las;
    auto found = std::find_if(cloud.attributes.begin(), cloud.attributes.end(),
                              [](const io::PointAttribute& a) { return a.name == "classification"; });
    if (found == cloud.attributes.end()) {
      cloud.attributes.push_back({"classification", "uchar", std::vector<double>(rows.size(), 0)});
      found = cloud.attributes.end() - 1;
    }
    constexpr double kLowNoise = 7;  // ASPRS class 7
    for (size_t r = 0; r < rows.size(); ++r) {
      if (result.indicators.is_outlier[rows[r]]) found->values[r] = kLowNoise;
    }
  }
  if (!with_lpd_fields) return cloud;
  for (size_t i : rows) cloud.normals.push_back(result.normals[i]);
  const solvers::PointIndicators& indicators = result.indicators;
  // Scores as float, as earlier outputs had them.
  auto field = [&](const char* name, const char* type, auto value_of) {
    io::PointAttribute attribute{name, type, {}};
    for (size_t i : rows) attribute.values.push_back(value_of(i));
    cloud.attributes.push_back(std::move(attribute));
  };
  field("outlier", "float", [&](size_t i) { return indicators.is_outlier[i]; });
  field("outlier_score", "float",
        [&](size_t i) { return static_cast<float>(indicators.outlier_score[i]); });
  field("feature", "float", [&](size_t i) { return indicators.is_feature[i]; });
  field("feature_score", "float",
        [&](size_t i) { return static_cast<float>(indicators.feature_score[i]); });
  field("source_index", "uint", [](size_t i) { return static_cast<double>(i); });
  return cloud;
}

}  // namespace lpd::cli

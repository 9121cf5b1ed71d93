#include "experiments/sweep/sweep_config.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "experiments/evaluation/ground_truth.h"
#include "experiments/shapes/shape_catalog.h"
#include "experiments/sweep/sweep_methods.h"

namespace lpd::experiments {
namespace {

int Line(const YAML::Node& node) { return node.Mark().line + 1; }

[[noreturn]] void Fail(const std::string& path, int line, const std::string& reason) {
  throw std::runtime_error(path + ":" + std::to_string(line) + ": " + reason);
}

// YAML leaves a repeated key to the reader; here it would run cells twice under one id.
void RefuseRepeatedKeys(const std::string& path, const YAML::Node& map) {
  std::set<std::string> seen;
  for (const auto& item : map) {
    const std::string key = item.first.as<std::string>();
    if (!seen.insert(key).second) {
      Fail(path, Line(item.first), "key '" + key + "' appears twice in one mapping");
    }
  }
}

void CheckKeys(const std::string& path, const YAML::Node& map, const std::string& where,
               const std::set<std::string>& allowed) {
  if (!map.IsMap()) Fail(path, Line(map), where + " must be a mapping of key: value");
  RefuseRepeatedKeys(path, map);
  for (const auto& item : map) {
    const std::string key = item.first.as<std::string>();
    if (!allowed.count(key)) {
      std::string known;
      for (const std::string& name : allowed) known += " " + name;
      Fail(path, Line(item.first), "unknown key '" + key + "' in " + where + " (known:" + known + ")");
    }
  }
}

std::string Scalar(const std::string& path, const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) Fail(path, Line(node), "'" + key + "' must be a single value");
  return node.Scalar();
}

// An integer in [minimum, maximum] (maximum: what the field holds, or a sane bound).
long Integer(const std::string& path, const YAML::Node& node, const std::string& key,
             long minimum, long maximum = std::numeric_limits<int>::max()) {
  const std::string text = Scalar(path, node, key);
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < minimum || value > maximum) {
    Fail(path, Line(node), "'" + key + "' must be an integer in [" + std::to_string(minimum) +
                               ", " + std::to_string(maximum) + "], got '" + text + "'");
  }
  return value;
}

double Number(const std::string& path, const YAML::Node& node, const std::string& key) {
  const std::string text = Scalar(path, node, key);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') {
    Fail(path, Line(node), "'" + key + "' must be a number, got '" + text + "'");
  }
  return value;
}

// The most cells one sweep runs (a mistyped range would otherwise expand to millions of
// cells and gigabytes before the first one runs); a larger study is split into configs.
constexpr double kMaxSweepCells = 100000;

// Expands a mapping whose values are scalars or lists of scalars into the cartesian product
// of its lists (a grid); the key `skip_key` is left out.
std::vector<ParameterSet> ExpandGrid(const std::string& path, const YAML::Node& map,
                                     const std::string& skip_key) {
  RefuseRepeatedKeys(path, map);
  std::vector<ParameterSet> grid(1);
  for (const auto& item : map) {
    const std::string key = item.first.as<std::string>();
    if (key == skip_key) continue;
    std::vector<ConfigValue> values;
    if (item.second.IsScalar()) {
      values.push_back({item.second.Scalar(), Line(item.second)});
    } else if (item.second.IsSequence() && item.second.size() > 0) {
      for (const YAML::Node& value : item.second) {
        if (!value.IsScalar()) Fail(path, Line(value), "'" + key + "' lists must hold values");
        values.push_back({value.Scalar(), Line(value)});
      }
    } else {
      Fail(path, Line(item.second), "'" + key + "' must be a value or a non-empty list");
    }
    for (size_t a = 0; a < values.size(); ++a) {
      for (size_t b = 0; b < a; ++b) {
        if (values[a].text == values[b].text) {
          Fail(path, values[a].line, "'" + key + "' lists " + values[a].text + " twice");
        }
      }
    }
    if (static_cast<double>(grid.size()) * values.size() > kMaxSweepCells) {
      Fail(path, Line(item.second),
           "the grid reaches more than " + std::to_string(static_cast<int>(kMaxSweepCells)) +
               " points at '" + key + "'; split the sweep into several configs");
    }
    std::vector<ParameterSet> expanded;
    for (const ParameterSet& point : grid) {
      for (const ConfigValue& value : values) {
        expanded.push_back(point);
        expanded.back()[key] = value;
      }
    }
    grid = std::move(expanded);
  }
  return grid;
}

void RequireFile(const std::string& path, int line, const std::string& file) {
  if (!std::filesystem::exists(file)) {
    Fail(path, line, "file not found: " + file + " (data paths may use ${LPD_DATA})");
  }
}

DatasetConfig LoadDataset(const std::string& path, const YAML::Node& node) {
  CheckKeys(path, node, "a dataset", {"shape", "mesh", "file", "ground_truth", "points", "sampling", "name"});
  DatasetConfig dataset;
  dataset.line = Line(node);
  int sources = 0;
  if (node["shape"]) {
    ++sources;
    dataset.shape = Scalar(path, node["shape"], "shape");
    try {
      MakeShape(ParseShapeSpec(dataset.shape));
    } catch (const std::invalid_argument& error) {
      Fail(path, Line(node["shape"]), error.what());
    }
  }
  if (node["mesh"]) {
    ++sources;
    dataset.mesh = ExpandDataPath(Scalar(path, node["mesh"], "mesh"));
    RequireFile(path, Line(node["mesh"]), dataset.mesh);
  }
  if (node["file"]) {
    ++sources;
    dataset.file = ExpandDataPath(Scalar(path, node["file"], "file"));
    RequireFile(path, Line(node["file"]), dataset.file);
  }
  if (sources != 1) Fail(path, dataset.line, "a dataset needs exactly one of shape, mesh, file");
  if (node["ground_truth"]) {
    if (dataset.file.empty()) {
      Fail(path, Line(node["ground_truth"]), "ground_truth is only for 'file' datasets");
    }
    dataset.ground_truth = ExpandDataPath(Scalar(path, node["ground_truth"], "ground_truth"));
    if (dataset.ground_truth.rfind("shape:", 0) != 0) {
      RequireFile(path, Line(node["ground_truth"]), dataset.ground_truth);
    }
  }
  if (node["points"]) {
    if (!dataset.file.empty()) Fail(path, Line(node["points"]), "'points' is for shape or mesh");
    dataset.points = static_cast<int>(Integer(path, node["points"], "points", 1, 1000000000));
  }
  if (node["sampling"]) {
    if (!dataset.file.empty()) Fail(path, Line(node["sampling"]), "'sampling' is for shape or mesh");
    const std::string sampling = Scalar(path, node["sampling"], "sampling");
    if (sampling != "uniform" && sampling != "poisson_disk") {
      Fail(path, Line(node["sampling"]),
           "unknown sampling '" + sampling + "' (expected uniform or poisson_disk)");
    }
    dataset.poisson_disk = sampling == "poisson_disk";
  }
  if (node["name"]) {
    dataset.name = Scalar(path, node["name"], "name");
  } else if (!dataset.shape.empty()) {
    dataset.name = dataset.shape;
  } else {
    dataset.name = std::filesystem::path(dataset.file.empty() ? dataset.mesh : dataset.file)
                       .stem()
                       .string();
  }
  return dataset;
}

}  // namespace

int NumNoiseSettings(const SweepConfig& config, const DatasetConfig& dataset) {
  return dataset.file.empty() ? static_cast<int>(config.noise.size()) : 1;
}

std::string ExpandDataPath(const std::string& path) {
  const std::string variable = "${LPD_DATA}";
  const size_t at = path.find(variable);
  if (at == std::string::npos) return path;
  const char* environment = std::getenv("LPD_DATA");
  const std::string data = environment && *environment ? environment : LPD_DEFAULT_DATA_DIR;
  return path.substr(0, at) + data + path.substr(at + variable.size());
}

std::string Describe(const ParameterSet& parameters) {
  std::string text;
  for (const auto& [key, value] : parameters) {
    text += (text.empty() ? "" : ",") + key + "=" + value.text;
  }
  return text;
}

NoiseOptions ToNoiseOptions(const ParameterSet& noise, const std::string& config_path) {
  NoiseOptions options;
  for (const auto& [key, value] : noise) {
    try {
      char* end = nullptr;
      const double number = std::strtod(value.text.c_str(), &end);
      const bool is_number = !value.text.empty() && *end == '\0';
      if (!std::set<std::string>{"model", "sigma", "scale", "outliers", "outlier_ratio",
                                 "outlier_margin"}
               .count(key)) {
        throw std::invalid_argument(
            "unknown noise key '" + key +
            "' (known: model, sigma, scale, outliers, outlier_ratio, outlier_margin)");
      }
      if (key == "model") {
        options.model = ParseNoiseModel(value.text);
      } else if (key == "scale") {
        options.scale = ParseNoiseScale(value.text);
      } else if (!is_number) {
        throw std::invalid_argument("noise " + key + " must be a number, got '" + value.text + "'");
      } else if (key == "sigma") {
        options.sigma = number;
      } else if (key == "outliers") {
        // Checked as a double first: casting 1e78 to int is undefined (found by the fuzzer).
        if (!(number >= 0.0 && number <= 1e9) || number != std::floor(number)) {
          throw std::invalid_argument("noise outliers must be an integer in [0, 1e9], got '" +
                                      value.text + "'");
        }
        options.outlier_count = static_cast<int>(number);
      } else if (key == "outlier_ratio") {
        options.outlier_ratio = number;
      } else {
        options.outlier_margin = number;
      }
    } catch (const std::invalid_argument& error) {
      Fail(config_path, value.line, error.what());
    }
  }
  std::string error;
  if (!options.IsValid(&error)) {
    Fail(config_path, noise.empty() ? 0 : noise.begin()->second.line, error);
  }
  return options;
}

namespace {

// The run settings: name, repetitions, seed, parallelism, metric options, save_clouds.
void LoadSettings(const std::string& path, const YAML::Node& root, SweepConfig* out) {
  SweepConfig& config = *out;
  config.name = root["name"] ? Scalar(path, root["name"], "name")
                             : std::filesystem::path(path).stem().string();
  if (root["repetitions"]) config.repetitions = Integer(path, root["repetitions"], "repetitions", 1);
  if (root["seed"]) {
    config.seed = Integer(path, root["seed"], "seed", 0, std::numeric_limits<long>::max());
  }
  if (root["parallel_cells"]) {
    config.parallel_cells = Integer(path, root["parallel_cells"], "parallel_cells", 1);
  }
  if (root["threads_per_cell"]) {
    config.threads_per_cell =
        Integer(path, root["threads_per_cell"], "threads_per_cell", 1, 1024);
  }
  if (root["ground_truth_samples"]) {
    config.ground_truth_samples =
        Integer(path, root["ground_truth_samples"], "ground_truth_samples", 1);
  }
  if (root["feature_band"]) {
    config.feature_band = Number(path, root["feature_band"], "feature_band");
    if (!(config.feature_band > 0.0)) Fail(path, Line(root["feature_band"]), "feature_band must be > 0");
  }

  if (root["save_clouds"]) {
    const std::string text = Scalar(path, root["save_clouds"], "save_clouds");
    if (text != "true" && text != "false") {
      Fail(path, Line(root["save_clouds"]), "save_clouds must be true or false, got '" + text + "'");
    }
    config.save_clouds = text == "true";
  }

}

void LoadReconstructions(const std::string& path, const YAML::Node& root, SweepConfig* config) {
  if (const YAML::Node reconstructions = root["reconstructions"]) {
    if (!reconstructions.IsSequence()) {
      Fail(path, Line(reconstructions), "'reconstructions' must be a list (advancing_front, "
                                        "scale_space)");
    }
    for (const YAML::Node& node : reconstructions) {
      try {
        config->reconstructions.push_back(
            ParseReconstruction(Scalar(path, node, "reconstructions")));
      } catch (const std::invalid_argument& error) {
        Fail(path, Line(node), error.what());
      }
    }
  }

}

void LoadDatasets(const std::string& path, const YAML::Node& root, SweepConfig* config) {
  const YAML::Node datasets = root["datasets"];
  if (!datasets || !datasets.IsSequence() || datasets.size() == 0) {
    Fail(path, datasets ? Line(datasets) : 1, "'datasets' must be a non-empty list");
  }
  std::set<std::string> names;
  for (const YAML::Node& node : datasets) {
    config->datasets.push_back(LoadDataset(path, node));
    if (!names.insert(config->datasets.back().name).second) {
      Fail(path, config->datasets.back().line,
           "two datasets are named '" + config->datasets.back().name + "' (give them names)");
    }
  }

}

// Every noise entry expanded into its grid; without a noise section, the data as they are.
void LoadNoise(const std::string& path, const YAML::Node& root, SweepConfig* config) {
  if (const YAML::Node noise = root["noise"]) {
    if (!noise.IsSequence() || noise.size() == 0) Fail(path, Line(noise), "'noise' must be a non-empty list");
    for (const YAML::Node& node : noise) {
      if (!node.IsMap()) Fail(path, Line(node), "a noise entry must be a mapping");
      for (const ParameterSet& point : ExpandGrid(path, node, "")) {
        ToNoiseOptions(point, path);  // validates
        config->noise.push_back(point);
      }
    }
  } else {
    config->noise.push_back({{"sigma", {"0", 0}}});
  }

}

// Every method entry expanded into its grid, each point checked as the method will read it.
void LoadMethods(const std::string& path, const YAML::Node& root, SweepConfig* config) {
  const YAML::Node methods = root["methods"];
  if (!methods || !methods.IsSequence() || methods.size() == 0) {
    Fail(path, methods ? Line(methods) : 1, "'methods' must be a non-empty list");
  }
  for (const YAML::Node& node : methods) {
    if (!node.IsMap() || !node["method"]) {
      Fail(path, Line(node), "a method entry needs 'method: NAME' (none, lpd or ceres)");
    }
    const std::string method = Scalar(path, node["method"], "method");
    for (const ParameterSet& point : ExpandGrid(path, node, "method")) {
      MethodConfig config_point{method, point};
      try {
        EffectiveParameters(config_point);
      } catch (const std::invalid_argument& error) {
        // Point at the offending key when the message names one.
        int line = Line(node);
        for (const auto& [key, value] : point) {
          if (std::string(error.what()).find(key) != std::string::npos) line = value.line;
        }
        Fail(path, line, error.what());
      }
      config->methods.push_back(config_point);
    }
  }
}

void CheckCellCount(const std::string& path, const SweepConfig& config) {
  double cells = 0.0;
  for (const DatasetConfig& dataset : config.datasets) {
    cells += static_cast<double>(config.repetitions) * config.methods.size() *
             NumNoiseSettings(config, dataset);
  }
  if (cells > kMaxSweepCells) {
    Fail(path, 1, "the sweep has " + std::to_string(static_cast<long long>(cells)) +
                      " cells, more than " + std::to_string(static_cast<int>(kMaxSweepCells)) +
                      "; split it into several configs");
  }
}

}  // namespace

SweepConfig LoadSweepConfig(const std::string& path) {
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error(path + ": cannot open config (missing or unreadable)");
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& error) {
    Fail(path, error.mark.line + 1, "invalid YAML: " + error.msg);
  }
  if (!root.IsMap()) Fail(path, 1, "a sweep config must be a mapping (name:, datasets:, ...)");
  CheckKeys(path, root, "the config",
            {"name", "repetitions", "seed", "parallel_cells", "threads_per_cell",
             "ground_truth_samples", "feature_band", "save_clouds", "reconstructions",
             "datasets", "noise", "methods"});
  SweepConfig config;
  config.path = path;
  LoadSettings(path, root, &config);
  LoadReconstructions(path, root, &config);
  LoadDatasets(path, root, &config);
  LoadNoise(path, root, &config);
  LoadMethods(path, root, &config);
  CheckCellCount(path, config);
  return config;
}

}  // namespace lpd::experiments

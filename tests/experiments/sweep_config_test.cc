// Sweep configs: grids expand as cartesian products, errors name the file and line, results
// round-trip through JSON, a rerun skips finished cells, and saved clouds carry distances.
#include "experiments/sweep/sweep_config.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "io/point_cloud_io.h"
#include "experiments/sweep/sweep_results.h"
#include "experiments/sweep/sweep_runner.h"

namespace lpd::experiments {
namespace {

std::string WriteConfig(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

// The message of the exception LoadSweepConfig throws for `text` ("" if none).
std::string LoadError(const std::string& text) {
  const std::string path = WriteConfig("bad", text);
  try {
    LoadSweepConfig(path);
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << "the error names the file: " << message;
    return message.substr(path.size());
  }
  return "";
}

const char* kValid = R"(name: tiny
datasets:
  - shape: cube
    points: 500
  - shape: cone:apex_angle=40
    points: 500
noise:
  - sigma: [0.01, 0.02, 0.03]
    outliers: [0, 10]
methods:
  - method: none
  - method: lpd
    k: [8, 12]
    lambda: [1, 2]
    max_iters: 1
)";

TEST(SweepConfig, GridsExpandAsCartesianProducts) {
  const SweepConfig config = LoadSweepConfig(WriteConfig("tiny", kValid));
  EXPECT_EQ(config.name, "tiny");
  ASSERT_EQ(config.datasets.size(), 2u);
  EXPECT_EQ(config.datasets[1].name, "cone:apex_angle=40");
  EXPECT_EQ(config.noise.size(), 6u);    // 3 sigmas x 2 outlier counts
  EXPECT_EQ(config.methods.size(), 5u);  // none + 2 k x 2 lambda
  const std::vector<SweepCell> cells = ExpandCells(config);
  EXPECT_EQ(cells.size(), 2u * 6u * 5u);
  std::set<std::string> ids;
  for (const SweepCell& cell : cells) ids.insert(cell.id);
  EXPECT_EQ(ids.size(), cells.size()) << "cell ids are unique";
}

TEST(SweepConfig, ErrorsNameTheLineAndTheKey) {
  EXPECT_EQ(LoadError("name: x\ndatasets: [\n"), ":3: invalid YAML: end of sequence flow not found");
  EXPECT_NE(LoadError("name: x\ncolour: red\n").find(":2: unknown key 'colour' in the config"),
            std::string::npos);
  const std::string base = "datasets:\n  - shape: cube\nmethods:\n  - method: lpd\n";
  EXPECT_NE(LoadError(base + "    kk: 3\n").find(":5: method lpd: unknown parameter 'kk'"),
            std::string::npos);
  EXPECT_NE(LoadError(base + "    k: [5, x]\n").find(":5: method lpd: parameter k: 'x' is not an integer or auto"),
            std::string::npos);
  // A repeated key or value would run cells twice under one id; a count that wrapped to
  // 2,000 points ran a different sweep.
  EXPECT_NE(LoadError(base + "    k: 5\n    k: 6\n").find(":6: key 'k' appears twice"),
            std::string::npos);
  EXPECT_NE(LoadError(base + "    k: [5, 6, 5]\n").find(":5: 'k' lists 5 twice"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - shape: cube\n    points: 4294969296\nmethods:\n"
                      "  - method: none\n")
                .find(":3: 'points' must be an integer in [1, 1000000000], got '4294969296'"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - shape: teapot\nmethods:\n  - method: none\n")
                .find(":2: unknown shape 'teapot'"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - file: /no/such.xyz\nmethods:\n  - method: none\n")
                .find(":2: file not found: /no/such.xyz"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - shape: cube\nnoise:\n  - sigma: 0.1\n    modle: normal\n"
                      "methods:\n  - method: none\n")
                .find(":5: unknown noise key 'modle'"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - shape: cube\nmethods:\n  - method: magic\n")
                .find(":4: unknown method 'magic'"),
            std::string::npos);
  // Baseline parameters are checked the same way (method_parameters.h).
  const std::string bilateral = "datasets:\n  - shape: cube\nmethods:\n  - method: bilateral\n";
  EXPECT_NE(LoadError(bilateral + "    radius: 3\n")
                .find(":5: unknown parameter 'radius' of method bilateral (known: iterations, k, "
                      "normals, sharpness_angle)"),
            std::string::npos);
  EXPECT_NE(LoadError(bilateral + "    normals: vcm\n")
                .find(":5: parameter normals of method bilateral: 'vcm' is not one of pca, jet"),
            std::string::npos);
  EXPECT_NE(LoadError(bilateral + "    sharpness_angle: 95\n")
                .find("parameter sharpness_angle of method bilateral: '95' is not a number in "
                      "[0.1, 89.9]"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets:\n  - shape: cube\nmethods:\n  - method: jet\n    k: 2.5\n")
                .find(":5: parameter k of method jet: '2.5' is not an integer >= 6"),
            std::string::npos);
  EXPECT_NE(LoadError("datasets: []\nmethods:\n  - method: none\n")
                .find(":1: 'datasets' must be a non-empty list"),
            std::string::npos);
}

TEST(SweepResults, RecordsRoundTripThroughJson) {
  ResultRecord record;
  record.Add("cell_id", std::string("abc"));
  record.Add("text", std::string("a \"quoted\", comma"));
  record.Add("number", 1.25e-7);
  record.Add("missing", NAN);
  record.Add("count", 42L);
  const ResultRecord back = ResultRecord::FromJson(record.ToJson());
  EXPECT_EQ(back.fields(), record.fields());
  EXPECT_EQ(back.ToJson(), record.ToJson());
}

// A record cut short (a full disk) is dropped when the results are read again, and the next
// record starts a line of its own instead of being glued onto the torn one.
TEST(SweepResults, ATornLastRecordIsDroppedAndTheNextOneStartsAFreshLine) {
  const std::string directory = ::testing::TempDir() + "/torn_results";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  auto record = [](const char* id) {
    ResultRecord r;
    r.Add("cell_id", std::string(id));
    r.Add("mse", 0.5);
    return r;
  };
  {
    std::ofstream out(directory + "/results.jsonl");
    out << record("a").ToJson() << "\n" << record("b").ToJson() << "\n";
    const std::string torn = record("c").ToJson();
    out << torn.substr(0, torn.size() / 2);
  }
  {
    ResultStore store(directory, {"cell_id", "mse"});
    EXPECT_TRUE(store.Contains("a") && store.Contains("b"));
    EXPECT_FALSE(store.Contains("c"));
    store.Append(record("c"));
  }
  const ResultStore again(directory, {"cell_id", "mse"});
  EXPECT_TRUE(again.Contains("a") && again.Contains("b") && again.Contains("c"));
  std::ifstream in(directory + "/results.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) {
    EXPECT_NO_THROW(ResultRecord::FromJson(line)) << line;
    ++lines;
  }
  EXPECT_EQ(lines, 3);
}

// The methods of the runner tests: the input as is, and one lpd iteration.
const char* kNoneAndOneLpdIteration = R"(methods:
  - method: none
  - method: lpd
    k: 8
    max_iters: 1
)";

// Run options writing to TempDir()/name, emptied first.
SweepRunOptions EmptyResultsDirectory(const std::string& name) {
  SweepRunOptions options;
  options.results_directory = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(options.results_directory);
  return options;
}

TEST(SweepRunner, ARerunSkipsFinishedCellsAndKeepsTheRows) {
  const std::string config_path = WriteConfig("resume", R"(name: resume
ground_truth_samples: 5000
datasets:
  - shape: sphere
    points: 400
noise:
  - sigma: [0.005, 0.01]
)" + std::string(kNoneAndOneLpdIteration));
  const SweepRunOptions options = EmptyResultsDirectory("resume_results");
  const SweepConfig config = LoadSweepConfig(config_path);
  const SweepRunSummary first = RunSweep(config, options);
  EXPECT_EQ(first.num_cells, 4);
  EXPECT_EQ(first.num_run, 4);
  EXPECT_EQ(first.num_failed, 0);
  const SweepRunSummary second = RunSweep(config, options);
  EXPECT_EQ(second.num_run, 0);
  EXPECT_EQ(second.num_skipped, 4);
  // The CSV has a header and one row per cell.
  std::ifstream csv(first.csv_path);
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 5);
}

TEST(SweepRunner, SavedOutputCloudsCarryTheDistanceToTheCleanSurface) {
  const std::string config_path = WriteConfig("clouds", R"(name: clouds
ground_truth_samples: 2000
save_clouds: true
datasets:
  - shape: sphere:radius=0.5
    points: 300
noise:
  - sigma: 0.01
)" + std::string(kNoneAndOneLpdIteration));
  const SweepRunOptions options = EmptyResultsDirectory("clouds_results");
  ASSERT_EQ(RunSweep(LoadSweepConfig(config_path), options).num_failed, 0);
  int outputs = 0;
  const std::string clouds = options.results_directory + "/clouds";
  for (const auto& entry : std::filesystem::directory_iterator(clouds)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 11 || name.substr(name.size() - 11) != "_output.ply") continue;
    ++outputs;
    const io::PointCloud cloud = io::ReadPointCloud(entry.path().string());
    ASSERT_EQ(cloud.attributes.size(), 1u) << name;
    ASSERT_EQ(cloud.attributes[0].name, "distance");
    ASSERT_EQ(cloud.attributes[0].values.size(), cloud.points.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
      // The sphere's distance in closed form; the PLY stores floats.
      EXPECT_NEAR(cloud.attributes[0].values[i], std::abs(cloud.points[i].norm() - 0.5), 1e-6)
          << name << " point " << i;
    }
  }
  EXPECT_EQ(outputs, 2);
}

}  // namespace
}  // namespace lpd::experiments

#include "experiments/sweep/sweep_runner.h"

#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "experiments/baselines/surface_reconstruction.h"
#include "experiments/evaluation/benchmark_metrics.h"
#include "experiments/evaluation/ground_truth_source.h"
#include "experiments/evaluation/metrics.h"
#include "io/atomic_output_file.h"
#include "io/interruption.h"
#include "io/machine_info.h"
#include "io/point_cloud_io.h"
#include "experiments/shapes/poisson_disk_sampling.h"
#include "experiments/shapes/shape_catalog.h"
#include "experiments/shapes/triangle_mesh.h"
#include "experiments/sweep/sweep_methods.h"
#include "experiments/sweep/sweep_results.h"

namespace lpd::experiments {
namespace {

using energy::PointList;

std::string Hash(const std::string& text) {  // FNV-1a, 64 bits
  uint64_t hash = 1469598103934665603ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016" PRIx64, hash);
  return hex;
}

// What a dataset provides to its cells, loaded once.
struct LoadedDataset {
  std::shared_ptr<const ProceduralShape> shape;
  std::unique_ptr<TriangleMesh> mesh;
  PointList file_points;
  std::unique_ptr<GroundTruth> truth;  // null when there is none
};

LoadedDataset LoadDataset(const DatasetConfig& dataset, const SweepConfig& config) {
  LoadedDataset loaded;
  if (!dataset.shape.empty()) {
    loaded.shape = std::make_shared<const ProceduralShape>(MakeShape(ParseShapeSpec(dataset.shape)));
    loaded.truth = std::make_unique<GroundTruth>(
        ShapeGroundTruth(loaded.shape, config.ground_truth_samples));
  } else if (!dataset.mesh.empty()) {
    loaded.mesh = std::make_unique<TriangleMesh>(ReadTriangleMesh(dataset.mesh));
    loaded.truth = std::make_unique<GroundTruth>(
        MeshGroundTruth(*loaded.mesh, dataset.mesh, config.ground_truth_samples));
  } else {
    loaded.file_points = io::ReadPoints(dataset.file);
    if (!dataset.ground_truth.empty()) {
      loaded.truth = std::make_unique<GroundTruth>(
          LoadGroundTruth(dataset.ground_truth, config.ground_truth_samples));
    }
  }
  return loaded;
}

// The input of one cell: the noisy points, and what is known about each of them.
struct CellInput {
  PointList points;
  PointList clean;                 // clean position of each non-outlier point (generated data)
  std::vector<uint8_t> is_outlier; // empty for file datasets
  NoiseOptions noise;
  double scale_length = NAN;
  double sigma_absolute = NAN;
};

CellInput MakeInput(const SweepConfig& config, const SweepCell& cell,
                    const LoadedDataset& loaded) {
  const DatasetConfig& dataset = config.datasets[cell.dataset];
  CellInput input;
  if (!dataset.file.empty()) {
    input.points = loaded.file_points;
    return input;
  }
  const uint64_t sample_seed = config.seed + cell.repetition;
  SurfaceSamples clean;
  if (dataset.poisson_disk) {
    clean = loaded.shape ? PoissonDiskSample(*loaded.shape, dataset.points, sample_seed)
                         : PoissonDiskSample(*loaded.mesh, dataset.points, sample_seed);
  } else {
    clean = loaded.shape ? loaded.shape->Sample(dataset.points, sample_seed)
                         : SampleTriangleMesh(*loaded.mesh, dataset.points, sample_seed);
  }
  input.noise = ToNoiseOptions(config.noise[cell.noise], config.path);
  input.noise.seed = config.seed + 1000003ull * (cell.repetition + 1);
  NoisyPointSet noisy = ApplyNoise(clean.points, clean.normals, input.noise);
  input.points = std::move(noisy.points);
  input.is_outlier = std::move(noisy.is_outlier);
  input.clean = clean.points;
  input.scale_length = noisy.scale_length;
  input.sigma_absolute = noisy.sigma_absolute;
  return input;
}

void AddDetection(const std::string& prefix, const DetectionScore& score, ResultRecord* record) {
  record->Add(prefix + "_precision", score.precision());
  record->Add(prefix + "_recall", score.recall());
}

// "seconds:energy" pairs separated by spaces (kept out of the CSV; plotted from the JSONL).
std::string EnergyTraceText(const std::vector<std::pair<double, double>>& trace) {
  std::string text;
  char pair[64];
  for (const auto& [seconds, energy] : trace) {
    std::snprintf(pair, sizeof(pair), "%s%.4f:%.10e", text.empty() ? "" : " ", seconds, energy);
    text += pair;
  }
  return text;
}

// "fitting:smoothness:stitching" per iteration, separated by spaces (JSONL only).
std::string EnergyTermsText(const std::vector<energy::EnergyBreakdown>& terms) {
  std::string text;
  char triple[96];
  for (const energy::EnergyBreakdown& energy : terms) {
    std::snprintf(triple, sizeof(triple), "%s%.8e:%.8e:%.8e", text.empty() ? "" : " ",
                  energy.fitting, energy.smoothness, energy.stitching);
    text += triple;
  }
  return text;
}

// RESULTS/clouds/ID_input.ply (the noisy input with the method's indicators and the true
// outlier labels) and ID_output.ply (the output with `distances`, each output point's
// distance to the clean surface, unless empty).
void SaveClouds(const std::string& directory, const std::string& cell_id,
                const CellInput& input, const MethodRun& run,
                const std::vector<double>& distances) {
  const std::string clouds = directory + "/clouds";
  std::filesystem::create_directories(clouds);
  // Written as float properties, as every viewer shows them.
  auto as_float = [](std::string name, const auto& values) {
    return io::PointAttribute{std::move(name), "float",
                              std::vector<double>(values.begin(), values.end())};
  };
  io::PointCloud noisy;
  noisy.points = input.points;
  if (!run.outlier_flags.empty()) noisy.attributes.push_back(as_float("outlier", run.outlier_flags));
  if (!run.feature_flags.empty()) noisy.attributes.push_back(as_float("feature", run.feature_flags));
  if (!input.is_outlier.empty()) {
    noisy.attributes.push_back(as_float("true_outlier", input.is_outlier));
  }
  io::WritePointCloud(clouds + "/" + cell_id + "_input.ply", noisy, /*overwrite=*/true);
  io::PointCloud output;
  output.points = run.output;
  if (!distances.empty()) output.attributes.push_back(as_float("distance", distances));
  io::WritePointCloud(clouds + "/" + cell_id + "_output.ply", output, /*overwrite=*/true);
}

// Reconstructs the cell's output with every method of `config.reconstructions` and records
// the seconds taken and any error (a failed reconstruction does not fail the cell).
void SaveMeshes(const SweepConfig& config, const std::string& directory,
                const std::string& cell_id, const MethodRun& run, ResultRecord* record) {
  if (config.reconstructions.empty()) return;
  const std::string meshes = directory + "/meshes";
  std::filesystem::create_directories(meshes);
  for (const Reconstruction method : config.reconstructions) {
    const std::string name = ToString(method);
    ReconstructionOptions options;
    options.method = method;
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    try {
      WriteTriangleMesh(meshes + "/" + cell_id + "_" + name + ".off",
                        ReconstructSurface(run.output, options), /*overwrite=*/true);
    } catch (const std::exception& failure) {
      error = failure.what();
    }
    record->Add(name + "_seconds",
                error.empty() ? std::chrono::duration<double>(
                                    std::chrono::steady_clock::now() - start).count()
                              : NAN);
    record->Add(name + "_error", error);
  }
}

ResultRecord RunCell(const SweepConfig& config, const SweepCell& cell,
                     const LoadedDataset& loaded, int num_threads,
                     const SweepRunOptions& options, const std::string& machine) {
  const DatasetConfig& dataset = config.datasets[cell.dataset];
  const MethodConfig& method = config.methods[cell.method];
  const CellInput input = MakeInput(config, cell, loaded);
  const MethodRun run = RunMethod(method, input.points, num_threads);

  ResultRecord record;
  record.Add("cell_id", cell.id);
  record.Add("config", config.name);
  record.Add("dataset", dataset.name);
  record.Add("dataset_source", !dataset.shape.empty()  ? "shape " + loaded.shape->description()
                               : !dataset.mesh.empty() ? "mesh " + dataset.mesh
                                                       : "file " + dataset.file);
  record.Add("repetition", static_cast<long>(cell.repetition));
  record.Add("num_input", static_cast<long>(input.points.size()));
  const bool generated = dataset.file.empty();
  record.Add("noise_model", generated ? ToString(input.noise.model) : "as given");
  record.Add("noise_sigma", generated ? input.noise.sigma : NAN);
  record.Add("noise_scale", generated ? ToString(input.noise.scale) : "");
  record.Add("noise_scale_length", input.scale_length);
  record.Add("noise_sigma_absolute", input.sigma_absolute);
  long num_outliers = 0;
  for (uint8_t label : input.is_outlier) num_outliers += label;
  record.Add("num_outliers", generated ? num_outliers : NAN);
  record.Add("method", method.method);
  record.Add("method_parameters", Describe(method.parameters));
  for (const auto& [name, value] : EffectiveParameters(method)) record.Add(name, value);

  record.Add("num_output", static_cast<long>(run.output.size()));
  const GroundTruth* truth = loaded.truth.get();
  Metrics metrics;
  if (truth) {
    record.Add("ground_truth", truth->description);
    metrics = ComputeMetrics(run.output, *truth, num_threads);
    for (const auto& [name, value] : metrics.Columns()) record.Add(name, value);
    record.Add("p2m_x1e4", PointToMeshDistanceX1e4(run.output, *truth, num_threads));
  }
  if (!input.clean.empty()) {
    record.Add("cd_x1e4", ChamferDistanceX1e4(run.output, input.clean, num_threads));
  }
  if (!input.is_outlier.empty() && !run.outlier_flags.empty() && num_outliers > 0) {
    AddDetection("outlier", ScoreDetection(run.outlier_flags, input.is_outlier), &record);
    if (truth && truth->surface_distances) {
      AddDetection("outlier_bound",
                   BestDistanceThreshold(truth->surface_distances(input.points, num_threads),
                                         input.is_outlier)
                       .score,
                   &record);
    }
  }
  if (truth && truth->feature_distance && !run.feature_flags.empty()) {
    // Only clean points have a position to label; outliers are left out of the score.
    const std::vector<uint8_t> labels =
        FeatureLabels(input.clean, *truth, config.feature_band * truth->diagonal);
    const std::vector<uint8_t> flags(run.feature_flags.begin(),
                                     run.feature_flags.begin() + input.clean.size());
    AddDetection("feature", ScoreDetection(flags, labels), &record);
    record.Add("feature_band", config.feature_band);
  }
  record.Add("iterations", static_cast<long>(run.iterations));
  record.Add("initial_energy", run.initial_energy);
  record.Add("final_energy", run.final_energy);
  record.Add("energy_trace", EnergyTraceText(run.energy_trace));
  record.Add("energy_terms_trace", EnergyTermsText(run.energy_terms));
  record.Add("mu_l_used", run.mu_l);
  if (config.save_clouds) {
    SaveClouds(options.results_directory, cell.id, input, run, metrics.distances);
  }
  SaveMeshes(config, options.results_directory, cell.id, run, &record);
  record.Add("termination", run.termination);
  record.Add("note", run.note);
  record.Add("seconds", run.seconds);
  record.Add("setup_seconds", run.setup_seconds);
  record.Add("local_seconds_per_iteration", run.local_seconds);
  record.Add("global_seconds_per_iteration", run.global_seconds);
  record.Add("threads", static_cast<long>(num_threads));
  record.Add("seed", static_cast<long>(config.seed));
  record.Add("git_revision", options.git_revision);
  record.Add("machine", machine);
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof(stamp), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  record.Add("finished_at", stamp);
  record.Add("cell_key", cell.key);
  return record;
}

std::string Brief(const ResultRecord& record) {
  std::string text = record.Get("dataset") + " | " + record.Get("noise_model");
  if (!record.Get("noise_sigma").empty()) text += " " + record.Get("noise_sigma");
  if (record.Get("num_outliers") != "0" && !record.Get("num_outliers").empty()) {
    text += " +" + record.Get("num_outliers") + " outliers";
  }
  text += " | " + record.Get("method") + " " + record.Get("method_parameters");
  if (!record.Get("mse_normalized").empty()) {
    text += " | MSE/d^2 " + record.Get("mse_normalized") + ", mean dist/d " +
            record.Get("mean_distance_normalized");
  }
  return text + " | " + record.Get("seconds") + " s";
}

}  // namespace

std::vector<SweepCell> ExpandCells(const SweepConfig& config) {
  std::vector<SweepCell> cells;
  for (int r = 0; r < config.repetitions; ++r) {
    for (size_t d = 0; d < config.datasets.size(); ++d) {
      const DatasetConfig& dataset = config.datasets[d];
      const bool generated = dataset.file.empty();
      const int num_noise = NumNoiseSettings(config, dataset);
      for (int n = 0; n < num_noise; ++n) {
        for (size_t m = 0; m < config.methods.size(); ++m) {
          SweepCell cell;
          cell.dataset = static_cast<int>(d);
          cell.noise = generated ? n : -1;
          cell.method = static_cast<int>(m);
          cell.repetition = r;
          cell.key = "dataset=" + dataset.name + "|source=" + dataset.shape + dataset.mesh +
                     dataset.file + "|points=" + std::to_string(generated ? dataset.points : 0) +
                     (dataset.poisson_disk ? "|sampling=poisson_disk" : "") +
                     "|ground_truth=" + dataset.ground_truth +
                     "|noise=" + (generated ? Describe(config.noise[n]) : "as given") +
                     "|method=" + config.methods[m].method + ":" +
                     Describe(config.methods[m].parameters) + "|seed=" +
                     std::to_string(config.seed) + "|repetition=" + std::to_string(r);
          cell.id = Hash(cell.key);
          cells.push_back(cell);
        }
      }
    }
  }
  return cells;
}

const std::vector<std::string>& ResultColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> list = {
        "cell_id", "config", "dataset", "repetition", "num_input", "noise_model", "noise_sigma",
        "noise_scale", "noise_scale_length", "noise_sigma_absolute", "num_outliers", "method",
        "method_parameters"};
    for (const char* name : {"k", "lambda", "eta", "mu_l", "mu_l_used", "mu_m", "max_iters",
                                    "inner_iters"}) {
      list.push_back(name);
    }
    for (const char* name :
         {"num_output", "mse", "mse_normalized", "mcd", "mcd_normalized", "snr_db",
          "mean_distance", "mean_distance_normalized", "rms_distance_normalized",
          "max_distance_normalized", "cd_x1e4", "p2m_x1e4", "outlier_precision", "outlier_recall",
          "outlier_bound_precision", "outlier_bound_recall", "feature_precision",
          "feature_recall", "iterations", "final_energy", "seconds", "setup_seconds",
          "local_seconds_per_iteration", "global_seconds_per_iteration", "threads",
          "git_revision", "machine"}) {
      list.push_back(name);
    }
    return list;
  }();
  return columns;
}

SweepRunSummary RunSweep(const SweepConfig& config, const SweepRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SweepCell> cells = ExpandCells(config);
  // Before any cell runs: a results directory that cannot be written is found now, not
  // after every cell was computed.
  std::error_code error;
  std::filesystem::create_directories(options.results_directory, error);
  if (error) {
    throw std::runtime_error(options.results_directory + ": cannot create the results "
                             "directory: " + error.message());
  }
  io::RefuseExistingOutput(options.results_directory + "/results.csv", /*overwrite=*/true);
  ResultStore store(options.results_directory, ResultColumns());
  SweepRunSummary summary;
  summary.num_cells = static_cast<int>(cells.size());
  summary.csv_path = store.csv_path();
  summary.jsonl_path = store.jsonl_path();

  std::vector<const SweepCell*> pending;
  std::vector<bool> dataset_needed(config.datasets.size(), false);
  for (const SweepCell& cell : cells) {
    if (store.Contains(cell.id)) {
      ++summary.num_skipped;
      continue;
    }
    pending.push_back(&cell);
    dataset_needed[cell.dataset] = true;
  }
  std::mutex progress_mutex;
  const auto report = [&](const std::string& message) {
    std::lock_guard<std::mutex> lock(progress_mutex);
    if (options.progress) options.progress(message);
  };
  report(std::to_string(cells.size()) + " cells, " + std::to_string(summary.num_skipped) +
         " already in " + store.jsonl_path() + ", " + std::to_string(pending.size()) + " to run");
  if (options.dry_run) {
    for (const SweepCell* cell : pending) report("would run " + cell->key);
    return summary;
  }

  std::vector<LoadedDataset> datasets(config.datasets.size());
  for (size_t d = 0; d < config.datasets.size(); ++d) {
    if (dataset_needed[d]) datasets[d] = LoadDataset(config.datasets[d], config);
  }
  const int workers = std::max(1, std::min<int>(config.parallel_cells, pending.size()));
  const int threads = config.threads_per_cell > 0
                          ? config.threads_per_cell
                          : std::max(1, options.num_threads / workers);
  const std::string machine = io::MachineDescription();
  std::atomic<size_t> next{0};
  std::atomic<int> run_count{0}, failed{0};
  const auto work = [&]() {
    for (size_t p = next++; p < pending.size() && !io::InterruptionRequested(); p = next++) {
      const SweepCell& cell = *pending[p];
      try {
        const ResultRecord record =
            RunCell(config, cell, datasets[cell.dataset], threads, options, machine);
        store.Append(record);
        const int done = ++run_count;
        report("[" + std::to_string(done) + "/" + std::to_string(pending.size()) + "] " +
               Brief(record));
      } catch (const io::Interrupted&) {
        return;  // the cell is left to the next run
      } catch (const std::exception& error) {
        ++failed;
        report("cell failed (" + cell.key + "): " + error.what());
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  io::ThrowIfInterrupted();
  summary.num_run = run_count;
  summary.num_failed = failed;
  summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace lpd::experiments

#include "experiments/cli/tile_world.h"

#include <cstdio>
#include <cstdlib>
#include <list>
#include <stdexcept>

#ifdef LPD_WITH_MPI
#include <mpi.h>
#endif

namespace lpd::experiments {
namespace {

// A tile's outcome as one array of doubles: a header, one record per own point, then the
// halo's input indices.
constexpr int kHeader = 8;   // index, count, halo count, k, solved, iterations, converged, seconds
constexpr int kRecord = 12;  // input index, position, normal, two scores, three flags

[[maybe_unused]] std::vector<double> Pack(int index, const solvers::TileOutcome& tile) {
  const size_t n = tile.own.size();
  std::vector<double> buffer;
  buffer.reserve(kHeader + kRecord * n + tile.halo.size());
  buffer.insert(buffer.end(), {static_cast<double>(index), static_cast<double>(n),
                               static_cast<double>(tile.halo.size()), static_cast<double>(tile.k),
                               static_cast<double>(tile.solved_points),
                               static_cast<double>(tile.iterations),
                               tile.converged ? 1.0 : 0.0, tile.seconds});
  for (size_t a = 0; a < n; ++a) {
    buffer.push_back(tile.own[a]);
    for (int c = 0; c < 3; ++c) buffer.push_back(tile.projected[a][c]);
    for (int c = 0; c < 3; ++c) buffer.push_back(tile.normals[a][c]);
    buffer.push_back(tile.indicators.outlier_score[a]);
    buffer.push_back(tile.indicators.feature_score[a]);
    buffer.push_back(tile.indicators.is_outlier[a]);
    buffer.push_back(tile.indicators.is_feature[a]);
    buffer.push_back(tile.kept[a]);
  }
  buffer.insert(buffer.end(), tile.halo.begin(), tile.halo.end());
  return buffer;
}

[[maybe_unused]] void Unpack(const std::vector<double>& buffer, int* index,
                             solvers::TileOutcome* tile) {
  *index = static_cast<int>(buffer[0]);
  const size_t n = static_cast<size_t>(buffer[1]);
  const size_t halo = static_cast<size_t>(buffer[2]);
  tile->k = static_cast<int>(buffer[3]);
  tile->solved_points = static_cast<int>(buffer[4]);
  tile->iterations = static_cast<int>(buffer[5]);
  tile->converged = buffer[6] != 0.0;
  tile->seconds = buffer[7];
  tile->own.resize(n);
  tile->projected.resize(n);
  tile->normals.resize(n);
  solvers::PointIndicators& indicators = tile->indicators;
  indicators.outlier_score.resize(n);
  indicators.feature_score.resize(n);
  indicators.is_outlier.resize(n);
  indicators.is_feature.resize(n);
  tile->kept.resize(n);
  for (size_t a = 0; a < n; ++a) {
    const double* record = buffer.data() + kHeader + kRecord * a;
    tile->own[a] = static_cast<int>(record[0]);
    tile->projected[a] = energy::Point3(record[1], record[2], record[3]);
    tile->normals[a] = energy::Point3(record[4], record[5], record[6]);
    indicators.outlier_score[a] = record[7];
    indicators.feature_score[a] = record[8];
    indicators.is_outlier[a] = record[9] != 0.0;
    indicators.is_feature[a] = record[10] != 0.0;
    tile->kept[a] = record[11] != 0.0;
  }
  const double* halo_begin = buffer.data() + kHeader + kRecord * n;
  tile->halo.assign(halo_begin, halo_begin + halo);
}

#ifdef LPD_WITH_MPI
constexpr int kOutcomeTag = 1;

bool StartedByMpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}
#endif

}  // namespace

// Buffers of non-blocking sends: kept until MPI has sent them.
struct TileWorld::PendingSends {
#ifdef LPD_WITH_MPI
  std::list<std::vector<double>> buffers;
  std::vector<MPI_Request> requests;
#endif
};

bool BuiltWithMpi() {
#ifdef LPD_WITH_MPI
  return true;
#else
  return false;
#endif
}

TileWorld::TileWorld() : pending_(std::make_unique<PendingSends>()) {
#ifdef LPD_WITH_MPI
  if (!StartedByMpirun()) return;
  MPI_Init(nullptr, nullptr);
  joined_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

TileWorld::~TileWorld() {
#ifdef LPD_WITH_MPI
  if (!joined_) return;
  if (!pending_->requests.empty()) {
    MPI_Waitall(static_cast<int>(pending_->requests.size()), pending_->requests.data(),
                MPI_STATUSES_IGNORE);
  }
  MPI_Finalize();
#endif
}

void TileWorld::Send(int index, const solvers::TileOutcome& tile) {
#ifdef LPD_WITH_MPI
  pending_->buffers.push_back(Pack(index, tile));
  const std::vector<double>& buffer = pending_->buffers.back();
  MPI_Request request;
  MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, 0, kOutcomeTag,
            MPI_COMM_WORLD, &request);
  pending_->requests.push_back(request);
#else
  (void)index;
  (void)tile;
  throw std::logic_error("TileWorld::Send in a world of one");
#endif
}

bool TileWorld::Receive(bool wait, int* index, solvers::TileOutcome* tile) {
#ifdef LPD_WITH_MPI
  if (!joined_ || size_ == 1) return false;
  MPI_Status status;
  if (wait) {
    MPI_Probe(MPI_ANY_SOURCE, kOutcomeTag, MPI_COMM_WORLD, &status);
  } else {
    int arrived = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, kOutcomeTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return false;
  }
  int count = 0;
  MPI_Get_count(&status, MPI_DOUBLE, &count);
  std::vector<double> buffer(count);
  MPI_Recv(buffer.data(), count, MPI_DOUBLE, status.MPI_SOURCE, kOutcomeTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  Unpack(buffer, index, tile);
  return true;
#else
  (void)wait;
  (void)index;
  (void)tile;
  return false;
#endif
}

void TileWorld::Fail(const std::string& message) {
#ifdef LPD_WITH_MPI
  if (joined_) {
    std::fprintf(stderr, "lpd denoise: error: %s\n", message.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
#endif
  throw std::runtime_error(message);
}

void TileWorld::FailEverywhere(const std::string& message) {
#ifdef LPD_WITH_MPI
  if (joined_) {
    if (is_root()) {
      std::fprintf(stderr, "lpd denoise: error: %s\n", message.c_str());
      std::fflush(stderr);
    }
    MPI_Barrier(MPI_COMM_WORLD);  // rank 0 has printed before any rank aborts
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
#endif
  throw std::runtime_error(message);
}

}  // namespace lpd::experiments

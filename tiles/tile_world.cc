#include "tiles/tile_world.h"

#include <cstdio>
#include <cstdlib>
#include <list>
#include <stdexcept>

#ifdef LPD_WITH_MPI
#include <mpi.h>
#endif

namespace lpd::tiles {
namespace {

#ifdef LPD_WITH_MPI
constexpr int kMessageTag = 1;
constexpr int kFailureTag = 2;

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

void TileWorld::Broadcast(std::vector<double>* values) {
#ifdef LPD_WITH_MPI
  if (!joined_ || size_ == 1) return;
  unsigned long size = values->size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG, 0, MPI_COMM_WORLD);
  values->resize(size);
  MPI_Bcast(values->data(), static_cast<int>(size), MPI_DOUBLE, 0, MPI_COMM_WORLD);
#else
  (void)values;
#endif
}

void TileWorld::Send(std::vector<double> message) {
#ifdef LPD_WITH_MPI
  pending_->buffers.push_back(std::move(message));
  const std::vector<double>& buffer = pending_->buffers.back();
  MPI_Request request;
  MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, 0, kMessageTag,
            MPI_COMM_WORLD, &request);
  pending_->requests.push_back(request);
#else
  (void)message;
  throw std::logic_error("TileWorld::Send in a world of one");
#endif
}

bool TileWorld::Receive(bool wait, std::vector<double>* message) {
#ifdef LPD_WITH_MPI
  if (!joined_ || size_ == 1) return false;
  MPI_Status status;
  if (wait) {
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
  } else {
    int arrived = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return false;
  }
  if (status.MPI_TAG == kFailureTag) throw RankFailed();
  int count = 0;
  MPI_Get_count(&status, MPI_DOUBLE, &count);
  message->resize(count);
  MPI_Recv(message->data(), count, MPI_DOUBLE, status.MPI_SOURCE, kMessageTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return true;
#else
  (void)wait;
  (void)message;
  return false;
#endif
}

void TileWorld::Fail(const std::string& message) {
#ifdef LPD_WITH_MPI
  if (joined_) {
    std::fprintf(stderr, "lpd denoise: error: %s\n", message.c_str());
    std::fflush(stderr);
    if (is_root()) Abort();
    int nothing = 0;
    MPI_Send(&nothing, 0, MPI_INT, 0, kFailureTag, MPI_COMM_WORLD);
    // Rank 0 ends the run; this receive never completes.
    MPI_Recv(&nothing, 0, MPI_INT, 0, kFailureTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
#endif
  throw std::runtime_error(message);
}

void TileWorld::Abort() {
#ifdef LPD_WITH_MPI
  if (joined_) MPI_Abort(MPI_COMM_WORLD, 1);
#endif
  std::exit(1);
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

}  // namespace lpd::tiles

// lpd: the processes that share the tiles of a tiled run (solvers/tiling.h).
//
// Started by `mpirun -np R` (Open MPI), the R ranks of MPI_COMM_WORLD: every rank denoises
// its tiles and sends each tile's outcome to rank 0 as soon as it is done, without waiting
// for rank 0 to take it; rank 0 assembles and writes the output. Started without mpirun, this
// process alone (no MPI call is made). Built without MPI (no libopenmpi-dev at configure
// time), always this process alone.
#ifndef LPD_EXPERIMENTS_CLI_TILE_WORLD_H_
#define LPD_EXPERIMENTS_CLI_TILE_WORLD_H_

#include <memory>
#include <string>
#include <vector>

#include "solvers/tiling.h"

namespace lpd::experiments {

class TileWorld {
 public:
  // Joins mpirun's world when this process was started by it (MPI_Init), else a world of one.
  TileWorld();
  ~TileWorld();  // waits for this rank's sends, then MPI_Finalize
  TileWorld(const TileWorld&) = delete;
  TileWorld& operator=(const TileWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }

  // A rank other than 0: hands `tile` (tile number `index`) to rank 0 without blocking.
  void Send(int index, const solvers::TileOutcome& tile);
  // Rank 0: the next outcome another rank sent, if one has arrived (or, with `wait`, once
  // one arrives). False when none is there (never with `wait`).
  bool Receive(bool wait, int* index, solvers::TileOutcome* tile);

  // Ends every rank with exit code 1 (MPI_Abort) after printing `message` on stderr: from
  // this rank with Fail (a failure of this rank's own), from rank 0 only with FailEverywhere
  // (a failure every rank meets alike). In a world of one both throw
  // std::runtime_error(message) instead.
  [[noreturn]] void Fail(const std::string& message);
  [[noreturn]] void FailEverywhere(const std::string& message);

 private:
  int rank_ = 0;
  int size_ = 1;
  bool joined_ = false;
  struct PendingSends;
  std::unique_ptr<PendingSends> pending_;
};

// Whether this binary was built with Open MPI.
bool BuiltWithMpi();

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_CLI_TILE_WORLD_H_

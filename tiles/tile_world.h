// lpd: the processes that share the tiles of a tiled run (solvers/tiling.h).
//
// Started by `mpirun -np R` (Open MPI), the R ranks of MPI_COMM_WORLD: rank 0 broadcasts the
// plan, every rank denoises its tiles and sends each tile's summary to rank 0 as soon as it is
// done, without waiting for rank 0 to take it. Messages are arrays of doubles. Started
// without mpirun, this process alone (no MPI call is made). Built without MPI (no
// libopenmpi-dev at configure time), always this process alone.
#ifndef LPD_TILES_TILE_WORLD_H_
#define LPD_TILES_TILE_WORLD_H_

#include <memory>
#include <string>
#include <vector>


namespace lpd::tiles {

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

  // Rank 0's `values` to every rank (resized on the others).
  void Broadcast(std::vector<double>* values);
  // A rank other than 0: hands `message` to rank 0 without blocking.
  void Send(std::vector<double> message);
  // Rank 0: the next message another rank sent, if one has arrived (or, with `wait`, once
  // one arrives). False when none is there (never with `wait`), and in a world of one.
  // Throws RankFailed when the message is another rank's Fail.
  bool Receive(bool wait, std::vector<double>* message);
  struct RankFailed {};

  // Ends every rank with exit code 1 after printing `message` on stderr. Fail is a failure of
  // this rank's own: on rank 0 it aborts at once (MPI_Abort); another rank tells rank 0 and
  // waits, so that rank 0 can clean up (its next Receive throws RankFailed) before it calls
  // Abort. FailEverywhere is a failure every rank meets alike: rank 0 alone prints it. In a
  // world of one, both throw std::runtime_error(message) instead.
  [[noreturn]] void Fail(const std::string& message);
  [[noreturn]] void FailEverywhere(const std::string& message);
  // Rank 0, after RankFailed: ends every rank with exit code 1 (the failing rank has spoken).
  [[noreturn]] void Abort();

 private:
  int rank_ = 0;
  int size_ = 1;
  bool joined_ = false;
  struct PendingSends;
  std::unique_ptr<PendingSends> pending_;
};

// Whether this binary was built with Open MPI.
bool BuiltWithMpi();

}  // namespace lpd::tiles

#endif  // LPD_TILES_TILE_WORLD_H_

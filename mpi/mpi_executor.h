// The pass schedule's executor over the processes of an MPI job
// (docs/distributed.md): tiles handed out dynamically (mpi/work_dispenser.h),
// and at the reduction points only what the schedule needs:
//
//   avgmax's sum        the exact sums' 256 counts, summed (MPI_Allreduce)
//   completePass1       each tile's border pixels, to the processes that
//                       traced the tiles beside it (MPI_Alltoallv)
//   shareMarks          pass 2's decisions, one bit per pixel (MPI_Allreduce, OR)
//   completeRender      the picture to rank 0 (MPI_Reduce: every pixel is
//                       non-zero on at most one process, so the sum is exact)
//                       and the ray counts (MPI_Reduce, sum)
//
// Every process keeps a film of the whole picture; only rank 0's ends whole.
#pragma once

#include "core/render/process_group.h"

#include <cstdint>
#include <vector>

namespace prism::mpi {

// A slow or failing host, simulated for the tests and the scaling
// benchmark: PRISM_MPI_SIMULATE="rank=R,tile_delay_ms=D,die_after_tiles=N"
// makes rank R wait D ms after each of its items, and kill itself (SIGKILL)
// after its N-th. Unset: nothing is simulated.
struct SimulatedFault {
  int rank = -1;
  int tileDelayMs = 0;
  int dieAfterTiles = 0;
  static SimulatedFault fromEnvironment();
};

class MpiExecutor final : public DistributedExecutor {
public:
  MpiExecutor(Executor& local, int rank, int size, int& calls)
      : local_(local), rank_(rank), size_(size), calls_(calls),
        fault_(SimulatedFault::fromEnvironment()) {}

  int workers() const override { return local_.workers(); }
  void forEach(int itemCount, const ItemWork& work, const StopCheck& stop) override;
  void forEachHere(int itemCount, const ItemWork& work, const StopCheck& stop) override {
    local_.forEach(itemCount, work, stop);
  }
  void sumOverProcesses(ExactSum& sum) override;
  void completePass1(Film& film, std::span<const Tile> tiles,
                     const std::vector<std::uint8_t>& traced) override;
  void shareMarks(std::vector<std::uint8_t>& marks) override;
  void completeRender(Film& film, RayCounts& counts) override;

  int itemsRunHere() const override { return itemsRun_; }
  std::uint64_t raysHere() const override { return raysHere_; }
  void setGroupProgress(GroupProgress progress) override { progress_ = std::move(progress); }

private:
  Executor& local_;
  int rank_, size_;
  int& calls_; // the group's count of collective hand-outs
  SimulatedFault fault_;
  int itemsRun_ = 0;
  std::uint64_t raysHere_ = 0;
  int pass_ = 1;
  GroupProgress progress_;
  std::vector<std::uint8_t> marks_; // pass 2's, once shared
};

} // namespace prism::mpi

// The processes one job runs on: one for a plain `prism render`, N under
// `mpirun -np N` (docs/distributed.md). The core does not know MPI: the
// implementation lives in the module libprism_mpi.so (mpi/), which the
// program loads only when an MPI launcher started it, so a run without MPI
// pays nothing for it.
#pragma once

#include "core/render/executor.h"
#include "core/render/stats.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace prism {

// An executor spread over the processes of a group: forEach hands the items
// out dynamically (a process asks for more when its threads run out), and
// the reduction points exchange what the pass schedule needs.
class DistributedExecutor : public Executor {
public:
  // Items this process ran, over every forEach so far, and the rays it
  // traced (known once the render completes).
  virtual int itemsRunHere() const = 0;
  virtual std::uint64_t raysHere() const = 0;
  // On rank 0: called, from the thread that runs the schedule, as the whole
  // group finishes items: the pass (1 or 2) and the fraction of it done.
  using GroupProgress = std::function<void(int pass, double fraction)>;
  virtual void setGroupProgress(GroupProgress progress) = 0;
};

class ProcessGroup {
public:
  virtual ~ProcessGroup() = default;

  virtual int rank() const = 0;
  virtual int size() const = 0;

  // An executor over the group whose share on this process runs on `local`
  // (which must outlive it).
  virtual std::unique_ptr<DistributedExecutor> makeExecutor(Executor& local) = 0;

  // Collective (every process calls it): the lowest rank whose `ok` is
  // false, with its `message`, on every process; nothing when all are ok.
  struct Failure {
    int rank = 0;
    std::string message;
  };
  virtual std::optional<Failure> firstFailure(bool ok, const std::string& message) = 0;

  // Collective: every process's stats, in rank order, on rank 0 (empty
  // elsewhere).
  virtual std::vector<RankStats> gatherStats(const RankStats& mine) = 0;

  // Collective: items [0, count) run one at a time by whichever process asks
  // first (dynamically, like tiles); each item's `work` returns its result
  // as text. Rank 0 receives every result in item order; the others an empty
  // vector. An exception in `work` ends the whole job (abort). On rank 0,
  // `progress(done, count)`, if given, hears how many items the whole job
  // has finished (from another thread than the one running `work`).
  using DistributeProgress = std::function<void(int done, int total)>;
  virtual std::vector<std::string> distribute(int count,
                                              const std::function<std::string(int)>& work,
                                              const DistributeProgress& progress) = 0;
  std::vector<std::string> distribute(int count, const std::function<std::string(int)>& work) {
    return distribute(count, work, {});
  }

  // Ends every process of the job at once with `status`: for a failure on
  // one process that the others, waiting for it, could not learn of.
  [[noreturn]] virtual void abort(int status) = 0;
};

} // namespace prism

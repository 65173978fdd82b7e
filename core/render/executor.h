// What runs the pass schedule's work items (core/render/pass_schedule.h). The
// schedule is written once and does not know who runs it: the thread pool
// (ThreadPoolExecutor, core/render/parallel.h) for `prism render` and the
// previewer, executors of the tests' own (one worker, items in reverse order)
// to show that the picture does not depend on the order, and the distributed
// executor (mpi/mpi_executor.h) that runs a share of the items on each MPI
// process and exchanges samples at the reduction points below. A distributed
// executor needs pass 1 in one level (render()'s): with coarse levels a
// tile's centres would be traced on several processes.
#pragma once

#include "core/math/exact_sum.h"
#include "core/render/film.h"
#include "core/render/ray_counts.h"
#include "core/render/tile.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace prism {

using ItemWork = std::function<void(int item, int worker)>;
// True when the work should end early (an edit cancelled it).
using StopCheck = std::function<bool()>;

class Executor {
public:
  virtual ~Executor() = default;

  // How many items may run at once: forEach's `worker` lies in [0, workers()),
  // so callers can keep per-worker state without locks.
  virtual int workers() const = 0;

  // Calls work(item, worker) for the items in [0, itemCount) it is in charge
  // of and returns when they have all run, or early once `stop` (if given;
  // checked between items) returns true. Items are independent: they may run
  // in any order, on any worker, at the same time. An exception thrown by
  // `work` ends the others and is rethrown here.
  virtual void forEach(int itemCount, const ItemWork& work, const StopCheck& stop) = 0;

  // Like forEach, but every item on this process's own workers: work on
  // what this process holds (pass 2's decisions for the tiles it traced).
  virtual void forEachHere(int itemCount, const ItemWork& work, const StopCheck& stop) {
    forEach(itemCount, work, stop);
  }

  // Adds the other processes' parts into `sum` (avgmax's sum of maxima, over
  // the tiles each process traced). Nothing to do in shared memory.
  virtual void sumOverProcesses(ExactSum& sum) { (void)sum; }

  // Reduction point 1, after pass 1 (not called without antialiasing,
  // whose picture reads no neighbours). `tiles` are the schedule's work items;
  // `traced[t]` is 1 for the tiles whose centres this process traced. On
  // return `film.centre` must also hold, around each of those tiles, the
  // ring of neighbours' centres that pass 2's decision for its pixels reads.
  // Workers that share the film have written them all already: nothing to
  // do. A distributed executor exchanges the tiles' borders here.
  virtual void completePass1(Film& film, std::span<const Tile> tiles,
                             const std::vector<std::uint8_t>& traced) {
    (void)film;
    (void)tiles;
    (void)traced;
  }

  // Pass 2's decisions (markForSupersampling): on entry those of the pixels
  // of the tiles this process traced, 0 elsewhere; on return every pixel's,
  // for pass 2 may run any tile anywhere. Nothing to do in shared memory.
  virtual void shareMarks(std::vector<std::uint8_t>& marks) { (void)marks; }

  // Reduction point 2, after pass 2. On return `film` (radiance and the
  // supersampled mask) and `counts` (the rays this process's items traced)
  // must be the whole render's wherever the result is used. Nothing to do in
  // shared memory; a distributed executor gathers the samples and sums the
  // counts to the process that writes the picture here.
  virtual void completeRender(Film& film, RayCounts& counts) {
    (void)film;
    (void)counts;
  }
};

} // namespace prism

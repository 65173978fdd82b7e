// What runs the pass schedule's work items (core/render/pass_schedule.h). The
// schedule is written once and does not know who runs it: the thread pool
// (ThreadPoolExecutor, core/render/parallel.h) for `prism render` and the
// previewer, executors of the tests' own (one worker, items in reverse order)
// to show that the picture does not depend on the order, and later a
// distributed (MPI) executor that runs a share of the items on each process
// and exchanges samples at the reduction points below.
#pragma once

#include "core/render/film.h"
#include "core/render/ray_counts.h"

#include <functional>

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

  // Reduction point 1, between pass 1 and avgmax. On return `film.centre`
  // must hold the centre sample of every pixel on this process: avgmax is the
  // mean over all of them, and pass 2's decision reads each pixel's four
  // neighbours, which may lie in tiles another process traced. Workers that
  // share the film have written them all already: nothing to do. A
  // distributed executor gathers (allgathers) the centres here.
  virtual void completePass1(Film& film) { (void)film; }

  // Reduction point 2, after pass 2. On return `film` (radiance and the
  // supersampled mask) and `counts` (the rays this process's items traced)
  // must be the whole render's wherever the result is used. Nothing to do in
  // shared memory; a distributed executor gathers the pass-2 samples and
  // sums the counts to the process that writes the picture here.
  virtual void completeRender(Film& film, RayCounts& counts) {
    (void)film;
    (void)counts;
  }
};

} // namespace prism

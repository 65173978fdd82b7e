// Dynamic scheduling of independent work items over a fixed set of threads:
// each worker takes the next unclaimed item, so uneven tiles balance out.
// Results must not depend on which worker ran an item (they never do here:
// items write disjoint pixels and keep per-worker ray counts).
#pragma once

#include "core/render/executor.h"

#include <functional>

namespace prism {

// Resolves a requested thread count: 0 means every core this process may run
// on (its CPU affinity: all of the machine's unless taskset, a container or
// an MPI launcher's binding restricts it).
int resolveThreadCount(int requested);

// Makes the calling thread yield to interactive threads (a previewer's UI):
// render workers call it so a busy machine still redraws the window on time.
// Idempotent; best effort (does nothing where the system refuses).
void lowerCurrentThreadPriority();

// Calls work(item, worker) for every item in [0, itemCount), worker in
// [0, threads). Returns when all items are done or when `stop` returns true
// (checked before each item).
void parallelFor(int itemCount, int threads, const std::function<void(int item, int worker)>& work,
                 const std::function<bool()>& stop = {});

// The pass schedule's executor on this machine: every item on a pool of
// `threads` threads (parallelFor), all sharing one film, so the reduction
// points have nothing to do. Background workers lower their priority
// (lowerCurrentThreadPriority): the previewer's session renders behind a
// window that must keep redrawing; `prism render` does not.
class ThreadPoolExecutor final : public Executor {
public:
  enum class Priority { Normal, Background };

  explicit ThreadPoolExecutor(int threads, Priority priority = Priority::Normal)
      : threads_(threads), priority_(priority) {}

  int workers() const override { return threads_; }
  void forEach(int itemCount, const ItemWork& work, const StopCheck& stop) override;

private:
  int threads_;
  Priority priority_;
};

} // namespace prism

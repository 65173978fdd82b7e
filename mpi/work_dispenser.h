// Dynamic hand-out of work items [0, count) over the processes of an MPI job
// (docs/distributed.md#scheduling). Rank 0 keeps the next unclaimed item; every
// process's threads take items from a small local queue, which the process's
// main thread refills from rank 0 when it runs low (rank 0 from itself), so
// fast and slow hosts both stay busy until the last items, and a request's
// round trip is hidden behind the items still queued.
//
// All MPI calls are made by the main thread (MPI_THREAD_FUNNELED): it polls
// for messages and sleeps on the local queue between polls (kPollInterval,
// doubling up to kLongestPoll while nothing happens), so it takes no core
// from the threads doing the work; a request's answer is late by at most a
// poll, hidden behind the items still queued.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>

namespace prism::mpi {

// What this process's threads take items from.
class ItemQueue {
public:
  // Blocks until an item is available (returns it) or none will come (-1).
  int take();
  // The worker that took an item finished it.
  void finished();
  // True once the queue is empty and no more items will come.
  bool exhausted();

private:
  friend class WorkDispenser;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<int> items_;
  bool closed_ = false;     // no more items will be added
  int doneSinceReport_ = 0; // finished items not yet reported to rank 0
  bool localDone_ = false;  // the local threads have all returned
};

class WorkDispenser {
public:
  static constexpr auto kPollInterval = std::chrono::microseconds(200);
  static constexpr auto kLongestPoll = std::chrono::microseconds(3200);

  // `call`: the number of this collective hand-out in the job (each process
  // counts its calls; messages of different calls never mix).
  WorkDispenser(int rank, int size, int call) : rank_(rank), size_(size), call_(call) {}

  // Hands items [0, itemCount) out over the job: `runLocal(queue)` runs on a
  // thread of its own and must take items from `queue` until it returns -1
  // on each of `localWorkers` workers, then return. Returns when every
  // process's items are done (all leave together); rethrows at once what
  // `runLocal` threw (the caller must end the job: the others would wait). On rank 0,
  // `progress(done, itemCount)` hears how many items the job has finished.
  void run(int itemCount, int localWorkers, const std::function<void(ItemQueue&)>& runLocal,
           const std::function<void(int done, int total)>& progress = {});

private:
  int rank_, size_, call_;
};

} // namespace prism::mpi

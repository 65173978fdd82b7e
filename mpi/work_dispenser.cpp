#include "mpi/work_dispenser.h"

#include <mpi.h>

#include <algorithm>
#include <exception>
#include <thread>

namespace prism::mpi {

namespace {

// Tags of one call's messages: a request (rank > 0 to rank 0: the items it
// finished since its last request and how many it wants) and a grant (rank 0
// to it: the first item and the count of a range, count 0 meaning "no
// more"). Calls cycle through a range of tags far below MPI's guaranteed
// upper bound of 32767.
int requestTag(int call) { return 1000 + 2 * (call % 4000); }
int grantTag(int call) { return requestTag(call) + 1; }

} // namespace

int ItemQueue::take() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !items_.empty() || closed_; });
  if (items_.empty()) return -1;
  const int item = items_.front();
  items_.pop_front();
  changed_.notify_all(); // the main thread refills when the queue runs low
  return item;
}

void ItemQueue::finished() {
  std::lock_guard lock(mutex_);
  ++doneSinceReport_;
  changed_.notify_all();
}

bool ItemQueue::exhausted() {
  std::lock_guard lock(mutex_);
  return closed_ && items_.empty();
}

void WorkDispenser::run(int itemCount, int localWorkers,
                        const std::function<void(ItemQueue&)>& runLocal,
                        const std::function<void(int, int)>& progress) {
  ItemQueue queue;
  int next = 0;                 // rank 0: the first item not handed out
  int jobDone = 0;              // rank 0: items finished over the job
  int ranksTold = 0;            // rank 0: processes told there are no more
  int reported = -1;            // rank 0: jobDone when progress last heard it
  const int low = localWorkers; // refill below one queued item per worker
  bool asking = false;          // rank > 0: a request is out
  int unreported = 0;           // rank > 0: items finished, for the next request
  int grant[2] = {0, 0};
  int request[2] = {0, 0}; // the request in flight (MPI owns it until sent)
  MPI_Request grantRequest = MPI_REQUEST_NULL, requestRequest = MPI_REQUEST_NULL;

  // The items rank 0 gives out next, contiguous: guided self-scheduling, a
  // share of what remains (1/16 of an even split over the processes) while
  // much remains, so that a picture of cheap tiles costs few round trips,
  // and, toward the end, as many as the process has workers, so that no
  // process holds items another could be running.
  auto grantFrom = [&](int want) {
    const int remaining = itemCount - next;
    const int count = std::min(remaining, std::max({1, want, remaining / (16 * size_)}));
    const int first = next;
    next += count;
    return std::pair{first, count};
  };

  std::exception_ptr failure;
  std::thread local([&] {
    try {
      runLocal(queue);
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard lock(queue.mutex_);
    queue.localDone_ = true;
    queue.closed_ = true; // a failed run takes no more
    queue.changed_.notify_all();
  });

  bool localDone = false; // the local threads have returned
  // The poll interval backs off while nothing happens (a poll costs tens of
  // microseconds of MPI progress), and starts over at every event.
  auto poll = kPollInterval;
  for (;;) {
    int doneNow = 0;
    bool happened = false;
    {
      std::unique_lock lock(queue.mutex_);
      // Sleeps until something local changes or the next poll is due (rank
      // 0, its own threads done, still answers the others' last requests:
      // without a poll interval it would spin).
      queue.changed_.wait_for(lock, poll, [&] {
        return queue.localDone_ != localDone || queue.doneSinceReport_ > 0 ||
               (!queue.closed_ && int(queue.items_.size()) < low && !asking);
      });
      happened = queue.localDone_ != localDone || queue.doneSinceReport_ > 0;
      localDone = queue.localDone_;
      doneNow = queue.doneSinceReport_;
      queue.doneSinceReport_ = 0;
      const bool wantsMore = !queue.closed_ && int(queue.items_.size()) < low;
      if (rank_ == 0) {
        jobDone += doneNow;
        if (wantsMore) {
          const auto [first, count] = grantFrom(localWorkers);
          for (int i = 0; i < count; ++i)
            queue.items_.push_back(first + i);
          if (count == 0) queue.closed_ = true;
          queue.changed_.notify_all();
        }
      } else {
        unreported += doneNow; // reported with the next request
        if (wantsMore && !asking) asking = true;
      }
    }

    if (rank_ == 0) {
      // Every request waiting now, answered at once.
      for (;;) {
        int pending = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, requestTag(call_), MPI_COMM_WORLD, &pending, &status);
        if (!pending) break;
        int asked[2];
        MPI_Recv(asked, 2, MPI_INT, status.MPI_SOURCE, requestTag(call_), MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        jobDone += asked[0];
        const auto [first, count] = grantFrom(asked[1]);
        const int reply[2] = {first, count};
        MPI_Send(reply, 2, MPI_INT, status.MPI_SOURCE, grantTag(call_), MPI_COMM_WORLD);
        if (count == 0) ++ranksTold;
        happened = true;
      }
      if (progress && jobDone != reported) progress(reported = jobDone, itemCount);
      if (localDone && ranksTold == size_ - 1) break;
    } else {
      if (asking && requestRequest == MPI_REQUEST_NULL && grantRequest == MPI_REQUEST_NULL) {
        request[0] = unreported;
        request[1] = localWorkers;
        unreported = 0;
        MPI_Irecv(grant, 2, MPI_INT, 0, grantTag(call_), MPI_COMM_WORLD, &grantRequest);
        MPI_Isend(request, 2, MPI_INT, 0, requestTag(call_), MPI_COMM_WORLD, &requestRequest);
      }
      if (requestRequest != MPI_REQUEST_NULL) {
        int sent = 0;
        MPI_Test(&requestRequest, &sent, MPI_STATUS_IGNORE);
      }
      if (grantRequest != MPI_REQUEST_NULL && requestRequest == MPI_REQUEST_NULL) {
        int granted = 0;
        MPI_Test(&grantRequest, &granted, MPI_STATUS_IGNORE);
        if (granted) {
          asking = false;
          happened = true;
          std::lock_guard lock(queue.mutex_);
          for (int i = 0; i < grant[1]; ++i)
            queue.items_.push_back(grant[0] + i);
          if (grant[1] == 0) queue.closed_ = true;
          queue.changed_.notify_all();
        }
      }
      if (localDone && !asking) break;
    }
    // A process waiting for its answer keeps polling often.
    poll = happened || asking ? kPollInterval : std::min(2 * poll, kLongestPoll);
  }
  local.join();
  // A failure here: the caller ends the job (the others cannot finish
  // without this process's items).
  if (failure) std::rethrow_exception(failure);
  // Items finished after a process's last request were never reported.
  if (rank_ == 0 && progress && reported != itemCount) progress(itemCount, itemCount);
  // Leave together, asleep between polls: a blocking collective next would
  // spin (MPI's progress loop) on every process that finished early.
  MPI_Request together;
  MPI_Ibarrier(MPI_COMM_WORLD, &together);
  for (int left = 0;;) {
    MPI_Test(&together, &left, MPI_STATUS_IGNORE);
    if (left) break;
    std::this_thread::sleep_for(poll);
    poll = std::min(2 * poll, kLongestPoll);
  }
}

} // namespace prism::mpi

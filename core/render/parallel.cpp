#include "core/render/parallel.h"

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace prism {

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  // The cores this process may run on, not the machine's: mpirun binds each
  // rank to its share of the cores (and taskset or a container's cpuset
  // restrict a process), and more threads than that only take turns.
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0)
    return CPU_COUNT(&allowed);
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? int(hardware) : 1;
}

void lowerCurrentThreadPriority() {
  thread_local bool lowered = false;
  if (lowered) return;
  lowered = true;
  // On Linux a nice value applies to the thread whose id is given.
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  setpriority(PRIO_PROCESS, tid, 10);
}

void parallelFor(int itemCount, int threads, const std::function<void(int, int)>& work,
                 const std::function<bool()>& stop) {
  std::atomic<int> next{0};
  // The first exception of any worker (std::bad_alloc, say) stops the others
  // and is rethrown to the caller: one escaping a thread would end the process.
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failureLock;
  auto worker = [&](int id) {
    try {
      for (int item = next++; item < itemCount && !failed; item = next++) {
        if (stop && stop()) return;
        work(item, id);
      }
    } catch (...) {
      const std::lock_guard lock(failureLock);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int id = 1; id < threads; ++id)
      pool.emplace_back(worker, id); // a thread that cannot start throws here
    worker(0);                       // the calling thread works too
  }
  if (failure) std::rethrow_exception(failure);
}

void ThreadPoolExecutor::forEach(int itemCount, const ItemWork& work, const StopCheck& stop) {
  if (priority_ == Priority::Normal) {
    parallelFor(itemCount, threads_, work, stop);
    return;
  }
  parallelFor(
      itemCount, threads_,
      [&](int item, int worker) {
        lowerCurrentThreadPriority(); // once per thread: it remembers
        work(item, worker);
      },
      stop);
}

} // namespace prism

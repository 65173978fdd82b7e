#include "core/parallel.h"

#include <atomic>
#include <thread>
#include <vector>

namespace prism {

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? int(hardware) : 1;
}

void parallelFor(int itemCount, int threads, const std::function<void(int, int)>& work,
                 const std::function<bool()>& stop) {
  std::atomic<int> next{0};
  auto worker = [&](int id) {
    for (int item = next++; item < itemCount; item = next++) {
      if (stop && stop()) return;
      work(item, id);
    }
  };
  std::vector<std::jthread> pool;
  for (int id = 1; id < threads; ++id) pool.emplace_back(worker, id);
  worker(0); // the calling thread works too
}

} // namespace prism

#include "bench/embree/timing.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <vector>

namespace prism::bench {

namespace {

// Passes per turn so that a turn lasts at least `minSeconds`, from one timed pass.
std::size_t passesFor(const Pass& pass, double minSeconds) {
  const double start = threadCpuSeconds();
  volatile std::size_t sink = pass();
  (void)sink;
  const double seconds = std::max(threadCpuSeconds() - start, 1e-6);
  return std::max<std::size_t>(1, std::size_t(std::ceil(minSeconds / seconds)));
}

double turn(const Pass& pass, std::size_t passes, std::size_t raysPerPass) {
  std::size_t hits = 0;
  const double start = threadCpuSeconds();
  for (std::size_t i = 0; i < passes; ++i)
    hits += pass();
  const double seconds = threadCpuSeconds() - start;
  volatile std::size_t sink = hits;
  (void)sink;
  return double(passes * raysPerPass) / seconds;
}

Rate summary(std::vector<double> rates) {
  std::sort(rates.begin(), rates.end());
  const std::size_t n = rates.size();
  return {rates.back(), n % 2 == 1 ? rates[n / 2] : 0.5 * (rates[n / 2 - 1] + rates[n / 2])};
}

} // namespace

double threadCpuSeconds() {
  timespec now{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) != 0)
    throw std::runtime_error("clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

RatePair compareRates(std::size_t raysPerPass, const Pass& prism, const Pass& embree,
                      const TimingOptions& o) {
  if (raysPerPass == 0) return {};
  // The calibrating passes also warm the caches and the branch predictors.
  const std::size_t prismPasses = passesFor(prism, o.minSeconds);
  const std::size_t embreePasses = passesFor(embree, o.minSeconds);
  std::vector<double> prismRates, embreeRates;
  for (int round = 0; round < o.rounds; ++round) {
    // Alternate which goes first, too: a turn may warm the caches for the next.
    if (round % 2 == 0) {
      prismRates.push_back(turn(prism, prismPasses, raysPerPass));
      embreeRates.push_back(turn(embree, embreePasses, raysPerPass));
    } else {
      embreeRates.push_back(turn(embree, embreePasses, raysPerPass));
      prismRates.push_back(turn(prism, prismPasses, raysPerPass));
    }
  }
  return {summary(prismRates), summary(embreeRates)};
}

} // namespace prism::bench

// Timing two engines on the same rays, on the calling thread only: each pass
// over the rays is repeated until it takes long enough to time, and the two
// engines take turns, so that a change in the machine's load (it is shared)
// falls on both rather than on whichever ran second.
#pragma once

#include <cstddef>
#include <functional>

namespace prism::bench {

// Rays per second over the rounds.
struct Rate {
  double best = 0.0;
  double median = 0.0;
};

struct RatePair {
  Rate prism, embree;
};

struct TimingOptions {
  int rounds = 5;          // turns each engine takes
  double minSeconds = 0.5; // a turn lasts at least this long (thread CPU time)
};

// A pass traces every ray of a set once and returns how many hit (so that
// the compiler cannot drop the work).
using Pass = std::function<std::size_t()>;

RatePair compareRates(std::size_t raysPerPass, const Pass& prism, const Pass& embree,
                      const TimingOptions& options);

// Seconds of CPU time of the calling thread: other processes disturb it little.
double threadCpuSeconds();

} // namespace prism::bench

// Rays actually traced, by kind (docs/statistics.md). Each render thread keeps its
// own counts and they are summed at the end, so totals never depend on timing.
#pragma once

#include <cstdint>

namespace prism {

struct RayCounts {
  std::uint64_t eyePrimary = 0;   // pass 1: one per pixel centre
  std::uint64_t eyeAntialias = 0; // pass 2: sixteen per supersampled pixel
  std::uint64_t shadow = 0;
  std::uint64_t reflected = 0;
  std::uint64_t transmitted = 0;
  std::uint64_t tirEvents = 0; // total internal reflections (no ray traced)
  // --bailout: the rays of a depth-1 trace of every pixel centre made first
  // for a lower bound on avgmax (eye and shadow rays), and the mirror and
  // refracted rays it skipped (not traced, not in the total; the rays their
  // trees would have started are not counted at all).
  std::uint64_t bailoutPilot = 0;
  std::uint64_t reflectedSkipped = 0;
  std::uint64_t transmittedSkipped = 0;

  std::uint64_t eye() const { return eyePrimary + eyeAntialias; }
  std::uint64_t total() const { return eye() + shadow + reflected + transmitted + bailoutPilot; }

  RayCounts& operator+=(const RayCounts& o) {
    eyePrimary += o.eyePrimary;
    eyeAntialias += o.eyeAntialias;
    shadow += o.shadow;
    reflected += o.reflected;
    transmitted += o.transmitted;
    tirEvents += o.tirEvents;
    bailoutPilot += o.bailoutPilot;
    reflectedSkipped += o.reflectedSkipped;
    transmittedSkipped += o.transmittedSkipped;
    return *this;
  }
  bool operator==(const RayCounts&) const = default;
};

} // namespace prism

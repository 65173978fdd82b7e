// The rays both engines trace: eye rays through pixel centres, the mirror rays
// and shadow rays from where Prism finds the eye rays hit. Every number in
// them is a float, so Embree (which traces in single precision) and Prism
// (double) are handed exactly the same rays.
#pragma once

#include "core/accel/accel.h"

#include <cstdint>
#include <vector>

namespace prism::bench {

// One query: a ray and the part of it that counts.
struct Query {
  Ray ray;
  Interval range;
};

struct RaySets {
  std::vector<Query> eye;       // closest hit, over the whole ray
  std::vector<Query> secondary; // closest hit: the mirror ray of each eye ray's hit
  std::vector<Query> shadow;    // any hit, ending at the light
};

struct RaySetOptions {
  int width = 0, height = 0; // the eye rays' image (the scene's resolution by default)
  // At most this many eye rays (0: every pixel): a random sample of the
  // pixels drawn with `seed`, kept in scanline order.
  std::size_t maxEyeRays = 0;
  std::uint64_t seed = 1;
};

// The secondary and shadow rays come from `accel`'s hits (Prism's), so both
// engines get the same rays whatever each finds.
RaySets makeRaySets(const Scene& scene, const Accel& accel, const RaySetOptions& options);

} // namespace prism::bench

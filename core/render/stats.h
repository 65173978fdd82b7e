// The statistics every render reports (docs/statistics.md), as text for people (stderr)
// and JSON for programs (--stats-json).
#pragma once

#include "core/render/ray_counts.h"

#include <cstdint>
#include <string>
#include <vector>

namespace prism {

// What one process of a distributed render did (docs/distributed.md).
struct RankStats {
  int rank = 0;
  std::string host;
  int threads = 0;
  int tiles = 0;          // work items it ran, over all passes
  std::uint64_t rays = 0; // rays it traced
  double cpuSeconds = 0.0;
};

struct RenderStats {
  std::string scene;   // the scene file
  std::string machine; // CPU model and architecture
  std::string accel;   // how rays found primitives
  int width = 0;
  int height = 0;
  int maxDepth = 0;
  double thresh = 0.0;
  bool jitter = false;
  bool noAa = false;
  double bailout = 0.0; // W levels; 0: exact
  int threads = 0;
  std::size_t primitives = 0;
  double loadSeconds = 0.0;  // parsing the scene (wall)
  double buildSeconds = 0.0; // building the acceleration structure (wall)
  double cpuSeconds = 0.0;   // rendering: process user + system, all threads (all ranks)
  double wallSeconds = 0.0;  // rendering
  RayCounts counts;
  long long supersampledPixels = 0;
  double avgmax = 0.0;
  std::vector<RankStats> ranks; // one per process of an MPI job; empty for one process

  // Of a distributed render: mean CPU over the largest CPU of the ranks (1
  // when every rank worked as long as the busiest; 0 without ranks).
  double loadBalance() const;

  long long pixels() const { return (long long)width * height; }
  double raysPerPixel() const {
    return pixels() > 0 ? double(counts.total()) / double(pixels()) : 0;
  }
  double supersampledShare() const {
    return pixels() > 0 ? double(supersampledPixels) / double(pixels()) : 0;
  }
};

std::string formatStatsText(const RenderStats& stats);
std::string formatStatsJson(const RenderStats& stats);

} // namespace prism

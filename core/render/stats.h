// The statistics every render reports (docs/statistics.md), as text for people (stderr)
// and JSON for programs (--stats-json).
#pragma once

#include "core/render/ray_counts.h"

#include <string>

namespace prism {

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
  double cpuSeconds = 0.0;   // rendering: process user + system, all threads
  double wallSeconds = 0.0;  // rendering
  RayCounts counts;
  long long supersampledPixels = 0;
  double avgmax = 0.0;

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

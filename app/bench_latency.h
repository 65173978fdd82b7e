// `prism bench --latency`: how quickly the previewer answers a light being
// moved. Measures, on a RenderSession like the one `prism view` drives, the time
// from the edit to the first complete coarse image (one sample per 8x8 block)
// and to the end of pass 1.
#pragma once

#include <string>
#include <vector>

namespace prism {

struct LatencyOptions {
  std::vector<std::string> scenes;
  int width = 640;
  int height = 480;
  int depth = 5;
  int threads = 0; // 0: every core
  int moves = 20;  // light moves measured per scene
};

void benchLatency(const LatencyOptions& options);

} // namespace prism

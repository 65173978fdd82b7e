#include "bench_latency.h"

#include "core/io/scene_parser.h"
#include "core/render/render_session.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace prism {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Spins until `done` holds. A benchmark may poll: it measures the session, it
// does not synchronise with it.
template <class Predicate> void waitUntil(const RenderSession& session, Predicate done) {
  while (!done(session.progress()))
    std::this_thread::yield();
}

struct Summary {
  double median = 0, max = 0;
};

Summary summarise(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v.back()};
}

} // namespace

void benchLatency(const LatencyOptions& o) {
  std::printf("\nPreviewer latency after moving light 1 (%d x %d, depth %d, %d moves per scene)\n",
              o.width, o.height, o.depth, o.moves);
  std::printf("| scene | edit returns (median / max ms) | first coarse image (median / max ms) "
              "| pass 1 complete (median / max ms) |\n|---|---|---|---|\n");
  for (const std::string& file : o.scenes) {
    Scene scene = loadScene(file);
    if (scene.lights.empty()) continue;
    RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.maxDepth = o.depth;
    settings.threads = o.threads;
    RenderSession session(scene, settings);
    // Moves happen while the previous render is still running, as when a user
    // drags a light: each one cancels work in flight.
    waitUntil(session, [](const SessionProgress& p) { return p.pass1Pixels > 0; });
    std::vector<double> edit, coarse, pass1;
    Light light = scene.lights[0];
    for (int i = 0; i < o.moves; ++i) {
      light.position.x += (i % 2 == 0 ? 0.05 : -0.05);
      const auto start = Clock::now();
      session.apply({.lights = {{0, light}}});
      edit.push_back(millisecondsSince(start));
      waitUntil(session, [](const SessionProgress& p) {
        return p.phase != SessionPhase::Coarse || p.level < 8;
      });
      coarse.push_back(millisecondsSince(start));
      waitUntil(session, [](const SessionProgress& p) { return p.phase != SessionPhase::Coarse; });
      pass1.push_back(millisecondsSince(start));
    }
    const Summary e = summarise(edit), c = summarise(coarse), p = summarise(pass1);
    std::printf("| %s | %.1f / %.1f | %.1f / %.1f | %.0f / %.0f |\n",
                std::filesystem::path(file).filename().c_str(), e.median, e.max, c.median, c.max,
                p.median, p.max);
  }
}

} // namespace prism

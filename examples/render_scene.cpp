// prism_example SCENE OUT.tif [--brighter]: renders a scene with the Prism
// library's public API (core/api/prism.h, docs/library.md) at the size the
// scene asks for and writes the picture, as `prism render SCENE -o OUT.tif`
// does with its default settings; prints its progress and the rays it
// traced. With --brighter, every light is made twice as strong first (an
// edit between loading and rendering). Ctrl-C cancels the render cleanly.
// Exit 0 on success, 1 on failure, 130 when cancelled.
#include "core/api/prism.h"

#include <csignal>
#include <cstring>
#include <exception>
#include <iostream>
#include <stop_token>

namespace {

// Ctrl-C asks the render to stop; the render checks between tiles.
std::stop_source stopRender;
volatile std::sig_atomic_t interrupted = 0;

extern "C" void onInterrupt(int) { interrupted = 1; }

} // namespace

int main(int argc, char** argv) {
  namespace api = prism::api;
  const bool brighter = argc == 4 && std::strcmp(argv[3], "--brighter") == 0;
  if (argc != 3 && !brighter) {
    std::cerr << "usage: prism_example SCENE OUT.tif [--brighter]\n";
    return 1;
  }
  std::signal(SIGINT, onInterrupt);
  try {
    api::LoadedScene scene = api::LoadedScene::fromFile(argv[1]);
    for (const std::string& warning : scene.warnings())
      std::cerr << warning << "\n";
    if (brighter)
      for (std::size_t i = 0; i < scene.lights().size(); ++i) {
        prism::Light light = scene.lights()[i];
        light.intensity *= 2.0;
        scene.setLight(i, light);
      }

    api::RenderOptions options; // the scene's size, depth 5, thresh 0.1
    int lastPercent = -1;
    const api::Image image = api::render(
        scene, options,
        [&](const api::Progress& p) {
          // A signal handler may only set a flag; the stop is requested here.
          if (interrupted) stopRender.request_stop();
          const int percent = int(p.fraction * 100.0);
          if (percent / 10 != lastPercent / 10)
            std::cerr << "pass " << p.pass << ": " << percent << "%\n";
          lastPercent = percent;
        },
        stopRender.get_token());

    api::write(argv[2], image);
    std::cerr << image.width << " x " << image.height << ", " << image.stats.counts.total()
              << " rays, avgmax " << image.avgmax << "\n";
  } catch (const api::Cancelled&) {
    std::cerr << "prism_example: cancelled; nothing written\n";
    return 130;
  } catch (const std::exception& error) {
    // A scene error's what() is one FILE:LINE:COLUMN: error: line per problem.
    std::cerr << error.what() << "\n";
    return 1;
  }
  return 0;
}

// Scenes and picture comparisons for tests/extremes_test.cpp: one scene moved
// and scaled anywhere in the world, rendered to the 8-bit picture a user sees.
#pragma once

#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/exposure.h"
#include "core/render/renderer.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace prism::test {

// x -> scale x + offset (the same on every axis): the camera too, which the
// scene language's transforms never move, and the lights' intensities times
// scale^2, so every 1/r^2 term, and with it the picture, stays the same.
struct Placement {
  double scale = 1.0;
  double offset = 0.0;
};

inline void placeCamera(Scene& scene, Placement at) {
  scene.camera.eye = at.scale * scene.camera.eye + Vec3(at.offset);
  scene.camera.lookat = at.scale * scene.camera.lookat + Vec3(at.offset);
  for (Light& light : scene.lights)
    light.intensity *= at.scale * at.scale;
}

// `body` (scene text without a camera) under the placement's transform.
inline Scene placedScene(const std::string& body, Placement at, const std::string& name) {
  std::ostringstream text;
  text.precision(17);
  text << "translate " << at.offset << ' ' << at.offset << ' ' << at.offset << "\nscale "
       << at.scale << ' ' << at.scale << ' ' << at.scale << '\n'
       << body;
  Scene scene = parseScene(text.str(), name);
  placeCamera(scene, at);
  return scene;
}

// A small glass-and-mirror room: a floor, a mirror behind, a glass sphere and
// an open glass tube (a cone) in front, a red ball, a triangle; one light, so every
// object casts a shadow. Units of about 1; ambient 0, so a placed copy with
// its light scaled (Placement) has exactly the same radiance.
inline const char* kGlassAndMirror = R"(
eye 0 1.6 6
lookat 0 0.6 0
up 0 1 0
fov 40
background 0.2 0.3 0.5
light 2.5 6 4  30 30 30
surface 0.9 0.9 0.8  0.8 0 0  1 1
polygon 4  -4 0 -4  4 0 -4  4 0 4  -4 0 4
surface 0.8 0.8 0.9  0.1 0.8 0  30 1
polygon 4  -3 0 -2  3 0 -2  3 3 -2  -3 3 -2
surface 1 1 1  0.02 0.1 0.88  60 1.5
sphere -0.9 0.7 0.6 0.7
cone 0.9 0 1.2 0.3  0.9 1.0 1.2 0.3
surface 0.9 0.2 0.1  0.7 0.3 0  20 1
sphere 0.8 0.45 -0.6 0.45
surface 0.2 0.8 0.3  0.8 0 0  1 1
triangle  -2.5 0.01 -1  -1.5 0.01 -1.2  -2 1.5 -1.5
)";

// The exposed 8-bit picture (RGB, row by row), as `prism render` writes it.
inline std::vector<std::uint8_t> picture(const Scene& scene, RenderSettings settings) {
  const auto accel = makeAccel(scene, AccelKind::Groups);
  const RenderResult r = render(scene, *accel, settings);
  return exposeImage(r.film.radiance, exposureScale(r.avgmax));
}

// How two pictures of the same size differ: the share of pixels whose three
// channels all lie within `levels` of each other, and the largest difference.
struct Agreement {
  double within = 0.0;
  int worst = 0;
};

inline Agreement compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                         int levels) {
  Agreement out;
  std::size_t good = 0;
  for (std::size_t p = 0; p + 2 < a.size(); p += 3) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(int(a[p + c]) - int(b[p + c])));
    good += worst <= levels ? 1 : 0;
    out.worst = std::max(out.worst, worst);
  }
  out.within = double(good) / double(a.size() / 3);
  return out;
}

} // namespace prism::test

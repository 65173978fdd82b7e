// shells: a sea shell of overlapping spheres on sand. The spheres follow a
// conical logarithmic spiral: five turns around a vertical axis, growing by a
// fixed factor per turn, each sphere's radius in proportion to its distance
// from the axis, consecutive ones overlapping heavily. The level is the
// number of spheres; the shell keeps its shape and size, only the spheres
// get denser (N + 1 primitives with the sand).
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr double kTurns = 5, kGrowth = 2.1; // distance from the axis grows by kGrowth a turn
constexpr double kRadiusRatio = 0.6, kHeight = 3.2;

long primitives(int spheres) { return spheres + 1L; }

void write(ScWriter& out, int spheres) {
  out.stage({.eye = {4.2, 5.2, 8.6},
             .lookat = {0, 1.3, 0},
             .fov = 40,
             .lights = {{{6, 10, 6}, 220}, {{-7, 4, 4}, 60}, {{0, 6, -8}, 40}},
             .background = {0.1, 0.15, 0.25},
             .ambient = 0.1});
  out.surface(plastic(0.75, 0.68, 0.5, 0.1, 10)); // sand
  groundSquare(out, 14);
  out.surface({0.95, 0.72, 0.55, 0.6, 0.35, 0, 60, 1}); // pearly
  const double total = 2 * kPi * kTurns, b = std::log(kGrowth) / (2 * kPi);
  for (int i = 0; i < spheres; ++i) {
    const double theta = spheres > 1 ? total * i / (spheres - 1) : total;
    const double rho = 1.6 * std::exp(b * (theta - total)); // 1.6 at the opening
    const double radius = kRadiusRatio * rho;
    // The apex is up; the widest whorl rests on the sand.
    const double y = radius + kHeight * (1 - rho / 1.6);
    out.sphere({rho * std::cos(theta), y, -rho * std::sin(theta)}, radius);
  }
}

} // namespace

SpdKind shellsKind() {
  return {"shells",
          "a sea shell of overlapping spheres on a logarithmic spiral",
          "spheres (N + 1 primitives)",
          2,
          200000,
          primitives,
          write};
}

} // namespace prism::spd

// Pieces several benchmark scenes share: the ground square and the kinds of
// material (matte, plastic, metal, glass) in the terms of `surface`.
#pragma once

#include "sc_writer.h"

namespace prism::spd {

// Diffuse only.
inline Surface matte(double r, double g, double b) { return {r, g, b, 0.8, 0, 0, 1, 1}; }
// Diffuse with a highlight and a weak mirror reflection (ks drives both).
inline Surface plastic(double r, double g, double b, double ks = 0.2, double e = 30) {
  return {r, g, b, 0.7, ks, 0, e, 1};
}
// Mostly mirror, a little of its own colour.
inline Surface metal(double r, double g, double b, double ks = 0.6) {
  return {r, g, b, 0.35, ks, 0, 60, 1};
}
// Clear glass of index 1.5: transmission, a reflection and a highlight.
inline Surface glass() { return {1, 1, 1, 0.02, 0.12, 0.85, 100, 1.5}; }

// A square of side 2 * half at height y, its front facing up (+y).
inline void groundSquare(ScWriter& out, double half, double y = 0) {
  out.polygon({{-half, y, half}, {half, y, half}, {half, y, -half}, {-half, y, -half}});
}

} // namespace prism::spd

// How Prism's shading model is expressed in POV-Ray 3.7's (docs/vs-povray.md):
// the finish numbers of a material and the fade of a point light. Kept apart
// from the writer so that the arithmetic, which is where the two renderers
// differ, can be tested and explained on its own.
#pragma once

#include "core/scene/material.h"

namespace prism {

// A material as POV-Ray's pigment, finish and interior.
struct PovMaterial {
  Color color{1.0};        // pigment rgb
  double transmit = 0.0;   // pigment transmit: the refracted ray's weight (kst)
  double ambient = 0.0;    // finish ambient (times global ambient_light)
  double diffuse = 0.0;    // finish diffuse
  double specular = 0.0;   // finish specular: Blinn highlight, like Prism's
  double roughness = 0.0;  // finish roughness: 1 / exponent (0 when specular is 0)
  double reflection = 0.0; // finish reflection { r }: the mirror ray's weight
  double ior = 1.0;        // interior ior, written only when transmit > 0
  // Absorption as POV-Ray's exponential fade (fade_power 1001), which
  // multiplies a refracted ray by exp(-(1 - fade_color) d / fade_distance)
  // per channel: fade_distance 1 / max sigma and fade_color 1 - sigma /
  // max sigma give exp(-sigma d) exactly. fadeDistance 0: no fade.
  double fadeDistance = 0.0;
  Color fadeColor{1.0};
  // False when POV-Ray cannot show this material as Prism does: a
  // transmitting material (kst >= 1) that also reflects diffusely.
  bool exact = true;
};

PovMaterial povMaterialOf(const Material& m);

// POV-Ray 3.7 scales a light by 2 / (1 + (d / fade_distance)^fade_power);
// with fade_power 2 and the colour multiplied by 1 / (2 fade_distance^2) that
// is I / (d^2 + fade_distance^2): Prism's I / d^2 to a relative error of
// (fade_distance / d)^2. The fade distance is a millionth of the scene's size
// (never below POV-Ray's 1e-10, under which it stops fading altogether).
double povFadeDistance(double sceneSize);
double povLightScale(double fadeDistance); // 1 / (2 fade_distance^2)

} // namespace prism

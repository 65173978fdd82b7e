// The surface model (docs/rendering-model.md): colour, three coefficients, an exponent and an
// index of refraction. Defaults are the `surface` defaults of docs/scene-language.md.
#pragma once

#include "core/math/math.h"
#include "core/texture/image_map.h"
#include "core/texture/texture.h"

namespace prism {

struct Material {
  Color color{1.0}; // C_mat
  double kdr = 1.0; // diffuse reflection
  double ksr = 0.0; // specular reflection (highlight and mirror ray)
  double kst = 0.0; // specular transmission (refracted ray)
  double e = 1.0;   // specular (Phong half-vector) exponent
  double ir = 1.0;  // index of refraction of the solid, air outside
  // Beer-Lambert absorption inside the solid, per unit of world length and
  // per channel (`absorption`): radiance crossing a length d of it is
  // multiplied by exp(-absorption d). Zero (the default) is clear.
  Color absorption{0.0};
  // A procedural texture varying C, kdr, ksr, kst and e over the surface
  // (`texture`, core/scene/material_blend.h); none by default.
  Texture texture{};
  // An image multiplying C over the surface (`image`, image_map.h); after
  // the procedural texture's blend when there are both. None by default.
  ImageMap image{};

  // Whether shading must look anything up at the hit point.
  bool textured() const { return texture.active() || image.active(); }
  bool absorbs() const { return absorption.r > 0.0 || absorption.g > 0.0 || absorption.b > 0.0; }

  bool operator==(const Material&) const = default;
};

} // namespace prism

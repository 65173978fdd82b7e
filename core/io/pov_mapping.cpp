#include "core/io/pov_mapping.h"

#include <algorithm>

namespace prism {

PovMaterial povMaterialOf(const Material& m) {
  PovMaterial p;
  p.color = m.color;
  p.transmit = m.kst;
  // POV-Ray multiplies a surface's own ambient and diffuse light by its
  // opacity, 1 - transmit; Prism does not, so the two are divided by it
  // beforehand. A material that transmits everything has no opacity left to
  // divide by (and POV-Ray refuses a negative diffuse): it keeps kdr and POV
  // shows no diffuse light on it.
  const double opacity = 1.0 - m.kst;
  const double kd = opacity > 0.0 ? m.kdr / opacity : m.kdr;
  p.exact = opacity > 0.0 || m.kdr == 0.0;
  p.ambient = kd;
  p.diffuse = kd;
  // `specular` is the Blinn half-vector highlight, exactly Prism's term
  // (`phong` would be the mirror-vector form). Its exponent is 1 / roughness:
  // e = 0 (a constant highlight) becomes an enormous roughness.
  p.specular = m.ksr;
  if (m.ksr > 0.0) p.roughness = m.e > 0.0 ? std::min(1.0 / m.e, 1e300) : 1e300;
  p.reflection = m.ksr;
  p.ior = m.ir;
  const double strongest = std::max({m.absorption.r, m.absorption.g, m.absorption.b});
  if (strongest > 0.0) {
    p.fadeDistance = 1.0 / strongest;
    p.fadeColor = Color(1.0) - m.absorption / strongest;
  }
  return p;
}

double povFadeDistance(double sceneSize) { return std::max(1e-6 * sceneSize, 1e-9); }

double povLightScale(double fadeDistance) { return 0.5 / (fadeDistance * fadeDistance); }

} // namespace prism

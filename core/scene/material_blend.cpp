#include "core/scene/material_blend.h"

#include "core/texture/pattern.h"

#include <algorithm>

namespace prism {

Material textureAt(const Material& m, const Vec3& p, TextureLookup* lookup) {
  const Texture& t = m.texture;
  if (!t.active()) return m;
  const Vec3 q = t.linear * p + t.offset;
  const double v = patternValue(t.kind, q / t.scale);
  if (lookup != nullptr) *lookup = {q, v};
  return textureBlend(m, v);
}

namespace {
// m with each blended coefficient (C per channel, kdr, ksr, kst, e) made
// op(m's, the texture's), and no texture; m itself when untextured.
template <class Op> Material combineEnds(const Material& m, Op op) {
  const Texture& t = m.texture;
  if (!t.active()) return m;
  Material c = m;
  c.texture = Texture{};
  c.color = {op(m.color.r, t.color.r), op(m.color.g, t.color.g), op(m.color.b, t.color.b)};
  c.kdr = op(m.kdr, t.kdr);
  c.ksr = op(m.ksr, t.ksr);
  c.kst = op(m.kst, t.kst);
  c.e = op(m.e, t.e);
  return c;
}
} // namespace

Material textureBlend(const Material& m, double v) {
  // (1 - v) a + v b rather than a + v (b - a): exactly a at 0 and b at 1,
  // and never negative for non-negative ends. Equal ends stay exact, so a
  // colour texture leaves its coefficients untouched.
  return combineEnds(m, [v](double a, double b) { return a == b ? a : (1.0 - v) * a + v * b; });
}

// An image multiplies C by a lookup between 0 and its peak (the filters are
// weighted averages with non-negative weights).
Material coefficientCeiling(const Material& m) {
  Material c = combineEnds(m, [](double a, double b) { return std::max(a, b); });
  if (m.image.active()) c.color *= m.image.peak;
  c.image = ImageMap{};
  return c;
}

Material coefficientFloor(const Material& m) {
  Material c = combineEnds(m, [](double a, double b) { return std::min(a, b); });
  if (m.image.active()) c.color = Color(0.0);
  c.image = ImageMap{};
  return c;
}

} // namespace prism

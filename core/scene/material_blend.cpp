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

Material textureBlend(const Material& m, double v) {
  const Texture& t = m.texture;
  if (!t.active()) return m;
  Material blended = m;
  blended.texture = Texture{};
  // (1 - v) a + v b rather than a + v (b - a): exactly a at 0 and b at 1,
  // and never negative for non-negative ends. Equal ends stay exact, so a
  // colour texture leaves its coefficients untouched.
  const auto mix = [v](double a, double b) { return a == b ? a : (1.0 - v) * a + v * b; };
  blended.color = {mix(m.color.r, t.color.r), mix(m.color.g, t.color.g), mix(m.color.b, t.color.b)};
  blended.kdr = mix(m.kdr, t.kdr);
  blended.ksr = mix(m.ksr, t.ksr);
  blended.kst = mix(m.kst, t.kst);
  blended.e = mix(m.e, t.e);
  return blended;
}

namespace {
template <class Pick> Material corner(const Material& m, Pick pick) {
  const Texture& t = m.texture;
  if (!t.active()) return m;
  Material c = m;
  c.texture = Texture{};
  c.color = {pick(m.color.r, t.color.r), pick(m.color.g, t.color.g), pick(m.color.b, t.color.b)};
  c.kdr = pick(m.kdr, t.kdr);
  c.ksr = pick(m.ksr, t.ksr);
  c.kst = pick(m.kst, t.kst);
  c.e = pick(m.e, t.e);
  return c;
}
} // namespace

Material coefficientCeiling(const Material& m) {
  return corner(m, [](double a, double b) { return std::max(a, b); });
}

Material coefficientFloor(const Material& m) {
  return corner(m, [](double a, double b) { return std::min(a, b); });
}

} // namespace prism

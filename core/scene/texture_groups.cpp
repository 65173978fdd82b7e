#include "core/scene/texture_groups.h"

#include <array>
#include <cmath>
#include <map>

namespace prism {

namespace {

// `m` without its texture's map: what the members of a group share.
Material withoutMap(Material m) {
  m.texture.linear = Mat3(1.0);
  m.texture.offset = Vec3(0.0);
  return m;
}

// A quick key for the values every material has, so that a scene with many
// textured materials is grouped without comparing each with every group;
// Material's own == then decides (it covers members this key does not).
using Key = std::array<double, 19>;
Key keyOf(const Material& m) {
  const Texture& t = m.texture;
  const ImageMap& image = m.image;
  const Key key{
      m.color.r,           m.color.g,     m.color.b,    m.kdr,     m.ksr,     m.kst, m.e,   m.ir,
      double(t.kind),      t.scale,       t.color.r,    t.color.g, t.color.b, t.kdr, t.ksr, t.kst,
      double(image.image), image.scale.x, image.scale.y};
  Key positive;
  for (std::size_t i = 0; i < key.size(); ++i)
    positive[i] = key[i] + 0.0; // -0 + 0 is +0: == takes them as equal, so must the map
  return positive;
}

} // namespace

std::vector<TextureGroup> textureGroups(const Scene& scene) {
  std::vector<TextureGroup> groups;
  std::vector<Material> shared; // per group: its members without their maps
  std::map<Key, std::vector<std::size_t>> byKey;
  for (std::uint32_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    if (!m.textured()) continue;
    const Material plain = withoutMap(m);
    std::vector<std::size_t>& candidates = byKey[keyOf(plain)];
    std::size_t group = groups.size();
    for (const std::size_t g : candidates)
      if (shared[g] == plain) {
        group = g;
        break;
      }
    if (group == groups.size()) {
      groups.push_back({m.texture.kind, m.image, textureValuesOf(m).scale, {}});
      shared.push_back(plain);
      candidates.push_back(group);
    }
    groups[group].materials.push_back(i);
  }
  return groups;
}

TextureValues textureValuesOf(const Material& m) {
  const double scale =
      m.texture.active() || !m.image.active() ? m.texture.scale : 1.0 / std::abs(m.image.scale.x);
  return {scale, m.texture.color, m.color};
}

void setTextureValues(Material& m, const TextureValues& values, const TextureGroup& group) {
  if (m.texture.active()) {
    m.texture.scale = values.scale;
    m.texture.color = values.color;
  }
  // The files' scale put back makes the factor exactly 1: the files' uv.
  if (group.image.active()) m.image.scale = group.image.scale * (group.scale / values.scale);
  m.color = values.base;
}

Material textureIdentity(Material m) {
  m.texture.scale = 1.0;
  m.texture.color = Color(1.0);
  m.color = Color(1.0);
  if (m.image.active()) {
    m.image.image = 0;
    m.image.peak = Color(1.0);
    m.image.scale = Vec2(1.0);
  }
  return withoutMap(m);
}

} // namespace prism

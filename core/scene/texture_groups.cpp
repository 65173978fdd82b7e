#include "core/scene/texture_groups.h"

#include <array>
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
using Key = std::array<double, 16>;
Key keyOf(const Material& m) {
  const Texture& t = m.texture;
  const Key key{m.color.r,      m.color.g, m.color.b, m.kdr,     m.ksr,     m.kst, m.e,   m.ir,
                double(t.kind), t.scale,   t.color.r, t.color.g, t.color.b, t.kdr, t.ksr, t.kst};
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
    if (!m.texture.active()) continue;
    const Material plain = withoutMap(m);
    std::vector<std::size_t>& candidates = byKey[keyOf(plain)];
    std::size_t group = groups.size();
    for (const std::size_t g : candidates)
      if (shared[g] == plain) {
        group = g;
        break;
      }
    if (group == groups.size()) {
      groups.push_back({m.texture.kind, {}});
      shared.push_back(plain);
      candidates.push_back(group);
    }
    groups[group].materials.push_back(i);
  }
  return groups;
}

TextureValues textureValuesOf(const Material& m) {
  return {m.texture.scale, m.texture.color, m.color};
}

void setTextureValues(Material& m, const TextureValues& values) {
  m.texture.scale = values.scale;
  m.texture.color = values.color;
  m.color = values.base;
}

Material textureIdentity(Material m) {
  setTextureValues(m, TextureValues{});
  return withoutMap(m);
}

} // namespace prism

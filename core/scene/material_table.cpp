#include "core/scene/material_table.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cstring>

namespace prism {

MaterialTable::MaterialTable(std::vector<Material>& materials) : materials_(materials) {
  for (std::uint32_t i = 0; i < materials_.size(); ++i)
    ids_.try_emplace(keyOf(materials_[i]), i);
}

std::uint32_t MaterialTable::intern(const Material& m) {
  const auto [it, inserted] = ids_.try_emplace(keyOf(m), std::uint32_t(materials_.size()));
  if (inserted) materials_.push_back(m);
  return it->second;
}

MaterialTable::Key MaterialTable::keyOf(const Material& m) {
  const Texture& t = m.texture;
  Key key{m.color.r, m.color.g, m.color.b,      m.kdr,          m.ksr,         m.kst,
          m.e,       m.ir,      m.absorption.r, m.absorption.g, m.absorption.b};
  // Zeros for an untextured material (whose texture is the default), and
  // for one without an image.
  if (const ImageMap& i = m.image; i.active()) {
    const double image[8] = {
        double(i.image),       i.scale.x, i.scale.y, i.offset.x, i.offset.y, double(i.wrap),
        i.filtered ? 1.0 : 0.0};
    std::copy(std::begin(image), std::end(image), key.begin() + 11 + 22);
  }
  if (!t.active()) return key;
  const double texture[22] = {double(t.kind), t.scale,        t.color.r,
                              t.color.g,      t.color.b,      t.kdr,
                              t.ksr,          t.kst,          t.e,
                              t.linear[0][0], t.linear[0][1], t.linear[0][2],
                              t.linear[1][0], t.linear[1][1], t.linear[1][2],
                              t.linear[2][0], t.linear[2][1], t.linear[2][2],
                              t.offset.x,     t.offset.y,     t.offset.z};
  std::copy(std::begin(texture), std::end(texture), key.begin() + 11);
  return key;
}

std::size_t MaterialTable::KeyHash::operator()(const Key& key) const {
  std::uint64_t h = 0;
  for (const double v : key) {
    std::uint64_t bits = 0;
    const double positiveZero = v + 0.0; // -0 + 0 is +0
    std::memcpy(&bits, &positiveZero, sizeof bits);
    h = hashCombine(h, bits);
  }
  return std::size_t(h);
}

} // namespace prism

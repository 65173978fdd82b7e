// The one place materials enter a scene: identical materials share one index,
// handed out in the order of first use. Every reader and generator goes
// through it (via SceneBuilder), so a scene read from .sc, NFF or OBJ, or
// written back by `prism convert`, numbers its materials the same way.
#pragma once

#include "core/scene/material.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace prism {

class MaterialTable {
public:
  // Appends to `materials`; those already there are known (the first of
  // identical ones keeps its index), so a table can continue a scene.
  explicit MaterialTable(std::vector<Material>& materials);

  // The index of `m`, appended when no identical material is there yet.
  // Identical means equal values; -0 and 0 are equal.
  std::uint32_t intern(const Material& m);

private:
  using Key = std::array<double, 11 + 22 + 8>; // a texture and an image map too
  // Agrees with the == of Key, which takes -0 and 0 as equal.
  struct KeyHash {
    std::size_t operator()(const Key& key) const;
  };
  static Key keyOf(const Material& m);

  std::vector<Material>& materials_;
  std::unordered_map<Key, std::uint32_t, KeyHash> ids_;
};

} // namespace prism

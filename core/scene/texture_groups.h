// A scene's procedural textures as a user edits them (the previewer,
// docs/previewer.md#textures). One `texture` line becomes a material per
// primitive object space (SceneBuilder composes that space into the
// texture's map), so a scene's textured materials are grouped by everything
// they hold but that map: a group is what one `texture` line under one
// `surface` made, on every primitive it textures. (Two lines with the same
// values under the same surface make one group: nothing tells them apart.)
// An edit of a group changes its scale and both ends' colours on every
// member alike.
#pragma once

#include "core/scene/scene.h"

#include <cstdint>
#include <vector>

namespace prism {

// What an edit of a texture changes.
struct TextureValues {
  double scale = 1.0; // the pattern's size (Texture::scale, > 0)
  Color color{1.0};   // the value-1 end: the `texture` line's R G B (Texture::color)
  Color base{1.0};    // the value-0 end: the material's own colour, its `surface` line's R G B

  bool operator==(const TextureValues&) const = default;
};

struct TextureGroup {
  TextureKind kind = TextureKind::None;
  // Indices into Scene::materials, ascending; never empty. Groups are in the
  // order of their first member.
  std::vector<std::uint32_t> materials;
};

// The textured materials of `scene`, grouped. Take them from a scene as its
// files say it: an edit can make two groups' values alike, after which they
// would be one group.
std::vector<TextureGroup> textureGroups(const Scene& scene);

// A textured material's values, and the same material with `values` put in
// (everything else, the texture's map among it, as it was).
TextureValues textureValuesOf(const Material& m);
void setTextureValues(Material& m, const TextureValues& values);

// `m` without what tells the members of a group apart or what an edit
// changes: its map and its TextureValues set to fixed ones. Two groups with
// equal identities differ only in what a user may have edited.
Material textureIdentity(Material m);

} // namespace prism

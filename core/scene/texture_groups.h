// A scene's textures as a user edits them (the previewer,
// docs/previewer.md#textures): procedural textures and images. One `texture`
// line becomes a material per primitive object space (SceneBuilder composes
// that space into the texture's map), so a scene's textured materials are
// grouped by everything they hold but that map: a group is what one
// `texture` line, or one `image` line, under one `surface` made, on every
// primitive it covers. (Two lines with the same values under the same
// `surface` make one group: nothing tells them apart.) A material with both
// a procedural texture and an image is in one group, which edits both. An
// edit of a group changes its scale and colours on every member alike.
#pragma once

#include "core/scene/scene.h"

#include <cstdint>
#include <vector>

namespace prism {

// What an edit of a texture changes.
struct TextureValues {
  // The texture's size: the pattern's (Texture::scale) when there is a
  // procedural texture; for an image alone, one repeat of the image in
  // surface coordinates, 1 / |SU| of its `uv` line. Always > 0.
  double scale = 1.0;
  Color color{1.0}; // the value-1 end: the `texture` line's R G B (Texture::color); no
                    // meaning for an image alone, whose edits leave it as it is
  Color base{1.0};  // the value-0 end, or the tint an image multiplies: the material's own
                    // colour C_mat, its `surface` line's R G B

  bool operator==(const TextureValues&) const = default;
};

struct TextureGroup {
  TextureKind kind = TextureKind::None; // the procedural texture's; None: an image alone
  // The members' image as the files give it (inactive: none). An edit of
  // the scale sizes it from these values: its `uv` scale is multiplied by
  // `scale` / the edited scale (both axes alike, so the image keeps its
  // aspect; the offset stays, so the image point at the surface's (0, 0)
  // stays there).
  ImageMap image{};
  double scale = 1.0; // TextureValues::scale as the files give it
  // Indices into Scene::materials, ascending; never empty. Groups are in the
  // order of their first member.
  std::vector<std::uint32_t> materials;

  bool imageOnly() const { return kind == TextureKind::None; }
};

// The textured materials of `scene` (those with a procedural texture, an
// image or both), grouped. Take them from a scene as its files say it: an
// edit can make two groups' values alike, after which they would be one
// group, and the group keeps the files' values to size an image from.
std::vector<TextureGroup> textureGroups(const Scene& scene);

// A textured material's values, and a member of `group` with `values` put in
// (everything else, the texture's map among it, as it was). The material
// that results depends on `values` and `group` only, not on what was edited
// before: the files' values put back give the files' material bit for bit.
// (An image's edited size read back may differ from the one put in by a
// rounding: compare materials, not values read back, to see whether an edit
// is shown.)
TextureValues textureValuesOf(const Material& m);
void setTextureValues(Material& m, const TextureValues& values, const TextureGroup& group);

// `m` without what tells the members of a group apart or what an edit
// changes: its map, its TextureValues and its image's scale set to fixed
// ones, and which image it holds (an index into its own scene's library,
// meaningless in another: compare the images' files) set to a fixed one
// when it has an image. Two groups with equal identities and the same image
// file differ only in what a user may have edited.
Material textureIdentity(Material m);

} // namespace prism

// The previewer's edits. A SceneEdit is one change a user makes (a panel
// control, the mouse, a script line); UserEdits is everything the user has
// changed, kept as a layer over the scene file's values, so that a reload can
// put the same layer over the re-read file, a reset can peel one value off,
// and undo can step between layers. No GL, no ImGui.
#pragma once

#include "core/render/render_session.h"
#include "core/scene/scene.h"
#include "core/scene/texture_groups.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace prism {

// The render settings (depth, threshold, jitter; the size follows the file or
// --size). They are not scene values: reloads and resets keep them.
struct SettingsEdit {
  RenderSettings settings;
};
// Light `index` (0-based; the panel says "light index+1"): position and intensity.
struct LightEdit {
  std::size_t index = 0;
  Light light;
};
struct AmbientEdit {
  Color ambient{0.0};
};
// The fog's colour and density (density 0: no fog).
struct FogEdit {
  Fog fog;
};
// Texture `index` (0-based, the panel says "texture index+1": a group of the
// scene's textured materials, core/scene/texture_groups.h): its scale and
// both ends' colours, on every material of the group.
struct TextureEdit {
  std::size_t index = 0;
  TextureValues values;
};
struct CameraEdit {
  CameraSpec camera;
};
// Back to the file's values: one light, one texture, the camera, or every
// scene value.
struct ResetLight {
  std::size_t index = 0;
};
struct ResetTexture {
  std::size_t index = 0;
};
struct ResetCamera {};
struct RevertToFile {}; // camera, ambient, fog, lights and textures; the render settings stay

using SceneEdit = std::variant<SettingsEdit, LightEdit, AmbientEdit, FogEdit, TextureEdit,
                               CameraEdit, ResetLight, ResetTexture, ResetCamera, RevertToFile>;

// A texture as the files give it: its group of materials (indices into
// Scene::materials, as RenderSession::textureGroups() has them), the first of
// them as the file says it, where it is first used, and the file of its
// image if it has one.
struct FileTexture {
  TextureGroup group;
  Material material;
  std::string place;             // "sphere #3 (scene.sc:12)", or "" (only CSG operands use it)
  std::string imagePath;         // as the scene resolved it (ImageInfo::path); "" without an image
  ImageEncoding imageEncoding{}; // as the `image` line asked for it

  TextureValues values() const { return textureValuesOf(material); }
  // What it is, for the panel: "marble", "image tiles.png" (the file's name),
  // "marble and image tiles.png".
  std::string description() const;
};

// The scene values as the files say them: what resets go back to.
struct FileValues {
  CameraSpec camera;
  Color ambient{0.0};
  Fog fog;
  std::vector<Light> lights;
  std::vector<FileTexture> textures; // by 0-based texture number

  // Of a scene as its files give it (no texture edited: they are grouped by
  // their values).
  static FileValues of(const Scene& scene);
};

// Where each texture of `before` is in `after` (the files re-read): the
// texture of the same kind, coefficients, surface and absorption, and the
// same image file, encoding, wrap, filtering and `uv` offset (its scale and
// colours, and the image's `uv` scale, may differ: those are what an edit
// holds), counted in order among the textures alike; none when `after` has
// no such texture.
std::vector<std::optional<std::size_t>> renumberTextures(const FileValues& before,
                                                         const FileValues& after);

// What the user changed: the render settings, and each scene value the user
// edited (an unset value shows the file's).
struct UserEdits {
  RenderSettings settings;
  std::optional<CameraSpec> camera;
  std::optional<Color> ambient;
  std::optional<Fog> fog;
  std::map<std::size_t, Light> lights;           // by 0-based index
  std::map<std::size_t, TextureValues> textures; // by 0-based texture number

  bool sceneEdited() const {
    return camera || ambient || fog || !lights.empty() || !textures.empty();
  }
  // The edited scene values, for the panel: "camera", "ambient", "fog",
  // "light 2", "texture 1", ...
  std::vector<std::string> names() const;
  // The values shown: the file's, with these edits over them.
  CameraSpec cameraOver(const FileValues& file) const { return camera.value_or(file.camera); }
  Color ambientOver(const FileValues& file) const { return ambient.value_or(file.ambient); }
  Fog fogOver(const FileValues& file) const { return fog.value_or(file.fog); }
  Light lightOver(const FileValues& file, std::size_t index) const;
  TextureValues textureOver(const FileValues& file, std::size_t index) const;
  // Puts the edited camera, ambient, fog and lights into `scene` (lights the
  // scene does not have are skipped). Not the textures: a session groups
  // them from the scene it is given, which must have the files' textures
  // (changeToShow edits them after).
  void applyTo(Scene& scene) const;
};

// Equal values, member by member (the core's types have no operator==).
bool operator==(const UserEdits& a, const UserEdits& b);

// `edits` after `edit`, in the scene `file` gives. Throws std::out_of_range
// for a LightEdit or TextureEdit of a light or texture `file` does not have
// (a reset of one is a no-op).
UserEdits withEdit(UserEdits edits, const SceneEdit& edit, const FileValues& file);

// What a session showing `shown` with `shownSettings` must change to show
// `edits` over `file`: only the values that differ (empty when none does).
// The session's texture groups must be file.textures' (as they are when it
// was given the scene `file` was taken from).
SessionEdit changeToShow(const UserEdits& edits, const FileValues& file, const Scene& shown,
                         const RenderSettings& shownSettings);

} // namespace prism

// The previewer's edits. A SceneEdit is one change a user makes (a panel
// control, the mouse, a script line); UserEdits is everything the user has
// changed, kept as a layer over the scene file's values, so that a reload can
// put the same layer over the re-read file, a reset can peel one value off,
// and undo can step between layers. No GL, no ImGui.
#pragma once

#include "core/render/render_session.h"
#include "core/scene/scene.h"

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
struct CameraEdit {
  CameraSpec camera;
};
// Back to the file's values: one light, the camera, or every scene value.
struct ResetLight {
  std::size_t index = 0;
};
struct ResetCamera {};
struct RevertToFile {}; // camera, ambient, fog and lights; the render settings stay

using SceneEdit = std::variant<SettingsEdit, LightEdit, AmbientEdit, FogEdit, CameraEdit,
                               ResetLight, ResetCamera, RevertToFile>;

// The scene values as the files say them: what resets go back to.
struct FileValues {
  CameraSpec camera;
  Color ambient{0.0};
  Fog fog;
  std::vector<Light> lights;

  static FileValues of(const Scene& scene) {
    return {scene.camera, scene.ambient, scene.fog, scene.lights};
  }
};

// What the user changed: the render settings, and each scene value the user
// edited (an unset value shows the file's).
struct UserEdits {
  RenderSettings settings;
  std::optional<CameraSpec> camera;
  std::optional<Color> ambient;
  std::optional<Fog> fog;
  std::map<std::size_t, Light> lights; // by 0-based index

  bool sceneEdited() const { return camera || ambient || fog || !lights.empty(); }
  // The edited scene values, for the panel: "camera", "ambient", "fog", "light 2", ...
  std::vector<std::string> names() const;
  // The values shown: the file's, with these edits over them.
  CameraSpec cameraOver(const FileValues& file) const { return camera.value_or(file.camera); }
  Color ambientOver(const FileValues& file) const { return ambient.value_or(file.ambient); }
  Fog fogOver(const FileValues& file) const { return fog.value_or(file.fog); }
  Light lightOver(const FileValues& file, std::size_t index) const;
  // Puts the edited camera, ambient, fog and lights into `scene` (lights the scene
  // does not have are skipped).
  void applyTo(Scene& scene) const;
};

// Equal values, member by member (the core's types have no operator==).
bool operator==(const UserEdits& a, const UserEdits& b);

// `edits` after `edit`. Throws std::out_of_range for a LightEdit of a light
// past `lightCount` (a ResetLight of one is a no-op).
UserEdits withEdit(UserEdits edits, const SceneEdit& edit, std::size_t lightCount);

// What a session showing `shown` with `shownSettings` must change to show
// `edits` over `file`: only the values that differ (empty when none does).
SessionEdit changeToShow(const UserEdits& edits, const FileValues& file, const Scene& shown,
                         const RenderSettings& shownSettings);

} // namespace prism

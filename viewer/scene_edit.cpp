#include "scene_edit.h"

#include <algorithm>
#include <stdexcept>

namespace prism {

namespace {

bool same(const CameraSpec& a, const CameraSpec& b) {
  return a.eye == b.eye && a.lookat == b.lookat && a.up == b.up && a.fov == b.fov;
}

bool same(const Light& a, const Light& b) {
  return a.position == b.position && a.intensity == b.intensity;
}

bool same(const Fog& a, const Fog& b) { return a.color == b.color && a.density == b.density; }

// Both unset, or both set to the same value.
template <class T> bool same(const std::optional<T>& a, const std::optional<T>& b) {
  return a.has_value() == b.has_value() && (!a || same(*a, *b));
}

bool same(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.maxDepth == b.maxDepth &&
         a.thresh == b.thresh && a.jitter == b.jitter && a.noAa == b.noAa &&
         a.bailout == b.bailout && a.threads == b.threads && a.tileSize == b.tileSize;
}

template <class... F> struct Overloaded : F... { using F::operator()...; };

} // namespace

std::vector<std::string> UserEdits::names() const {
  std::vector<std::string> names;
  if (camera) names.push_back("camera");
  if (ambient) names.push_back("ambient");
  if (fog) names.push_back("fog");
  for (const auto& [index, light] : lights)
    names.push_back("light " + std::to_string(index + 1));
  return names;
}

Light UserEdits::lightOver(const FileValues& file, std::size_t index) const {
  const auto it = lights.find(index);
  return it != lights.end() ? it->second : file.lights.at(index);
}

void UserEdits::applyTo(Scene& scene) const {
  if (camera) scene.camera = *camera;
  if (ambient) scene.ambient = *ambient;
  if (fog) scene.fog = *fog;
  for (const auto& [index, light] : lights)
    if (index < scene.lights.size()) scene.lights[index] = light;
}

bool operator==(const UserEdits& a, const UserEdits& b) {
  return same(a.settings, b.settings) && same(a.camera, b.camera) && a.ambient == b.ambient &&
         same(a.fog, b.fog) &&
         std::equal(a.lights.begin(), a.lights.end(), b.lights.begin(), b.lights.end(),
                    [](const auto& x, const auto& y) {
                      return x.first == y.first && same(x.second, y.second);
                    });
}

UserEdits withEdit(UserEdits edits, const SceneEdit& edit, std::size_t lightCount) {
  std::visit(Overloaded{
                 [&](const SettingsEdit& e) { edits.settings = e.settings; },
                 [&](const LightEdit& e) {
                   if (e.index >= lightCount)
                     throw std::out_of_range("light " + std::to_string(e.index + 1) +
                                             " does not exist: the scene has " +
                                             std::to_string(lightCount));
                   edits.lights[e.index] = e.light;
                 },
                 [&](const AmbientEdit& e) { edits.ambient = e.ambient; },
                 [&](const FogEdit& e) { edits.fog = e.fog; },
                 [&](const CameraEdit& e) { edits.camera = e.camera; },
                 [&](const ResetLight& e) { edits.lights.erase(e.index); },
                 [&](const ResetCamera&) { edits.camera.reset(); },
                 [&](const RevertToFile&) {
                   edits.camera.reset();
                   edits.ambient.reset();
                   edits.fog.reset();
                   edits.lights.clear();
                 },
             },
             edit);
  return edits;
}

SessionEdit changeToShow(const UserEdits& edits, const FileValues& file, const Scene& shown,
                         const RenderSettings& shownSettings) {
  SessionEdit change;
  if (!same(edits.settings, shownSettings)) change.settings = edits.settings;
  if (const CameraSpec camera = edits.cameraOver(file); !same(camera, shown.camera))
    change.camera = camera;
  if (const Color ambient = edits.ambientOver(file); ambient != shown.ambient)
    change.ambient = ambient;
  if (const Fog fog = edits.fogOver(file); !same(fog, shown.fog)) change.fog = fog;
  for (std::size_t i = 0; i < shown.lights.size(); ++i)
    if (const Light light = edits.lightOver(file, i); !same(light, shown.lights[i]))
      change.lights.emplace_back(i, light);
  return change;
}

} // namespace prism

#include "scene_edit.h"

#include "core/texture/image_library.h"

#include <algorithm>
#include <filesystem>
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
// The C++17 guide: Clang before 17 does not deduce an aggregate's arguments (P1816).
template <class... F> Overloaded(F...) -> Overloaded<F...>;

// Where each texture is first used: the first primitive (in the order of the
// kinds) whose material is one of its group's.
std::vector<std::string> placesOf(const Scene& scene, const std::vector<TextureGroup>& groups) {
  std::vector<std::string> places(groups.size());
  if (groups.empty()) return places;
  std::vector<std::size_t> groupOf(scene.materials.size(), groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (const std::uint32_t m : groups[g].materials)
      groupOf[m] = g;
  std::size_t left = groups.size();
  for (const PrimitiveRef ref : scene.allPrimitives()) {
    const std::size_t g = groupOf[scene.materialIndex(ref)];
    if (g == groups.size() || !places[g].empty()) continue;
    places[g] = scene.describe(ref);
    if (--left == 0) break;
  }
  return places;
}

} // namespace

FileValues FileValues::of(const Scene& scene) {
  FileValues file{scene.camera, scene.ambient, scene.fog, scene.lights, {}};
  const std::vector<TextureGroup> groups = textureGroups(scene);
  std::vector<std::string> places = placesOf(scene, groups);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    FileTexture texture{groups[g], scene.materials[groups[g].materials.front()],
                        std::move(places[g]), "", ImageEncoding::Auto};
    if (groups[g].image.active() && scene.images) {
      const ImageInfo& info = scene.images->info(groups[g].image.image);
      texture.imagePath = info.path;
      texture.imageEncoding = info.asked;
    }
    file.textures.push_back(std::move(texture));
  }
  return file;
}

std::string FileTexture::description() const {
  const std::string image = "image " + std::filesystem::path(imagePath).filename().string();
  if (group.imageOnly()) return image;
  const std::string kind(textureKindName(group.kind));
  return group.image.active() ? kind + " and " + image : kind;
}

std::vector<std::optional<std::size_t>> renumberTextures(const FileValues& before,
                                                         const FileValues& after) {
  std::vector<std::optional<std::size_t>> to(before.textures.size());
  std::vector<bool> taken(after.textures.size(), false);
  // An image is an index into its own scene's library: compare the files.
  const auto alike = [](const FileTexture& a, const FileTexture& b) {
    return textureIdentity(a.material) == textureIdentity(b.material) &&
           a.imagePath == b.imagePath && a.imageEncoding == b.imageEncoding;
  };
  for (std::size_t i = 0; i < before.textures.size(); ++i) {
    for (std::size_t j = 0; j < after.textures.size(); ++j) {
      if (taken[j] || !alike(before.textures[i], after.textures[j])) continue;
      to[i] = j; // textures alike pair off in order
      taken[j] = true;
      break;
    }
  }
  return to;
}

std::vector<std::string> UserEdits::names() const {
  std::vector<std::string> names;
  if (camera) names.push_back("camera");
  if (ambient) names.push_back("ambient");
  if (fog) names.push_back("fog");
  for (const auto& [index, light] : lights)
    names.push_back("light " + std::to_string(index + 1));
  for (const auto& [index, values] : textures)
    names.push_back("texture " + std::to_string(index + 1));
  return names;
}

Light UserEdits::lightOver(const FileValues& file, std::size_t index) const {
  const auto it = lights.find(index);
  return it != lights.end() ? it->second : file.lights.at(index);
}

TextureValues UserEdits::textureOver(const FileValues& file, std::size_t index) const {
  const auto it = textures.find(index);
  return it != textures.end() ? it->second : file.textures.at(index).values();
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
                    }) &&
         a.textures == b.textures;
}

UserEdits withEdit(UserEdits edits, const SceneEdit& edit, const FileValues& file) {
  const auto exists = [](const char* what, std::size_t index, std::size_t count) {
    if (index >= count)
      throw std::out_of_range(std::string(what) + " " + std::to_string(index + 1) +
                              " does not exist: the scene has " + std::to_string(count));
  };
  std::visit(Overloaded{
                 [&](const SettingsEdit& e) { edits.settings = e.settings; },
                 [&](const LightEdit& e) {
                   exists("light", e.index, file.lights.size());
                   edits.lights[e.index] = e.light;
                 },
                 [&](const AmbientEdit& e) { edits.ambient = e.ambient; },
                 [&](const FogEdit& e) { edits.fog = e.fog; },
                 [&](const TextureEdit& e) {
                   exists("texture", e.index, file.textures.size());
                   edits.textures[e.index] = e.values;
                 },
                 [&](const CameraEdit& e) { edits.camera = e.camera; },
                 [&](const ResetLight& e) { edits.lights.erase(e.index); },
                 [&](const ResetTexture& e) { edits.textures.erase(e.index); },
                 [&](const ResetCamera&) { edits.camera.reset(); },
                 [&](const RevertToFile&) {
                   edits.camera.reset();
                   edits.ambient.reset();
                   edits.fog.reset();
                   edits.lights.clear();
                   edits.textures.clear();
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
  // Materials compared, not values read back (an image's size read back may
  // be a rounding off the one put in): what the edit makes of the first
  // member as the file gives it, against the shown one.
  for (std::size_t i = 0; i < file.textures.size(); ++i) {
    const FileTexture& texture = file.textures[i];
    const TextureValues values = edits.textureOver(file, i);
    Material wanted = texture.material;
    setTextureValues(wanted, values, texture.group);
    if (!(wanted == shown.materials[texture.group.materials.front()]))
      change.textures.emplace_back(i, values);
  }
  return change;
}

} // namespace prism

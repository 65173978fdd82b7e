#include "info_command.h"

#include "cli_options.h"
#include "render_command.h"

#include "core/io/scene_loader.h"
#include "core/io/scene_text.h"
#include "core/math/aabb.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <iostream>
#include <optional>
#include <vector>

namespace prism {

namespace {

// The shortest text that reads back as exactly `x`.
std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string point(const Vec3& v) {
  return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

nlohmann::ordered_json jsonPoint(const Vec3& v) { return {v.x, v.y, v.z}; }

// The box around every primitive (each as Scene::bounds gives it, unpadded);
// nothing for a scene without primitives.
std::optional<Aabb> sceneBounds(const Scene& scene) {
  Aabb box;
  for (const PrimitiveRef ref : scene.allPrimitives())
    box.extend(scene.bounds(ref));
  if (box.empty()) return std::nullopt;
  return box;
}

// Each kind the scene has, by its name in messages and the ray tree (kName),
// with its count.
std::vector<std::pair<std::string, std::size_t>> kindCounts(const Scene& scene) {
  std::vector<std::pair<std::string, std::size_t>> counts;
  const auto add = [&]<class Kind>(const std::vector<Kind>& all) {
    if (!all.empty()) counts.emplace_back(Kind::kName, all.size());
  };
  std::apply([&](const auto&... all) { (add(all), ...); }, scene.storage.vectors);
  return counts;
}

struct MaterialCounts {
  std::size_t textured = 0; // a procedural `texture`
  std::size_t imaged = 0;   // an `image`
  std::size_t absorbing = 0;
};

MaterialCounts materialCounts(const Scene& scene) {
  MaterialCounts counts;
  for (const Material& m : scene.materials) {
    counts.textured += m.texture.active() ? 1 : 0;
    counts.imaged += m.image.active() ? 1 : 0;
    counts.absorbing += m.absorbs() ? 1 : 0;
  }
  return counts;
}

std::size_t imageCount(const Scene& scene) { return scene.images ? scene.images->size() : 0; }

nlohmann::ordered_json describeJson(const std::string& path, const Scene& scene,
                                    const std::vector<Diagnostic>& warnings) {
  using Json = nlohmann::ordered_json;
  Json kinds = Json::object();
  for (const auto& [name, count] : kindCounts(scene))
    kinds[name] = count;
  Json images = Json::array();
  for (std::uint32_t i = 0; i < imageCount(scene); ++i) {
    const ImageInfo& image = scene.images->info(i);
    images.push_back(Json{{"path", image.path}, {"width", image.width}, {"height", image.height}});
  }
  const MaterialCounts materials = materialCounts(scene);
  Json bounds = nullptr;
  if (const std::optional<Aabb> box = sceneBounds(scene))
    bounds = {{"min", jsonPoint(box->lo)}, {"max", jsonPoint(box->hi)}};
  Json warningList = Json::array();
  for (const Diagnostic& d : warnings)
    warningList.push_back(
        Json{{"file", d.file}, {"line", d.line}, {"column", d.column}, {"message", d.message}});
  return {
      {"scene", path},
      {"files", scene.files},
      {"width", scene.width},
      {"height", scene.height},
      {"camera",
       {{"eye", jsonPoint(scene.camera.eye)},
        {"lookat", jsonPoint(scene.camera.lookat)},
        {"up", jsonPoint(scene.camera.up)},
        {"fov", scene.camera.fov}}},
      {"primitives", scene.primitiveCount()},
      {"kinds", kinds},
      {"lights", scene.lights.size()},
      {"materials", scene.materials.size()},
      {"textured_materials", materials.textured},
      {"image_materials", materials.imaged},
      {"absorbing_materials", materials.absorbing},
      {"images", images},
      {"bounds", bounds},
      {"warnings", warningList},
  };
}

void describeText(const std::string& path, const Scene& scene,
                  const std::vector<Diagnostic>& warnings) {
  std::ostream& out = std::cout;
  out << "scene       " << printable(path);
  if (scene.files.size() > 1) out << " (and " << scene.files.size() - 1 << " included files)";
  out << "\nimage       " << scene.width << " x " << scene.height << "\n";
  const CameraSpec& c = scene.camera;
  out << "camera      eye " << point(c.eye) << ", lookat " << point(c.lookat) << ", up "
      << point(c.up) << ", fov " << number(c.fov) << "\n";
  const std::string kinds = scene.kindCounts(); // "3 spheres, 2 polygons"
  out << "primitives  " << scene.primitiveCount() << (kinds.empty() ? "" : ": " + kinds) << "\n";
  out << "lights      " << scene.lights.size() << "\n";
  const MaterialCounts m = materialCounts(scene);
  out << "materials   " << scene.materials.size() << " (" << m.textured << " textured, " << m.imaged
      << " with an image, " << m.absorbing << " absorbing)\n";
  out << "images      " << imageCount(scene) << "\n";
  for (std::uint32_t i = 0; i < imageCount(scene); ++i) {
    const ImageInfo& image = scene.images->info(i);
    out << "  " << printable(image.path) << " " << image.width << " x " << image.height << "\n";
  }
  if (const std::optional<Aabb> box = sceneBounds(scene))
    out << "bounds      " << point(box->lo) << " to " << point(box->hi) << "\n";
  else
    out << "bounds      none (no primitives)\n";
  out << "warnings    " << warnings.size() << "\n";
  for (const Diagnostic& d : warnings)
    out << "  " << printable(formatWarning(d)) << "\n";
}

} // namespace

CLI::App* addInfoCommand(CLI::App& app, InfoCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "info", "Read a scene and describe it (primitives, lights, materials, camera, bounds, "
              "warnings) without rendering; exit 2 on scene errors");
  cmd->alias("check");
  addSceneArgument(*cmd, o.scene);
  cmd->add_flag("--json", o.json, "Print the description as JSON");
  return cmd;
}

int runInfoCommand(const InfoCommandOptions& o) {
  std::vector<Diagnostic> warnings;
  std::optional<Scene> scene;
  try {
    scene = loadAnyScene(o.scene, &warnings);
  } catch (const SceneError& error) {
    for (const Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    return kExitUsage;
  }
  if (o.json)
    std::cout << describeJson(o.scene, *scene, warnings)
                     .dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace)
              << "\n";
  else
    describeText(o.scene, *scene, warnings);
  return kExitOk;
}

} // namespace prism

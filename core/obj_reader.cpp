#include "core/obj_reader.h"

#include "core/import_common.h"
#include "core/obj_scan.h"
#include "core/scene_text.h"
#include "core/triangulate.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <sstream>

namespace prism {

namespace {

// An OBJ of a few million triangles is a few hundred MiB of text.
constexpr std::size_t kMaxObjBytes = std::size_t(2) << 30;

// Faces without `usemtl` (or all faces of an OBJ without materials): a light
// grey, diffuse only.
Material defaultMaterial() { return Material{Color(0.8), 1.0, 0.0, 0.0, 1.0, 1.0}; }

// tinyobjloader's messages are free text, one per line; some name a line
// ("... line 12 ...", "(line 12.)"). Each becomes a Diagnostic at that line,
// or at the start of the file when it names none.
// The number after the first "line" (and an optional ':' and spaces), if any.
int lineNamedIn(const std::string& message) {
  const std::size_t at = message.find("line");
  if (at == std::string::npos) return 1;
  std::size_t i = at + 4;
  if (i < message.size() && message[i] == ':') ++i;
  while (i < message.size() && message[i] == ' ')
    ++i;
  long long line = 0;
  for (; i < message.size() && message[i] >= '0' && message[i] <= '9'; ++i) {
    line = std::min(line * 10 + (message[i] - '0'), 1'000'000'000LL);
  }
  return line > 0 ? int(line) : 1;
}

std::vector<Diagnostic> fromTinyObj(const std::string& text, const std::string& file) {
  std::vector<Diagnostic> out;
  std::istringstream lines(text);
  std::string message;
  while (std::getline(lines, message)) {
    while (!message.empty() && (message.back() == '\r' || message.back() == ' '))
      message.pop_back();
    if (message.empty() || message == ".") continue;
    out.push_back({file, lineNamedIn(message), 1, "tinyobjloader: " + message});
  }
  return out;
}

MtlValues valuesOf(const tinyobj::material_t& m, bool illumGiven) {
  MtlValues v;
  v.kd = Color(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
  v.ks = Color(m.specular[0], m.specular[1], m.specular[2]);
  v.ns = m.shininess;
  v.ni = m.ior;
  v.dissolve = m.dissolve;
  // Without `illum` the file asks for nothing in particular: the usual model
  // 2 (diffuse and highlight), as most viewers assume.
  v.illum = illumGiven ? m.illum : 2;
  return v;
}

// Light placed relative to the mesh: a key light above, left and in front,
// and a weaker fill from the right, each compensated for 1/r^2 so that it
// delivers its nominal intensity (1 and 0.35) at the mesh's centre; ambient
// 0.1 so that what neither reaches is not black.
void addDefaultLights(Scene& scene, const Aabb& box) {
  const Vec3 centre = box.centroid();
  const double radius = std::max(0.5 * glm::length(box.extent()), 1e-300);
  const struct {
    Vec3 direction;
    double intensity;
  } kLights[] = {{Vec3(-2.0, 3.0, 4.0), 1.0}, {Vec3(3.0, 1.0, 2.0), 0.35}};
  for (const auto& l : kLights) {
    // Far enough (ten radii) that 1/r^2 barely varies across the mesh.
    const Vec3 offset = 10.0 * radius * glm::normalize(l.direction);
    scene.lights.push_back(
        {centre + offset, falloffCompensated(Color(l.intensity), glm::length(offset))});
  }
  scene.ambient = Color(0.1);
  // A mid-grey backdrop: automatic exposure scales by the image's mean, and a
  // black one would leave a small object overexposed.
  scene.background = Color(0.4);
}

} // namespace

Material materialFromMtl(const MtlValues& mtl) {
  Material m;
  const double d = std::clamp(mtl.dissolve, 0.0, 1.0);
  m.color = mtl.kd;
  m.kdr = d;
  // Prism's ksr drives both the highlight and the mirror ray; MTL's Ks is a
  // colour, Prism's highlight takes the light's colour: its mean is used.
  m.ksr = mtl.illum <= 1 ? 0.0 : (mtl.ks.r + mtl.ks.g + mtl.ks.b) / 3.0;
  m.kst = 1.0 - d;
  m.e = std::max(mtl.ns, 0.0);
  m.ir = mtl.ni > 0.0 ? mtl.ni : 1.0;
  return m;
}

Scene loadObj(const std::filesystem::path& path, std::vector<Diagnostic>* warnings) {
  const std::string name = path.string();
  ObjScan scan;
  {
    std::string text;
    if (const std::optional<std::string> problem = readFile(path, false, text, kMaxObjBytes)) {
      throw SceneError({Diagnostic{name, 1, 1, "cannot read file: " + *problem}});
    }
    scan = scanObj(text, name, path.parent_path());
  } // the text is freed before tinyobjloader builds its arrays
  if (!scan.errors.empty()) throw SceneError(std::move(scan.errors));

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::string directory = path.parent_path().string();
  if (directory.empty()) directory = ".";
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, name.c_str(),
                                   directory.c_str(), /*triangulate=*/false);
  if (!ok || !err.empty()) {
    std::vector<Diagnostic> errors = fromTinyObj(err, name);
    if (errors.empty()) errors.push_back({name, 1, 1, "tinyobjloader could not read the file"});
    throw SceneError(std::move(errors));
  }
  if (warnings != nullptr) {
    for (Diagnostic& d : fromTinyObj(warn, name))
      warnings->push_back(std::move(d));
  }

  Scene scene;
  scene.files.push_back(name);
  // Listed so that the previewer reloads when a material file changes too.
  for (const std::string& library : scan.materialLibraries)
    scene.files.push_back(library);
  scene.meshVertices.resize(attrib.vertices.size() / 3);
  for (std::size_t i = 0; i < scene.meshVertices.size(); ++i) {
    scene.meshVertices[i] =
        Vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  }
  // A zero or unusable normal cannot be interpolated: a face using one is flat.
  std::vector<bool> usable(attrib.normals.size() / 3);
  scene.meshNormals.resize(attrib.normals.size() / 3);
  for (std::size_t i = 0; i < scene.meshNormals.size(); ++i) {
    const Vec3 n(attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]);
    const double scale = maxAbsComponent(n);
    usable[i] = scale > 0.0 && std::isfinite(scale);
    scene.meshNormals[i] = usable[i] ? glm::normalize(n / scale) : Vec3(0.0, 0.0, 1.0);
  }
  attrib = tinyobj::attrib_t{};

  // Materials are stored when a face first uses them, as in .sc scenes.
  MaterialTable table(scene);
  std::vector<std::optional<std::uint32_t>> materialIds(materials.size());
  std::optional<std::uint32_t> fallback;
  const auto materialOf = [&](int id) {
    if (id < 0 || std::size_t(id) >= materials.size()) {
      if (!fallback) fallback = table.intern(defaultMaterial());
      return *fallback;
    }
    std::optional<std::uint32_t>& slot = materialIds[std::size_t(id)];
    if (!slot) {
      const tinyobj::material_t& m = materials[std::size_t(id)];
      const auto it = scan.materials.find(m.name);
      slot = table.intern(materialFromMtl(valuesOf(m, it != scan.materials.end() && it->second)));
    }
    return *slot;
  };

  scene.triangles.reserve(scan.triangles);
  std::size_t face = 0, dropped = 0;
  std::vector<Vec3> corners;
  for (const tinyobj::shape_t& shape : shapes) {
    // Each OBJ object or group is a group of the scene (the hint `--accel
    // groups` builds on).
    const auto group = std::uint32_t(scene.groups.size());
    scene.groups.push_back(Group{});
    scene.groups[0].children.push_back(group);
    const tinyobj::mesh_t& mesh = shape.mesh;
    std::size_t index = 0;
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++face) {
      const std::size_t count = mesh.num_face_vertices[f];
      const Origin origin{0, face < scan.faceLines.size() ? scan.faceLines[face] : 0};
      if (f == 0) scene.groups[group].origin = origin;
      const std::uint32_t material =
          materialOf(f < mesh.material_ids.size() ? mesh.material_ids[f] : -1);
      bool smooth = true;
      corners.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const tinyobj::index_t& ix = mesh.indices[index + k];
        corners.push_back(scene.meshVertices[std::size_t(ix.vertex_index)]);
        smooth = smooth && ix.normal_index >= 0 && usable[std::size_t(ix.normal_index)];
      }
      for (const std::array<std::uint32_t, 3>& tri : triangulate(corners)) {
        std::array<std::uint32_t, 3> v, n;
        for (int c = 0; c < 3; ++c) {
          const tinyobj::index_t& ix = mesh.indices[index + tri[std::size_t(c)]];
          v[std::size_t(c)] = std::uint32_t(ix.vertex_index);
          n[std::size_t(c)] = smooth ? std::uint32_t(ix.normal_index) : kNoNormal;
        }
        if (!addMeshTriangle(scene, v, smooth ? &n : nullptr, material, origin, group)) ++dropped;
      }
      index += count;
    }
  }
  if (dropped > 0 && warnings != nullptr) {
    warnings->push_back({name, 1, 1,
                         std::to_string(dropped) + " zero-area triangle" +
                             (dropped == 1 ? " was" : "s were") + " dropped"});
  }

  const Aabb box = sceneBounds(scene);
  scene.camera = frameBox(box);
  addDefaultLights(scene, box);
  return scene;
}

} // namespace prism

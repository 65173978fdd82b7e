#include "core/io/obj_reader.h"

#include "core/io/import_common.h"
#include "core/io/obj_scan.h"
#include "core/io/oiio_module.h"
#include "core/io/reader_base.h"
#include "core/io/scene_text.h"
#include "core/math/model_range.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/triangulate.h"

#include <tiny_obj_loader.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <variant>

namespace prism {

namespace {

// An OBJ of a few million triangles is a few hundred MiB of text. Just under
// 2 GiB, so that no line or column number (an int) can overflow.
constexpr std::size_t kMaxObjBytes = (std::size_t(2) << 30) - (std::size_t(1) << 20);

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

// tinyobjloader's messages about `file`: its errors are thrown, its warnings
// passed on.
void passOn(bool ok, const std::string& warn, const std::string& err, const std::string& file,
            std::vector<Diagnostic>* warnings) {
  if (!ok || !err.empty()) {
    std::vector<Diagnostic> errors = fromTinyObj(err, file);
    if (errors.empty()) errors.push_back({file, 1, 1, "tinyobjloader could not read the file"});
    throw SceneError(std::move(errors));
  }
  if (warnings != nullptr) {
    for (Diagnostic& d : fromTinyObj(warn, file))
      warnings->push_back(std::move(d));
  }
}

// What tinyobjloader makes of the normalised OBJ and of its libraries.
struct TinyObj {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials; // of every library, in order
  std::map<std::string, int> materialIds;     // by name: the first definition
};

// tinyobjloader reads the copy the scan wrote, never the file (see
// core/io/obj_scan.h). It gets no material reader: it would look a `usemtl`
// name up before a later `mtllib` is read, and read only the first readable
// file of an `mtllib` line. The libraries are read here, all of them, and
// each face's material comes from the scan.
TinyObj readWithTinyObj(std::string objText, const ObjScan& scan, const std::string& name,
                        std::vector<Diagnostic>* warnings) {
  TinyObj tiny;
  {
    std::istringstream in(std::move(objText));
    std::vector<tinyobj::material_t> none;
    std::string warn, err;
    const bool ok = tinyobj::LoadObj(&tiny.attrib, &tiny.shapes, &none, &warn, &err, &in,
                                     /*readMatFn=*/nullptr, /*triangulate=*/false,
                                     /*default_vcols_fallback=*/false);
    passOn(ok, warn, err, name, warnings);
  } // the text is freed before the scene is built
  for (const MaterialLibrary& library : scan.libraries) {
    std::istringstream in(library.text);
    std::string warn, err;
    tinyobj::LoadMtl(&tiny.materialIds, &tiny.materials, &in, &warn, &err);
    passOn(true, warn, err, library.path, warnings);
  }
  return tiny;
}

// Where tinyobjloader's result is not what the scan checked: a bug in one of
// them, reported at the face's line rather than read out of bounds.
[[noreturn]] void internalError(const std::string& file, std::uint32_t line,
                                const std::string& what) {
  throw SceneError({Diagnostic{file, int(std::max<std::uint32_t>(line, 1)), 1,
                               "internal error: " + what + " (please report this)"}});
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
void addDefaultLights(SceneBuilder& build, const Aabb& box) {
  const Vec3 centre = box.centroid();
  const double radius = std::max(0.5 * glm::length(box.extent()), 1e-300);
  const struct {
    Vec3 direction;
    double intensity;
  } kLights[] = {{Vec3(-2.0, 3.0, 4.0), 1.0}, {Vec3(3.0, 1.0, 2.0), 0.35}};
  for (const auto& l : kLights) {
    // Far enough (ten radii) that 1/r^2 barely varies across the mesh.
    const Vec3 offset = 10.0 * radius * glm::normalize(l.direction);
    build.addLight({centre + offset, falloffCompensated(Color(l.intensity), glm::length(offset))});
  }
  Scene& scene = build.scene();
  scene.ambient = Color(0.1);
  // A mid-grey backdrop: automatic exposure scales by the image's mean, and a
  // black one would leave a small object overexposed.
  scene.background = Color(0.4);
}

// The mesh's box for the default camera and lights; a unit box at the
// origin when there is no triangle (an empty box has no centre: its lights
// were NaN).
Aabb framedBox(const Scene& scene) {
  Aabb box = sceneBounds(scene);
  if (box.empty()) {
    box.extend(Vec3(-0.5));
    box.extend(Vec3(0.5));
  }
  return box;
}

void frameAndLight(SceneBuilder& build, const std::string& file) {
  Scene& scene = build.scene();
  const Aabb box = framedBox(scene);
  scene.camera = frameBox(box);
  addDefaultLights(build, box);
  bool finite = isFinite(scene.camera.eye);
  for (const Light& light : scene.lights)
    finite = finite && isFinite(light.position) && isFinite(light.intensity);
  if (!finite) {
    // The lights' intensity grows with the square of the mesh's size.
    throw SceneError({Diagnostic{file, 1, 1,
                                 "the mesh is too large for the default camera and lights "
                                 "(their distance or intensity overflows)"}});
  }
}

void copyVertices(const tinyobj::attrib_t& attrib, Scene& scene) {
  scene.meshVertices.resize(attrib.vertices.size() / 3);
  for (std::size_t i = 0; i < scene.meshVertices.size(); ++i) {
    scene.meshVertices[i] =
        Vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  }
}

// The normals, each scaled to unit length; a zero or unusable one cannot be
// interpolated: a face using one is flat. Returns which are usable.
std::vector<bool> copyNormals(const tinyobj::attrib_t& attrib, Scene& scene) {
  std::vector<bool> usable(attrib.normals.size() / 3);
  scene.meshNormals.resize(attrib.normals.size() / 3);
  for (std::size_t i = 0; i < scene.meshNormals.size(); ++i) {
    const Vec3 n(attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]);
    const double scale = maxAbsComponent(n);
    usable[i] = scale > 0.0 && std::isfinite(scale);
    scene.meshNormals[i] = usable[i] ? glm::normalize(n / scale) : Vec3(0.0, 0.0, 1.0);
  }
  return usable;
}

// A material's `map_Kd` read into the scene's image library, as the .sc
// `image` command reads its file (sRGB unless the file says otherwise); an
// unreadable one is an error at its FILE in the MTL file.
ImageMap loadDiffuseMap(Scene& scene, const DiffuseMap& map) {
  const auto fail = [&](const std::string& why) {
    throw SceneError({Diagnostic{map.library, map.line, map.column,
                                 "map_Kd: cannot read '" + map.path + "': " + why}});
  };
  const std::filesystem::path path(map.path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail(std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  std::variant<std::uint32_t, std::string> loaded;
  try {
    if (!scene.images) scene.images = std::make_shared<ImageLibrary>(oiioTextureBackend());
    loaded = scene.images->load(map.path, ImageEncoding::Auto);
  } catch (const std::runtime_error& e) { // the OpenImageIO module is missing
    loaded = std::string(e.what());
  }
  if (const std::string* why = std::get_if<std::string>(&loaded)) fail(*why);
  ImageMap image;
  image.image = std::get<std::uint32_t>(loaded);
  image.peak = scene.images->info(image.image).peak;
  image.scale = map.scale;
  image.offset = map.offset;
  image.wrap = map.clamp ? ImageWrap::Clamp : ImageWrap::Repeat;
  return image;
}

bool allFinite(const MtlValues& v) {
  return isFinite(v.kd) && isFinite(v.ks) && std::isfinite(v.ns) && std::isfinite(v.ni) &&
         std::isfinite(v.dissolve);
}

// The scene's material of each face, stored when a face first uses it, as in
// .sc scenes.
class ObjMaterials {
public:
  ObjMaterials(SceneBuilder& build, const ObjScan& scan, const TinyObj& tiny,
               const std::string& file)
      : build_(build), scan_(scan), tiny_(tiny), file_(file), ids_(scan.usedMaterials.size()) {}

  std::uint32_t of(const ObjFace& face) {
    if (face.material == kNoMaterial) {
      if (!fallback_) fallback_ = build_.material(defaultMaterial());
      return *fallback_;
    }
    if (face.material >= ids_.size()) internalError(file_, face.line, "an unknown material");
    std::optional<std::uint32_t>& slot = ids_[face.material];
    if (!slot) slot = build_.material(convert(face));
    return *slot;
  }

private:
  Material convert(const ObjFace& face) const {
    const std::string& name = scan_.usedMaterials[face.material];
    const auto id = tiny_.materialIds.find(name);
    if (id == tiny_.materialIds.end() || id->second < 0 ||
        std::size_t(id->second) >= tiny_.materials.size()) {
      internalError(file_, face.line, "tinyobjloader has no material " + prism::quoted(name));
    }
    const auto given = scan_.materials.find(name);
    const MtlValues values = valuesOf(tiny_.materials[std::size_t(id->second)],
                                      given != scan_.materials.end() && given->second);
    if (!allFinite(values)) {
      throw SceneError({Diagnostic{file_, int(face.line), 1,
                                   "usemtl: tinyobjloader reads a value of material " +
                                       prism::quoted(name) + " as infinite"}});
    }
    Material m = materialFromMtl(values);
    // Kd multiplies the map, as C_mat multiplies an image. Read only for
    // materials that faces use.
    if (const auto map = scan_.diffuseMaps.find(name); map != scan_.diffuseMaps.end())
      m.image = loadDiffuseMap(build_.scene(), map->second);
    return m;
  }

  SceneBuilder& build_;
  const ObjScan& scan_;
  const TinyObj& tiny_;
  const std::string& file_;
  std::vector<std::optional<std::uint32_t>> ids_; // by ObjFace::material
  std::optional<std::uint32_t> fallback_;
};

// Turns tinyobjloader's faces into triangles. The size of each face is the
// scan's (tinyobjloader's is 8 bits: a 256-gon is 0 to it, and a 300-gon 44),
// and every index it returns is checked before use.
class FaceBuilder {
public:
  FaceBuilder(SceneBuilder& build, const ObjScan& scan, const std::vector<bool>& usable,
              ObjMaterials& materials, const std::string& file)
      : build_(build), scene_(build.scene()), scan_(scan), usable_(usable), materials_(materials),
        file_(file) {}

  void addShape(const tinyobj::mesh_t& mesh) {
    // Each OBJ object or group is a group of the scene (the hint `--accel
    // groups` builds on), written where its first face is.
    const bool hasFaces = !mesh.num_face_vertices.empty() && face_ < scan_.faces.size();
    build_.push(hasFaces ? Origin{0, scan_.faces[face_].line} : Origin{});
    std::size_t next = 0; // the face's first corner in mesh.indices
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++face_) {
      if (face_ >= scan_.faces.size()) internalError(file_, 1, "tinyobjloader read more faces");
      const ObjFace& face = scan_.faces[face_];
      if (mesh.num_face_vertices[f] != (face.corners & 0xFFu) ||
          face.corners > mesh.indices.size() - next) {
        internalError(file_, face.line, "tinyobjloader read another number of vertices");
      }
      addFace({mesh.indices.data() + next, face.corners}, face);
      next += face.corners;
    }
    if (next != mesh.indices.size()) internalError(file_, 1, "tinyobjloader read more vertices");
    build_.pop();
  }

  // After the last shape.
  void checkAllFacesRead() const {
    if (face_ != scan_.faces.size()) internalError(file_, 1, "tinyobjloader read fewer faces");
  }

  std::size_t dropped() const { return dropped_; }
  std::size_t notSimple() const { return notSimple_; }

private:
  void addFace(std::span<const tinyobj::index_t> corners, const ObjFace& face) {
    const std::uint32_t material = materials_.of(face);
    bool smooth = true;
    // Surface coordinates when every corner names a `vt` (v/t or v/t/n);
    // otherwise each triangle keeps its barycentric ones.
    bool textured = true;
    points_.clear();
    for (const tinyobj::index_t& ix : corners) {
      points_.push_back(vertex(ix, face));
      smooth = smooth && ix.normal_index >= 0 && usable_[std::size_t(ix.normal_index)];
      textured = textured && ix.texcoord_index >= 0;
    }
    const Triangulation triangulation = triangulatePolygon(points_);
    const std::size_t droppedBefore = dropped_;
    for (const std::array<std::uint32_t, 3>& tri : triangulation.triangles) {
      std::array<std::uint32_t, 3> v, n;
      std::array<Vec2, 3> uv;
      for (std::size_t c = 0; c < 3; ++c) {
        if (tri[c] >= corners.size()) internalError(file_, face.line, "a triangle out of range");
        const tinyobj::index_t& ix = corners[tri[c]];
        v[c] = std::uint32_t(ix.vertex_index);
        n[c] = smooth ? std::uint32_t(ix.normal_index) : kNoNormal;
        if (textured) uv[c] = scan_.texcoords[std::size_t(ix.texcoord_index)];
      }
      const Origin origin{0, face.line};
      if (!build_.meshTriangle(v, smooth ? &n : nullptr, material, origin,
                               textured ? &uv : nullptr))
        ++dropped_;
    }
    // A face of zero area is not simple either; it is reported as dropped.
    const bool keptSome = dropped_ - droppedBefore < triangulation.triangles.size();
    if (!triangulation.simple && keptSome) ++notSimple_;
  }

  // The corner's vertex, its vertex, normal and texture coordinate indices checked.
  const Vec3& vertex(const tinyobj::index_t& ix, const ObjFace& face) const {
    if (ix.vertex_index < 0 || std::size_t(ix.vertex_index) >= scene_.meshVertices.size() ||
        (ix.normal_index >= 0 && std::size_t(ix.normal_index) >= usable_.size()) ||
        (ix.texcoord_index >= 0 && std::size_t(ix.texcoord_index) >= scan_.texcoords.size())) {
      internalError(file_, face.line, "tinyobjloader read an index out of range");
    }
    const Vec3& p = scene_.meshVertices[std::size_t(ix.vertex_index)];
    if (!isFinite(p)) {
      throw SceneError({Diagnostic{file_, int(face.line), 1,
                                   "f: tinyobjloader reads vertex " +
                                       std::to_string(ix.vertex_index + 1) + " as infinite"}});
    }
    if (!withinModelRange(p)) {
      throw SceneError({Diagnostic{file_, int(face.line), 1,
                                   "f: vertex " + std::to_string(ix.vertex_index + 1) +
                                       " lies outside the supported range: coordinates must be "
                                       "within +-" +
                                       kMaxCoordinateText}});
    }
    return p;
  }

  SceneBuilder& build_;
  const Scene& scene_;
  const ObjScan& scan_;
  const std::vector<bool>& usable_;
  ObjMaterials& materials_;
  const std::string& file_;
  std::size_t face_ = 0; // into scan_.faces
  std::size_t dropped_ = 0;
  std::size_t notSimple_ = 0; // faces whose triangles are a best effort
  std::vector<Vec3> points_;
};

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
  std::string text = readSceneText(path, kMaxObjBytes);
  ObjScan scan = scanObj(text, name, path.parent_path());
  if (!scan.errors.empty()) throw SceneError(std::move(scan.errors));
  normaliseObjForTinyObj(text);
  TinyObj tiny = readWithTinyObj(std::move(text), scan, name, warnings);

  Scene scene;
  SceneBuilder build(scene);
  build.addFile(name);
  // Listed so that the previewer reloads when a material file changes too.
  for (const MaterialLibrary& library : scan.libraries)
    build.addFile(library.path);
  copyVertices(tiny.attrib, scene);
  const std::vector<bool> usable = copyNormals(tiny.attrib, scene);
  // The scan's exact texture coordinates, which tinyobjloader's indices
  // (checked against them) point into.
  if (tiny.attrib.texcoords.size() / 2 != scan.texcoords.size())
    internalError(name, 1, "tinyobjloader read another number of texture coordinates");
  tiny.attrib = tinyobj::attrib_t{};

  ObjMaterials materials(build, scan, tiny, name);
  FaceBuilder faces(build, scan, usable, materials, name);
  scene.shapes<Triangle>().reserve(scan.triangles);
  if (!scan.texcoords.empty()) scene.triangleUvs.reserve(scan.triangles);
  for (const tinyobj::shape_t& shape : tiny.shapes)
    faces.addShape(shape.mesh);
  faces.checkAllFacesRead();
  if (warnings != nullptr) {
    if (faces.dropped() > 0) {
      warnings->push_back({name, 1, 1,
                           std::to_string(faces.dropped()) + " zero-area triangle" +
                               (faces.dropped() == 1 ? " was" : "s were") + " dropped"});
    }
    if (faces.notSimple() > 0) {
      warnings->push_back({name, 1, 1, notSimpleWarning(faces.notSimple(), "face")});
    }
    if (scan.faces.empty()) {
      warnings->push_back({name, 1, 1, "the file has no faces: nothing to render"});
    }
  }
  frameAndLight(build, name);
  return scene;
}

} // namespace prism

// Reads Wavefront OBJ meshes with their MTL materials (through tinyobjloader)
// into a Scene of mesh triangles: smooth where the faces give vertex normals,
// flat where they do not, with their corners' texture coordinates where the
// faces give them (Scene::triangleUvs, which an MTL `map_Kd` image reads).
// OBJ has no camera and no lights, so the scene gets a camera that frames
// the mesh and two default lights. The mapping of MTL onto Prism's material
// model is documented in docs/importing.md, "Importing NFF and OBJ". Errors
// are Diagnostics with file, line and column (SceneError).
#pragma once

#include "core/io/diagnostic.h"
#include "core/scene/scene.h"

#include <filesystem>
#include <vector>

namespace prism {

// Reads the OBJ file at `path` and the MTL files it names (relative to its
// directory). Zero-area faces are dropped with a warning in `warnings`; a file
// without faces gets a warning, and the camera and lights of a unit box at
// the origin.
Scene loadObj(const std::filesystem::path& path, std::vector<Diagnostic>* warnings = nullptr);

// The material an MTL entry becomes (exposed for tests): colour Kd, kdr the
// dissolve d, ksr the mean of Ks (0 for illum 0 and 1), kst 1 - d, e Ns,
// ir Ni.
struct MtlValues {
  Color kd{0.8};
  Color ks{0.0};
  double ns = 0.0;
  double ni = 1.0;
  double dissolve = 1.0;
  int illum = 2;
};
Material materialFromMtl(const MtlValues& mtl);

} // namespace prism

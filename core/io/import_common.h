// What the NFF and OBJ readers share: interning materials, placing mesh
// triangles, and a default camera and lights for files that have none.
#pragma once

#include "core/scene/scene.h"

#include <array>
#include <map>
#include <string>

namespace prism {

// Hands out one index per distinct material, as the .sc reader does.
class MaterialTable {
public:
  explicit MaterialTable(Scene& scene) : scene_(scene) {}
  std::uint32_t intern(const Material& m);

private:
  Scene& scene_;
  std::map<std::array<double, 8>, std::uint32_t> ids_;
};

// Appends a triangle over three existing mesh vertices (and, when `normals`
// is given, three existing unit normals) to the scene and to group 0's list.
// When the vertex normals all lie on the other side of the face than its
// winding says, the winding is reversed: the normals are what the modeller
// saw, and the tracer's entering/leaving test must agree with them. Returns
// false (and adds nothing) for a zero-area triangle.
bool addMeshTriangle(Scene& scene, std::array<std::uint32_t, 3> vertex,
                     const std::array<std::uint32_t, 3>* normals, std::uint32_t material,
                     Origin origin, std::uint32_t group = 0);

// A camera that sees the whole box from the front (+z side, y up, looking
// along -z), with the scene's default 45 degree field of view.
CameraSpec frameBox(const Aabb& box);

// Every primitive's bounds together (empty when there are none).
Aabb sceneBounds(const Scene& scene);

// The intensity that makes a 1/r^2 light deliver `intensity` at `distance`:
// Prism's point lights fall off, NFF's and the default lights' do not.
Color falloffCompensated(const Color& intensity, double distance);

} // namespace prism

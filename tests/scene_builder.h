// Helpers that build prism::Scene objects in code, without the scene parser, for
// the geometry and physics tests: thin wrappers over the core's SceneBuilder
// (so tests build scenes as the readers do) that take the group explicitly.
// Every add* function appends one item to the scene and returns how to refer
// to it.
#pragma once

#include "core/scene/scene.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace prism::test {

// Through the material table: an identical material already there is reused.
inline std::uint32_t addMaterial(Scene& scene, const Material& m) {
  return SceneBuilder(scene).material(m);
}

// A plain diffuse material with colour `c` and diffuse coefficient `kdr`.
inline Material diffuse(const Color& c, double kdr) {
  Material m;
  m.color = c;
  m.kdr = kdr;
  return m;
}

// A new, empty push/pop group below `parent`; returns its index.
inline std::uint32_t addGroup(Scene& scene, std::uint32_t parent = 0) {
  return SceneBuilder(scene).addGroup(parent);
}

// Calls add with a builder over `scene` whose primitives go to `group`.
template <class Add> PrimitiveRef addIn(Scene& scene, std::uint32_t group, const Add& add) {
  SceneBuilder build(scene);
  build.enter(group);
  return add(build);
}

inline PrimitiveRef addSphere(Scene& scene, const Vec3& center, double radius,
                              std::uint32_t material, std::uint32_t group = 0) {
  Sphere s;
  s.center = center;
  s.radius = radius;
  s.material = material;
  return addIn(scene, group, [&](SceneBuilder& build) { return build.add(s); });
}

// The unit sphere under x -> linear * x + offset.
inline PrimitiveRef addEllipsoid(Scene& scene, const Mat3& linear, const Vec3& offset,
                                 std::uint32_t material, std::uint32_t group = 0) {
  Ellipsoid e = makeEllipsoid(linear, offset);
  e.material = material;
  return addIn(scene, group, [&](SceneBuilder& build) { return build.add(e); });
}

// A polygon with the vertices in the given order (counterclockwise seen from the
// side its normal should face). Throws if polygonProblem rejects the vertices,
// so a mistyped test scene fails loudly.
inline PrimitiveRef addPolygon(Scene& scene, const std::vector<Vec3>& vertices,
                               std::uint32_t material, std::uint32_t group = 0) {
  if (polygonProblem(vertices)) throw std::invalid_argument("bad test polygon");
  return addIn(scene, group,
               [&](SceneBuilder& build) { return build.polygon(vertices, material, Origin{}); });
}

// The square [-half, half]^2 in the plane z = height, facing +z (or -z when
// `facingDown`).
inline PrimitiveRef addHorizontalSquare(Scene& scene, double height, double half,
                                        std::uint32_t material, bool facingDown = false,
                                        std::uint32_t group = 0) {
  std::vector<Vec3> v{
      {-half, -half, height}, {half, -half, height}, {half, half, height}, {-half, half, height}};
  if (facingDown) v = {v[0], v[3], v[2], v[1]};
  return addPolygon(scene, v, material, group);
}

inline void addLight(Scene& scene, const Vec3& position, const Color& intensity) {
  SceneBuilder(scene).addLight(Light{position, intensity});
}

} // namespace prism::test

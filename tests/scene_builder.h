// Helpers that build prism::Scene objects in code, without the scene parser, for
// the geometry and physics tests. Every add* function appends one item to the
// scene and returns how to refer to it.
#pragma once

#include "core/scene/scene.h"
#include "core/shapes/shape_kinds.h"

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace prism::test {

inline std::uint32_t addMaterial(Scene& scene, const Material& m) {
  scene.materials.push_back(m);
  return std::uint32_t(scene.materials.size() - 1);
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
  scene.groups.emplace_back();
  const auto index = std::uint32_t(scene.groups.size() - 1);
  scene.groups[parent].children.push_back(index);
  return index;
}

inline PrimitiveRef addSphere(Scene& scene, const Vec3& center, double radius,
                              std::uint32_t material, std::uint32_t group = 0) {
  Sphere s;
  s.center = center;
  s.radius = radius;
  s.material = material;
  scene.shapes<Sphere>().push_back(s);
  const PrimitiveRef ref{kindOf<Sphere>, std::uint32_t(scene.shapes<Sphere>().size() - 1)};
  scene.groups[group].primitives.push_back(ref);
  return ref;
}

// The unit sphere under x -> linear * x + offset.
inline PrimitiveRef addEllipsoid(Scene& scene, const Mat3& linear, const Vec3& offset,
                                 std::uint32_t material, std::uint32_t group = 0) {
  Ellipsoid e = makeEllipsoid(linear, offset);
  e.material = material;
  scene.shapes<Ellipsoid>().push_back(e);
  const PrimitiveRef ref{kindOf<Ellipsoid>, std::uint32_t(scene.shapes<Ellipsoid>().size() - 1)};
  scene.groups[group].primitives.push_back(ref);
  return ref;
}

// A polygon with the vertices in the given order (counterclockwise seen from the
// side its normal should face). Throws if polygonProblem rejects the vertices,
// so a mistyped test scene fails loudly.
inline PrimitiveRef addPolygon(Scene& scene, const std::vector<Vec3>& vertices,
                               std::uint32_t material, std::uint32_t group = 0) {
  if (polygonProblem(vertices)) throw std::invalid_argument("bad test polygon");
  return prism::addPolygon(scene, vertices, material, Origin{}, group);
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
  scene.lights.push_back(Light{position, intensity});
}

} // namespace prism::test

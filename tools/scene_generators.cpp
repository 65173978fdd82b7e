#include "tools/scene_generators.h"

#include "core/math/hash.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <vector>

namespace prism {

namespace {

// splitmix64 (core/math/hash.h): the same numbers on every platform and
// standard library.
class Rng : public SplitMix64 {
public:
  using SplitMix64::SplitMix64;
  Vec3 unitVector() {
    const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * std::numbers::pi);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
};

// Two unit vectors completing `n` (unit) to a right-handed orthonormal frame.
void frameAround(const Vec3& n, Vec3& e1, Vec3& e2) {
  e1 = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  e2 = glm::cross(n, e1);
}

Material plastic(const Color& color, double kdr, double ksr, double e) {
  Material m;
  m.color = color;
  m.kdr = kdr;
  m.ksr = ksr;
  m.e = e;
  return m;
}

// What a generated scene is seen and lit by: the camera (up +y), the
// background, the ambient light and two lights, a key and a fill.
struct Stage {
  Vec3 eye, lookat;
  double fov;
  Color background;
  double ambient;
  Light key, fill;
};

void setStage(Scene& scene, SceneBuilder& build, const Stage& stage) {
  scene.camera.eye = stage.eye;
  scene.camera.lookat = stage.lookat;
  scene.camera.fov = stage.fov;
  scene.background = stage.background;
  scene.ambient = Color(stage.ambient);
  build.addLight(stage.key);
  build.addLight(stage.fill);
}

void addPolygonIfValid(SceneBuilder& build, const std::vector<Vec3>& vertices,
                       std::uint32_t material) {
  if (!polygonProblem(vertices)) build.polygon(vertices, material, Origin{});
}

} // namespace

Scene makeSphereflake(std::size_t spheres) {
  Scene scene;
  SceneBuilder build(scene);
  build.addFile("(generated sphereflake)");
  setStage(scene, build,
           {Vec3(2.1, 1.7, 2.6), Vec3(0.0, 0.15, 0.0), 45.0, Color(0.08, 0.1, 0.16), 0.1,
            Light{Vec3(4, 6, 3), Color(40.0)}, Light{Vec3(-5, 3, 4), Color(12.0)}});
  const std::uint32_t ground = build.material(plastic(Color(0.6, 0.6, 0.55), 0.8, 0.0, 1.0));
  const std::uint32_t flake = build.material(plastic(Color(0.85, 0.7, 0.45), 0.5, 0.4, 40.0));
  addPolygonIfValid(build, {{-4, -1, 4}, {4, -1, 4}, {4, -1, -4}, {-4, -1, -4}}, ground);

  // The 9 child directions in a sphere's own frame (z up): 6 around the
  // equator and 3 above, as in the classic flake.
  std::vector<Vec3> directions;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    directions.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  for (int k = 0; k < 3; ++k) {
    const double a = std::numbers::pi / 6.0 + k * 2.0 * std::numbers::pi / 3.0;
    const double up = std::numbers::pi / 3.0;
    directions.emplace_back(std::cos(a) * std::cos(up), std::sin(a) * std::cos(up), std::sin(up));
  }

  struct Pending {
    Vec3 center;
    double radius;
    Vec3 up;
    std::uint32_t parentGroup;
  };
  std::deque<Pending> queue{{Vec3(0.0), 0.5, Vec3(0, 1, 0), 0}};
  std::size_t made = 0;
  while (made < spheres && !queue.empty()) {
    const Pending s = queue.front();
    queue.pop_front();
    // A sphere whose children will be made groups itself with them.
    const bool hasChildren = made + queue.size() + 1 < spheres;
    const std::uint32_t group = hasChildren ? build.addGroup(s.parentGroup) : s.parentGroup;
    build.enter(group); // breadth first: not the group of the sphere before
    build.add(Sphere{s.center, s.radius, flake, {}});
    ++made;
    if (!hasChildren) continue;
    Vec3 e1, e2;
    frameAround(s.up, e1, e2);
    const double r = s.radius / 3.0;
    for (const Vec3& d : directions) {
      const Vec3 dir = glm::normalize(d.x * e1 + d.y * e2 + d.z * s.up);
      queue.push_back({s.center + (s.radius + r) * dir, r, dir, group});
    }
  }
  return scene;
}

namespace {

// Spreads the low 21 bits of x so that two zero bits follow each one.
std::uint64_t spreadBits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Position of a point of [-1, 1]^3 along the Morton (Z-order) curve.
std::uint64_t mortonCode(const Vec3& p) {
  auto cell = [](double x) {
    return std::uint64_t(std::clamp((x + 1.0) * 0.5, 0.0, 1.0) * double((1 << 21) - 1));
  };
  return spreadBits(cell(p.x)) | spreadBits(cell(p.y)) << 1 | spreadBits(cell(p.z)) << 2;
}

struct SoupTriangle {
  std::uint64_t morton; // of the centre
  std::array<Vec3, 3> vertices;
};

// Equilateral triangles of circumradius `radius` with random centres in the
// cube [-1, 1]^3 and random orientations, in a scene with a camera and lights.
Scene polygonSoup(std::size_t triangles, double radius, bool spatialOrder, std::uint64_t seed) {
  Scene scene;
  SceneBuilder build(scene);
  build.addFile("(generated polygon soup)");
  setStage(scene, build,
           {Vec3(0.0, 0.0, 4.2), Vec3(0.0), 40.0, Color(0.1, 0.12, 0.2), 0.15,
            Light{Vec3(3, 4, 5), Color(40.0)}, Light{Vec3(-4, 2, 3), Color(12.0)}});
  const std::uint32_t material = build.material(plastic(Color(0.7, 0.75, 0.8), 0.8, 0.2, 20.0));

  std::vector<SoupTriangle> soup(triangles);
  Rng rng(seed);
  for (std::size_t i = 0; i < triangles; ++i) {
    const Vec3 c(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    Vec3 e1, e2;
    frameAround(rng.unitVector(), e1, e2);
    const double phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
    for (int k = 0; k < 3; ++k) {
      const double a = phase + k * 2.0 * std::numbers::pi / 3.0;
      soup[i].vertices[std::size_t(k)] = c + radius * (std::cos(a) * e1 + std::sin(a) * e2);
    }
    soup[i].morton = mortonCode(c);
  }
  if (spatialOrder)
    std::stable_sort(soup.begin(), soup.end(), [](const SoupTriangle& a, const SoupTriangle& b) {
      return a.morton < b.morton;
    });

  scene.shapes<Polygon>().reserve(triangles);
  scene.polygonVertices.reserve(3 * triangles);
  scene.groups[0].primitives.reserve(triangles);
  std::vector<Vec3> v(3);
  for (const SoupTriangle& t : soup) {
    v.assign(t.vertices.begin(), t.vertices.end());
    addPolygonIfValid(build, v, material);
  }
  return scene;
}

} // namespace

Scene makePolygonSoup(std::size_t triangles, std::uint64_t seed) {
  // Equilateral triangles of circumradius s have area (3 sqrt 3 / 4) s^2; a
  // total area of 64 in a cube of volume 8 gives a ray crossing the cube
  // (length 2) about 2 * 64 / 8 / 2 = 8 crossings.
  const double s =
      std::sqrt(64.0 / double(std::max<std::size_t>(1, triangles)) / (0.75 * std::sqrt(3.0)));
  return polygonSoup(triangles, s, false, seed);
}

Scene makeScaledPolygonSoup(std::size_t triangles, std::uint64_t seed) {
  // Three quarters of the mean spacing (8 / n)^(1/3): at 10^4 the same size as
  // makePolygonSoup's triangles.
  const double s = 0.75 * std::cbrt(8.0 / double(std::max<std::size_t>(1, triangles)));
  return polygonSoup(triangles, s, true, seed);
}

} // namespace prism

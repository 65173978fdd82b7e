#include "core/shapes/mesh_closure.h"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <utility>

namespace prism {

namespace {

std::uint64_t edgeKey(std::uint32_t from, std::uint32_t to) {
  return std::uint64_t(from) << 32 | to;
}

} // namespace

WeldedMesh weld(std::span<const std::array<Vec3, 3>> triangles) {
  WeldedMesh mesh;
  // Ordered by coordinates: equal ones (0 and -0 too) are one vertex.
  std::map<std::array<double, 3>, std::uint32_t> index;
  mesh.triangles.reserve(triangles.size());
  for (const std::array<Vec3, 3>& t : triangles) {
    std::array<std::uint32_t, 3> corners{};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [it, added] =
          index.try_emplace({t[k].x, t[k].y, t[k].z}, std::uint32_t(mesh.vertices.size()));
      if (added) mesh.vertices.push_back(t[k]);
      corners[k] = it->second;
    }
    mesh.triangles.push_back(corners);
  }
  return mesh;
}

std::optional<ClosureProblem> closureProblem(const WeldedMesh& mesh) {
  std::unordered_map<std::uint64_t, std::uint32_t> runBy; // directed edge -> triangle
  runBy.reserve(mesh.triangles.size() * 3);
  std::optional<ClosureProblem> first;
  for (std::uint32_t i = 0; i < mesh.triangles.size() && !first; ++i) {
    const auto& t = mesh.triangles[i];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      const auto [it, added] = runBy.try_emplace(edgeKey(a, b), i);
      if (!added) {
        first = ClosureProblem{ClosureProblem::Kind::SameDirection, i, it->second, mesh.vertices[a],
                               mesh.vertices[b]};
        break;
      }
    }
  }
  if (first) return first;
  for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (!runBy.contains(edgeKey(b, a)))
        return ClosureProblem{ClosureProblem::Kind::Open, i, i, mesh.vertices[a], mesh.vertices[b]};
    }
  }
  return std::nullopt;
}

double signedVolume6(const WeldedMesh& mesh) {
  // Each triangle's tetrahedron with a point of the mesh (its first vertex,
  // not the origin, so a mesh far away keeps its digits).
  const Vec3 o = mesh.vertices.empty() ? Vec3(0.0) : mesh.vertices.front();
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o,
               c = mesh.vertices[t[2]] - o;
    sum += glm::dot(a, glm::cross(b, c));
  }
  return sum;
}

} // namespace prism

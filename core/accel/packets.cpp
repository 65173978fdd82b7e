#include "core/accel/packets.h"

#include <algorithm>

namespace prism {

namespace {

// Appends the three coordinates of point(lane) for every lane, value by value.
template <class Point> void appendPoint(std::vector<double>& out, std::size_t lanes, Point point) {
  for (int a = 0; a < 3; ++a)
    for (std::size_t lane = 0; lane < lanes; ++lane)
      out.push_back(point(lane)[a]);
}

} // namespace

void appendPacket(std::span<const Triangle* const> shapes, const ShapeArrays& arrays,
                  std::vector<double>& out) {
  for (std::size_t k = 0; k < 3; ++k)
    appendPoint(out, shapes.size(), [&](std::size_t lane) -> const Vec3& {
      return arrays.meshVertices[shapes[lane]->vertex[k]];
    });
}

std::uint32_t appendPacket(std::span<const Polygon* const> shapes, const ShapeArrays& arrays,
                           std::vector<double>& out) {
  std::uint32_t vertices = 0;
  for (const Polygon* p : shapes)
    vertices = std::max(vertices, p->vertexCount);
  appendPoint(out, shapes.size(),
              [&](std::size_t lane) -> const Vec3& { return shapes[lane]->normal; });
  for (const Polygon* p : shapes)
    out.push_back(p->planeOffset);
  for (std::uint32_t k = 0; k < vertices; ++k)
    appendPoint(out, shapes.size(), [&](std::size_t lane) -> const Vec3& {
      const Polygon& p = *shapes[lane];
      return arrays.polygonVertices[p.firstVertex + std::min(k, p.vertexCount - 1)];
    });
  return vertices;
}

} // namespace prism

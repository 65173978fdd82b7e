#include "tools/sphere_mesh.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace prism {

namespace {

void put(std::string& line, double x) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  line += ' ';
  line.append(buffer, r.ptr);
}

} // namespace

void writeSphereObj(std::ostream& out, int stacks, int slices, double radius, double cx, double cy,
                    double cz) {
  out << "# UV sphere: " << stacks << " stacks, " << slices << " slices, "
      << sphereMeshTriangles(stacks, slices) << " triangles\n";
  // Vertex 1 is the north pole, then (stacks - 1) rings of `slices`, then the
  // south pole; normal k belongs to vertex k.
  std::string line;
  const auto vertex = [&](double x, double y, double z) {
    line = "v";
    put(line, cx + radius * x);
    put(line, cy + radius * y);
    put(line, cz + radius * z);
    line += "\nvn";
    put(line, x);
    put(line, y);
    put(line, z);
    line += '\n';
    out << line;
  };
  vertex(0.0, 1.0, 0.0);
  for (int i = 1; i < stacks; ++i) {
    const double theta = std::numbers::pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / slices;
      vertex(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
    }
  }
  vertex(0.0, -1.0, 0.0);
  const long long south = 2 + (long long)(stacks - 1) * slices;
  const auto ring = [&](int i, int j) { return 2 + (long long)(i - 1) * slices + (j % slices); };
  const auto face = [&](long long a, long long b, long long c) {
    out << "f " << a << "//" << a << ' ' << b << "//" << b << ' ' << c << "//" << c << '\n';
  };
  for (int j = 0; j < slices; ++j)
    face(1, ring(1, j), ring(1, j + 1));
  for (int i = 1; i + 1 < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      face(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      face(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  }
  for (int j = 0; j < slices; ++j)
    face(south, ring(stacks - 1, j + 1), ring(stacks - 1, j));
}

} // namespace prism

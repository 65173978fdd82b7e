#include "sc_writer.h"

#include <cmath>
#include <cstdio>

namespace prism::spd {

void ScWriter::comment(std::string_view text) {
  text_ += "# ";
  text_ += text;
  text_ += '\n';
}

void ScWriter::stage(const Stage& s) {
  text_ += "resolution 512 512\neye";
  point(s.eye);
  text_ += "\nlookat";
  point(s.lookat);
  text_ += "\nup 0 1 0\nfov";
  number(s.fov);
  text_ += "\nbackground";
  for (double c : s.background)
    number(c);
  text_ += "\nambient";
  for (int k = 0; k < 3; ++k)
    number(s.ambient);
  text_ += '\n';
  for (const PointLight& l : s.lights) {
    text_ += "light";
    point(l.position);
    for (int k = 0; k < 3; ++k)
      number(l.intensity);
    text_ += '\n';
  }
  text_ += '\n';
}

void ScWriter::surface(const Surface& s) {
  text_ += "surface";
  for (double v : {s.r, s.g, s.b, s.kd, s.ks, s.kt, s.e, s.ir})
    number(v);
  text_ += '\n';
}

void ScWriter::sphere(V3 centre, double radius) {
  text_ += "sphere";
  point(centre);
  number(radius);
  text_ += '\n';
  ++counts_.spheres;
}

void ScWriter::cone(V3 base, double baseRadius, V3 apex, double apexRadius) {
  text_ += "cone";
  point(base);
  number(baseRadius);
  point(apex);
  number(apexRadius);
  text_ += '\n';
  ++counts_.cones;
}

void ScWriter::polygon(const std::vector<V3>& vertices) {
  text_ += "polygon " + std::to_string(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    // Long polygons get a line per vertex, so a reader of the file can follow them.
    if (vertices.size() > 8) text_ += "\n ";
    point(vertices[i]);
  }
  text_ += '\n';
  ++counts_.polygons;
}

void ScWriter::triangle(V3 a, V3 b, V3 c) {
  text_ += "triangle";
  point(a);
  point(b);
  point(c);
  text_ += '\n';
  ++counts_.triangles;
}

void ScWriter::ptriangle(V3 a, V3 na, V3 b, V3 nb, V3 c, V3 nc) {
  text_ += "ptriangle";
  for (V3 p : {a, na, b, nb, c, nc})
    point(p);
  text_ += '\n';
  ++counts_.triangles;
}

void ScWriter::number(double value) {
  // 7 significant digits keep the tiny triangles of the largest sizes
  // non-degenerate, and hide last-bit differences between maths libraries
  // (the same bytes on every platform). Round-off residues such as
  // cos(90 degrees) = 6e-17, and -0, are written as 0.
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, " %.7g", std::fabs(value) < 1e-12 ? 0.0 : value);
  text_ += buffer;
}

void ScWriter::point(V3 p) {
  number(p.x);
  number(p.y);
  number(p.z);
}

} // namespace prism::spd

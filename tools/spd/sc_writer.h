// Writes Prism's scene language (docs/scene-language.md) into a string and
// counts the primitives it writes, by the kind the reader will store them as,
// so every benchmark scene can say (and the tests can check) what it holds.
#pragma once

#include "vec3.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace prism::spd {

// A `surface` command's arguments (their meaning is in docs/rendering-model.md).
struct Surface {
  double r = 1, g = 1, b = 1;
  double kd = 1, ks = 0, kt = 0, e = 1, ir = 1;
};

struct PointLight {
  V3 position;
  double intensity; // the same in red, green and blue
};

// Camera, image and lighting: what every scene starts with.
struct Stage {
  V3 eye, lookat;
  double fov; // vertical, degrees
  std::vector<PointLight> lights;
  double background[3] = {0, 0, 0};
  double ambient = 0.1;
};

// Primitives written, by the shape kind the reader stores them as (a
// `ptriangle` is a triangle too).
struct Counts {
  long spheres = 0, polygons = 0, cones = 0, triangles = 0;
  long total() const { return spheres + polygons + cones + triangles; }
};

class ScWriter {
public:
  void comment(std::string_view text); // one `# ...` line
  void blank() { text_ += '\n'; }
  void stage(const Stage& s);
  void surface(const Surface& s);
  void push() { text_ += "push\n"; }
  void pop() { text_ += "pop\n"; }

  void sphere(V3 centre, double radius);
  void cone(V3 base, double baseRadius, V3 apex, double apexRadius);
  void polygon(const std::vector<V3>& vertices); // counterclockwise seen from the front
  void polygon(std::initializer_list<V3> vertices) { polygon(std::vector<V3>(vertices)); }
  void triangle(V3 a, V3 b, V3 c);
  void ptriangle(V3 a, V3 na, V3 b, V3 nb, V3 c, V3 nc);

  const std::string& text() const { return text_; }
  const Counts& counts() const { return counts_; }

private:
  void number(double value); // a space, then the value in 7 significant digits
  void point(V3 p);

  std::string text_;
  Counts counts_;
};

} // namespace prism::spd

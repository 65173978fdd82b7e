// How each shape kind is written back as .sc text, one file per kind
// (sphere_text.cpp, ...), and what they write with: numbers in their shortest
// exact form, indented lines, and placing an object written in its own
// frame. scene_writer.cpp writes the rest of the scene and reaches these
// through Scene::visit, so a new kind adds a file here, not a case there.
#pragma once

#include "core/scene/scene.h"

#include <array>
#include <ostream>
#include <string>

namespace prism::sc {

// The shortest text that reads back as exactly `x` (std::to_chars).
std::string num(double x);
std::string vec(const Vec3& v); // "X Y Z"

// Where the text goes, and the scene whose arrays the shapes index into.
class TextOut {
public:
  TextOut(std::ostream& out, const Scene& scene) : out_(out), scene_(scene) {}

  const Scene& scene() const { return scene_; }
  std::ostream& out() { return out_; }

  // Starts a line indented by two spaces per level, up to kMaxIndent levels:
  // deeper nesting is not indented further, or the output would grow with
  // the square of the depth.
  std::ostream& line(int depth);

  // An object written in its own frame, mapped to the world by
  // x -> offset + a x: push, the placing transforms, what `command(depth + 1)`
  // writes, pop. Every kind that writes such a block writes it with this.
  template <class Command>
  void inFrame(const Mat3& a, const Vec3& offset, int depth, Command&& command) {
    line(depth) << "push\n";
    placed(a, offset, depth + 1);
    command(depth + 1);
    line(depth) << "pop\n";
  }

private:
  // translate, rotate, scale, rotate: the map x -> offset + a x.
  void placed(const Mat3& a, const Vec3& offset, int depth);

  static constexpr int kMaxIndent = 16;
  std::ostream& out_;
  const Scene& scene_;
};

// One command (or a push/pop block) per shape, at nesting depth `depth`.
void write(TextOut& text, const Sphere& s, int depth);
void write(TextOut& text, const Ellipsoid& e, int depth);
void write(TextOut& text, const Polygon& p, int depth);
// `triangle_uv` or `ptriangle_uv` when `uvs` (the triangle's per-vertex
// surface coordinates, Scene::triangleUvs) are given.
void write(TextOut& text, const Triangle& t, int depth, const std::array<Vec2, 3>* uvs = nullptr);
void write(TextOut& text, const Cone& c, int depth);
void write(TextOut& text, const Torus& t, int depth);
void write(TextOut& text, const CappedCone& c, int depth);
void write(TextOut& text, const Box& b, int depth);
void write(TextOut& text, const Disc& d, int depth);
void write(TextOut& text, const Quadric& q, int depth);
void write(TextOut& text, const Blob& b, int depth);
void write(TextOut& text, const SolidMesh& m, int depth); // a CSG operand's `mesh` block

} // namespace prism::sc

// Cones, open (`cone`) and capped (`capped_cone`, `cylinder` when the radii
// are equal): with both centres and radii when circular; an elliptic one
// (sheared or unevenly scaled) in its own frame, placed inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

namespace {

void writeCone(TextOut& text, const Cone& c, int depth, const char* keyword) {
  const Mat3& m = c.objectToWorld;
  const bool cylinder = keyword == std::string_view("cylinder");
  if (isCircular(c)) {
    const double unit = glm::length(m[0]); // world length of the frame's x
    const Vec3 base = c.objectToWorldOffset, apex = c.objectToWorldOffset + m[2];
    if (cylinder) {
      text.line(depth) << keyword << " " << vec(base) << "  " << vec(apex) << " "
                       << num(c.baseRadius * unit) << "\n";
    } else {
      text.line(depth) << keyword << " " << vec(base) << " " << num(c.baseRadius * unit) << "  "
                       << vec(apex) << " " << num(c.apexRadius * unit) << "\n";
    }
    return;
  }
  text.inFrame(m, c.objectToWorldOffset, depth, [&](int inside) {
    if (cylinder) {
      text.line(inside) << keyword << " 0 0 0  0 0 1 " << num(c.baseRadius) << "\n";
    } else {
      text.line(inside) << keyword << " 0 0 0 " << num(c.baseRadius) << "  0 0 1 "
                        << num(c.apexRadius) << "\n";
    }
  });
}

} // namespace

void write(TextOut& text, const Cone& c, int depth) { writeCone(text, c, depth, "cone"); }

void write(TextOut& text, const CappedCone& c, int depth) {
  const Cone& side = c.side;
  writeCone(text, side, depth, side.baseRadius == side.apexRadius ? "cylinder" : "capped_cone");
}

} // namespace prism::sc

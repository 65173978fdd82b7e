// A disc: `disc` with centre, normal and radius when it is circular; an
// elliptic one (sheared or unevenly scaled) as the disc of its own frame,
// placed inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Disc& d, int depth) {
  const Mat3& m = d.frame.objectToWorld;
  if (isCircular(d)) {
    text.line(depth) << "disc " << vec(d.frame.objectToWorldOffset) << "  "
                     << vec(d.normal + Vec3(0.0)) << " " << num(d.radius * glm::length(m[0]))
                     << "\n";
    return;
  }
  text.inFrame(m, d.frame.objectToWorldOffset, depth, [&](int inside) {
    text.line(inside) << "disc 0 0 0  0 0 1 " << num(d.radius) << "\n";
  });
}

} // namespace prism::sc

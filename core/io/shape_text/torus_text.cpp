// A torus: `torus` with its centre, axis and radii when it is round; a
// stretched one (sheared or unevenly scaled) in its own frame, placed inside
// push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Torus& t, int depth) {
  const Mat3& m = t.objectToWorld;
  if (isRound(t)) {
    const double unit = glm::length(m[0]); // world length of the frame's x
    text.line(depth) << "torus " << vec(t.objectToWorldOffset) << "  " << vec(m[2]) << "  "
                     << num(t.major * unit) << " " << num(t.minor * unit) << "\n";
    return;
  }
  text.inFrame(m, t.objectToWorldOffset, depth, [&](int inside) {
    text.line(inside) << "torus 0 0 0  0 0 1  " << num(t.major) << " " << num(t.minor) << "\n";
  });
}

} // namespace prism::sc

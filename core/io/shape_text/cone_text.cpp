// A cone: `cone` with both centres and radii when it is circular; an elliptic
// one (sheared or unevenly scaled) in its own frame, placed inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Cone& c, int depth) {
  const Mat3& m = c.objectToWorld;
  if (isCircular(c)) {
    const double unit = glm::length(m[0]); // world length of the frame's x
    text.line(depth) << "cone " << vec(c.objectToWorldOffset) << " " << num(c.baseRadius * unit)
                     << "  " << vec(c.objectToWorldOffset + m[2]) << " " << num(c.apexRadius * unit)
                     << "\n";
    return;
  }
  text.line(depth) << "push\n";
  text.placed(m, c.objectToWorldOffset, depth + 1);
  text.line(depth + 1) << "cone 0 0 0 " << num(c.baseRadius) << "  0 0 1 " << num(c.apexRadius)
                       << "\n";
  text.line(depth) << "pop\n";
}

} // namespace prism::sc

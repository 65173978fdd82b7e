// A box: `box` with its corners when it is stored in world coordinates;
// one under a rotation or shear as its corners in its own frame, placed
// inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Box& b, int depth) {
  if (isWorldAligned(b)) {
    text.line(depth) << "box " << vec(b.lo) << "  " << vec(b.hi) << "\n";
    return;
  }
  text.line(depth) << "push\n";
  text.placed(b.frame.objectToWorld, b.frame.objectToWorldOffset, depth + 1);
  text.line(depth + 1) << "box " << vec(b.lo) << "  " << vec(b.hi) << "\n";
  text.line(depth) << "pop\n";
}

} // namespace prism::sc

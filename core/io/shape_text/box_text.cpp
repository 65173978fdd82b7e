// A box: `box` with its corners when it is stored in world coordinates;
// one under a rotation or shear as its corners in its own frame, placed
// inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Box& b, int depth) {
  const auto command = [&](int at) {
    text.line(at) << "box " << vec(b.lo) << "  " << vec(b.hi) << "\n";
  };
  if (isWorldAligned(b))
    command(depth);
  else
    text.inFrame(b.frame.objectToWorld, b.frame.objectToWorldOffset, depth, command);
}

} // namespace prism::sc

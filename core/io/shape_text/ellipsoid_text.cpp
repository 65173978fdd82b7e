// An ellipsoid: the unit sphere under objectToWorld, placed inside push/pop
// (the .sc language has no ellipsoid command; a transformed sphere reads
// back as one).
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Ellipsoid& e, int depth) {
  text.line(depth) << "push\n";
  text.placed(e.objectToWorld, e.center, depth + 1);
  text.line(depth + 1) << "sphere 0 0 0 1\n";
  text.line(depth) << "pop\n";
}

} // namespace prism::sc

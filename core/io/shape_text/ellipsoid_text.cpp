// An ellipsoid: the unit sphere under objectToWorld, placed inside push/pop
// (the .sc language has no ellipsoid command; a transformed sphere reads
// back as one).
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Ellipsoid& e, int depth) {
  text.inFrame(e.objectToWorld, e.center, depth,
               [&](int inside) { text.line(inside) << "sphere 0 0 0 1\n"; });
}

} // namespace prism::sc

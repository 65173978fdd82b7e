// A sphere: `sphere X Y Z RADIUS`.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Sphere& s, int depth) {
  text.line(depth) << "sphere " << vec(s.center) << " " << num(s.radius) << "\n";
}

} // namespace prism::sc

// A polygon: `polygon N` and its vertices, in their stored order.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Polygon& p, int depth) {
  text.line(depth) << "polygon " << p.vertexCount;
  for (std::uint32_t i = 0; i < p.vertexCount; ++i) {
    text.out() << "  " << vec(text.scene().polygonVertices[p.firstVertex + i]);
  }
  text.out() << "\n";
}

} // namespace prism::sc

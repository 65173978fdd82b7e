// A closed mesh operand of CSG: `mesh`, its triangles one a line (each as a
// triangle primitive is written), `end`. They are stored wound outward, so
// they read back unchanged.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const SolidMesh& m, int depth) {
  text.line(depth) << "mesh\n";
  for (const Triangle& t : trianglesOf(m, text.scene().arrays()))
    write(text, t, depth + 1);
  text.line(depth) << "end\n";
}

} // namespace prism::sc

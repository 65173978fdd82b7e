// A quadric: `quadric` with its coefficients as given and clip box; one
// placed by a transform in its own frame inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

namespace {

void command(TextOut& text, const Quadric& q, int depth) {
  std::ostream& out = text.line(depth) << "quadric";
  for (const double c : givenCoefficients(q))
    out << " " << num(c);
  out << "  " << vec(q.lo) << "  " << vec(q.hi) << "\n";
}

} // namespace

void write(TextOut& text, const Quadric& q, int depth) {
  if (isUnplaced(q)) {
    command(text, q, depth);
    return;
  }
  text.inFrame(q.frame.objectToWorld, q.frame.objectToWorldOffset, depth,
               [&](int inside) { command(text, q, inside); });
}

} // namespace prism::sc

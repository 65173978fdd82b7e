// A blob: `blob` with its threshold and components, one component a line;
// one with a frame (written under a stretching transform) in that frame,
// placed inside push/pop.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

namespace {

void blobCommand(TextOut& text, const Blob& b, int depth) {
  text.line(depth) << "blob " << num(b.threshold) << " " << b.componentCount << "\n";
  for (const BlobComponent& c : componentsOf(b, text.scene().arrays()))
    text.line(depth + 1) << vec(c.center) << "  " << num(c.radius) << " " << num(c.strength)
                         << "\n";
}

} // namespace

void write(TextOut& text, const Blob& b, int depth) {
  if (!b.placed) {
    blobCommand(text, b, depth);
    return;
  }
  text.inFrame(b.frame.objectToWorld, b.frame.objectToWorldOffset, depth,
               [&](int inside) { blobCommand(text, b, inside); });
}

} // namespace prism::sc

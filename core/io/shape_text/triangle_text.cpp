// A mesh triangle: `triangle` with its three vertices, or `ptriangle` with
// each vertex followed by its normal when it is smooth; `triangle_uv` and
// `ptriangle_uv` add each vertex's surface coordinates U V last.
#include "core/io/shape_text/shape_text.h"

namespace prism::sc {

void write(TextOut& text, const Triangle& t, int depth, const std::array<Vec2, 3>* uvs) {
  const Scene& scene = text.scene();
  text.line(depth) << (t.smooth() ? "ptriangle" : "triangle") << (uvs != nullptr ? "_uv" : "");
  for (int i = 0; i < 3; ++i) {
    text.out() << "  " << vec(scene.meshVertices[t.vertex[std::size_t(i)]]);
    if (t.smooth()) text.out() << "  " << vec(scene.meshNormals[t.normal[std::size_t(i)]]);
    if (uvs != nullptr) {
      const Vec2& uv = (*uvs)[std::size_t(i)];
      text.out() << "  " << num(uv.x) << " " << num(uv.y);
    }
  }
  text.out() << "\n";
}

} // namespace prism::sc

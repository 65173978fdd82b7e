#include "core/io/scene_writer.h"

#include "core/io/pending_file.h"
#include "core/io/shape_text/shape_text.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace prism {

namespace {

using sc::num;
using sc::vec;

class Writer {
public:
  Writer(std::ostream& out, const Scene& scene) : out_(out), scene_(scene), text_(out, scene) {}

  void header(const std::string& text) {
    std::istringstream lines(text);
    std::string comment;
    while (std::getline(lines, comment))
      out_ << "# " << comment << "\n";
  }

  void globals() {
    const CameraSpec& c = scene_.camera;
    out_ << "resolution " << scene_.width << " " << scene_.height << "\n";
    out_ << "eye " << vec(c.eye) << "\nlookat " << vec(c.lookat) << "\nup " << vec(c.up) << "\n";
    out_ << "fov " << num(c.fov) << "\n";
    out_ << "background " << vec(scene_.background) << "\n";
    out_ << "ambient " << vec(scene_.ambient) << "\n";
    if (scene_.fog.active())
      out_ << "fog " << vec(scene_.fog.color) << "  " << num(scene_.fog.density) << "\n";
    for (const Light& l : scene_.lights) {
      out_ << "light " << vec(l.position) << " " << vec(l.intensity) << "\n";
    }
  }

  // Every group's own primitives, then its sub-groups, each inside push/pop.
  // Groups may nest as deep as the reader allows, so the walk keeps its own
  // stack rather than recursing.
  void groups() {
    struct Open {
      std::uint32_t group;
      std::size_t nextChild = 0;
      Material saved; // the material `pop` restores
    };
    primitives(0, 0);
    std::vector<Open> open{{0, 0, current_}};
    while (!open.empty()) {
      const int depth = int(open.size()) - 1;
      Open& top = open.back();
      const Group& g = scene_.groups[top.group];
      if (top.nextChild == g.children.size()) {
        current_ = top.saved;
        open.pop_back();
        if (depth > 0) line(depth - 1) << "pop\n";
        continue;
      }
      const std::uint32_t child = g.children[top.nextChild++];
      line(depth) << "push\n";
      open.push_back({child, 0, current_}); // invalidates top
      primitives(child, depth + 1);
    }
  }

private:
  std::ostream& line(int depth) { return text_.line(depth); }

  void primitives(std::uint32_t group, int depth) {
    for (const PrimitiveRef& ref : scene_.groups[group].primitives)
      primitive(ref, depth);
  }

  void material(const Material& m, int depth) {
    if (m == current_) return;
    line(depth) << "surface " << vec(m.color) << "  " << num(m.kdr) << " " << num(m.ksr) << " "
                << num(m.kst) << "  " << num(m.e) << " " << num(m.ir) << "\n";
    if (m.absorbs()) line(depth) << "absorption " << vec(m.absorption) << "\n";
    if (m.texture.active()) texture(m.texture, depth);
    if (m.image.active()) image(m.image, depth);
    current_ = m;
  }

  // The path as the scene resolved it (absolute), so the text reads the
  // same image wherever it is written.
  void image(const ImageMap& map, int depth) {
    const ImageInfo& info = scene_.images->info(map.image);
    std::ostream& out = line(depth) << "image \"" << info.path << "\" " << imageWrapName(map.wrap)
                                    << " " << imageEncodingName(info.asked);
    if (!map.filtered) out << " unfiltered";
    out << "\n";
    if (map.scale != Vec2(1.0) || map.offset != Vec2(0.0))
      line(depth) << "uv " << num(map.scale.x) << " " << num(map.scale.y) << "  "
                  << num(map.offset.x) << " " << num(map.offset.y) << "\n";
  }

  // The texture's map from the world (its primitive's object space composed
  // in) is written whole, as `texture_space`, which the reader takes as it
  // is: a shape may be written under a transform of its own (push,
  // translate, ...), which must not move its texture again.
  void texture(const Texture& t, int depth) {
    line(depth) << "texture " << textureKindName(t.kind) << " " << num(t.scale) << "  "
                << vec(t.color) << "  " << num(t.kdr) << " " << num(t.ksr) << " " << num(t.kst)
                << "  " << num(t.e) << "\n";
    std::ostream& out = line(depth) << "texture_space";
    for (int row = 0; row < 3; ++row) {
      out << " ";
      for (int column = 0; column < 3; ++column)
        out << " " << num(t.linear[column][row]);
      out << " " << num(t.offset[row]);
    }
    out << "\n";
  }

  // Each kind's text is written by its own file (core/io/shape_text/); a
  // CSG node's here, for its operands' materials.
  void primitive(const PrimitiveRef& ref, int depth) {
    if (ref.kind == kindOf<Csg>) {
      csg(scene_.shapes<Csg>()[ref.index], depth);
      return;
    }
    material(scene_.material(ref), depth);
    if (ref.kind == kindOf<Triangle>) {
      triangle(ref.index, depth);
      return;
    }
    scene_.visit(ref, [&](const auto& shape) {
      if constexpr (!std::is_same_v<std::decay_t<decltype(shape)>, Csg>)
        sc::write(text_, shape, depth);
    });
  }

  // A triangle with surface coordinates of its own as `triangle_uv` or
  // `ptriangle_uv`; one whose coordinates are the barycentric default (or
  // beyond the end of Scene::triangleUvs) as `triangle` or `ptriangle`.
  void triangle(std::uint32_t index, int depth) {
    static constexpr std::array<Vec2, 3> kBarycentric = {Vec2(0.0), Vec2(1.0, 0.0), Vec2(0.0, 1.0)};
    const std::array<Vec2, 3>* uvs =
        index < scene_.triangleUvs.size() ? &scene_.triangleUvs[index] : nullptr;
    if (uvs != nullptr && *uvs == kBarycentric) uvs = nullptr;
    sc::write(text_, scene_.shapes<Triangle>()[index], depth, uvs);
  }

  // `csg OPERATION`, each operand after its material, `end`: the block
  // restores the material it began with, as the reader does.
  void csg(const Csg& node, int depth) {
    material(scene_.materials[node.material], depth);
    const Material saved = current_;
    line(depth) << "csg " << csgOpName(node.op) << "\n";
    for (const CsgOperand& operand : operandsOf(node, scene_.arrays())) {
      std::visit(
          [&](const auto& shape) {
            if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>) {
              csg(scene_.csgNodes[shape.index], depth + 1);
            } else {
              material(scene_.materials[shape.material], depth + 1);
              sc::write(text_, shape, depth + 1);
            }
          },
          operand.shape);
    }
    line(depth) << "end\n";
    current_ = saved;
  }

  std::ostream& out_;
  const Scene& scene_;
  sc::TextOut text_;
  Material current_; // the parser's default surface
};

} // namespace

void writeScene(std::ostream& out, const Scene& scene, const std::string& header) {
  Writer w(out, scene);
  w.header(header);
  w.globals();
  w.groups();
}

void saveScene(const std::filesystem::path& path, const Scene& scene, const std::string& header) {
  writeFileAtomically(path, [&](std::ostream& out) { writeScene(out, scene, header); });
}

} // namespace prism

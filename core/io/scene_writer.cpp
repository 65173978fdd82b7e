#include "core/io/scene_writer.h"

#include "core/io/pending_file.h"
#include "core/math/affine_decompose.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace prism {

namespace {

// The shortest text that reads back as exactly `x` (std::to_chars).
std::string num(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string vec(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

class Writer {
public:
  Writer(std::ostream& out, const Scene& scene) : out_(out), scene_(scene) {}

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
  // Starts a line indented by two spaces per level, up to kMaxIndent levels:
  // deeper nesting is not indented further, or the output would grow with
  // the square of the depth.
  static constexpr int kMaxIndent = 16;
  std::ostream& line(int depth) {
    return out_ << std::string(std::size_t(std::min(depth, kMaxIndent)) * 2, ' ');
  }

  void primitives(std::uint32_t group, int depth) {
    for (const PrimitiveRef& ref : scene_.groups[group].primitives)
      primitive(ref, depth);
  }

  void material(const Material& m, int depth) {
    if (m == current_) return;
    line(depth) << "surface " << vec(m.color) << "  " << num(m.kdr) << " " << num(m.ksr) << " "
                << num(m.kst) << "  " << num(m.e) << " " << num(m.ir) << "\n";
    current_ = m;
  }

  // translate, rotate, scale, rotate: the map x -> offset + a x, for an
  // object written in its own frame.
  void placed(const Mat3& a, const Vec3& offset, int depth) {
    const RotationScaleRotation d = decompose(a);
    line(depth) << "translate " << vec(offset) << "\n";
    Vec3 axis;
    double degrees;
    axisAngle(d.u, axis, degrees);
    line(depth) << "rotate " << vec(axis) << " " << num(degrees) << "\n";
    line(depth) << "scale " << vec(d.scale) << "\n";
    axisAngle(glm::transpose(d.v), axis, degrees);
    line(depth) << "rotate " << vec(axis) << " " << num(degrees) << "\n";
  }

  void primitive(const PrimitiveRef& ref, int depth) {
    material(scene_.material(ref), depth);
    scene_.visit(ref, [&](const auto& shape) { write(shape, depth); });
  }

  void write(const Sphere& s, int depth) {
    line(depth) << "sphere " << vec(s.center) << " " << num(s.radius) << "\n";
  }

  // The unit sphere under objectToWorld.
  void write(const Ellipsoid& e, int depth) {
    line(depth) << "push\n";
    placed(e.objectToWorld, e.center, depth + 1);
    line(depth + 1) << "sphere 0 0 0 1\n";
    line(depth) << "pop\n";
  }

  void write(const Polygon& p, int depth) {
    line(depth) << "polygon " << p.vertexCount;
    for (std::uint32_t i = 0; i < p.vertexCount; ++i) {
      out_ << "  " << vec(scene_.polygonVertices[p.firstVertex + i]);
    }
    out_ << "\n";
  }

  void write(const Triangle& t, int depth) {
    line(depth) << (t.smooth() ? "ptriangle" : "triangle");
    for (int i = 0; i < 3; ++i) {
      out_ << "  " << vec(scene_.meshVertices[t.vertex[std::size_t(i)]]);
      if (t.smooth()) out_ << "  " << vec(scene_.meshNormals[t.normal[std::size_t(i)]]);
    }
    out_ << "\n";
  }

  void write(const Cone& c, int depth) {
    const Mat3& m = c.objectToWorld;
    if (isCircular(c)) {
      const double unit = glm::length(m[0]); // world length of the frame's x
      line(depth) << "cone " << vec(c.objectToWorldOffset) << " " << num(c.baseRadius * unit)
                  << "  " << vec(c.objectToWorldOffset + m[2]) << " " << num(c.apexRadius * unit)
                  << "\n";
      return;
    }
    // Elliptic (sheared or unevenly scaled): the cone in its own frame, placed.
    line(depth) << "push\n";
    placed(m, c.objectToWorldOffset, depth + 1);
    line(depth + 1) << "cone 0 0 0 " << num(c.baseRadius) << "  0 0 1 " << num(c.apexRadius)
                    << "\n";
    line(depth) << "pop\n";
  }

  std::ostream& out_;
  const Scene& scene_;
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

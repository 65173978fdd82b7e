// `prism convert`'s promise (core/io/scene_writer.h): the .sc text written for a
// scene reads back as the same scene. The input is read as .sc, or as NFF or
// OBJ when its first line is `#!nff` or `#!obj` (a comment in all three);
// whatever loads is written with writeScene, parsed back with parseScene and
// compared. Any difference, or text that does not read back, is a crash.
#include "core/io/nff_reader.h"
#include "core/io/obj_reader.h"
#include "core/io/scene_writer.h"
#include "fuzz/fuzz_check.h"

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>

using namespace prism;

namespace {

std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string num(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

// The first difference between the original and the scene read back.
class Comparison {
public:
  template <typename T> void same(const char* what, const T& a, const T& b) {
    if (!problem_ && !(a == b)) problem_ = std::string(what) + " differ";
  }
  void same(const char* what, const Vec3& a, const Vec3& b) {
    if (!problem_ && a != b) problem_ = std::string(what) + ": " + num(a) + " vs " + num(b);
  }
  // For what the writer must decompose (ellipsoids, elliptic cones, tori) or the
  // reader normalises again (vertex normals): equal up to round-off.
  void near(const char* what, const Vec3& a, const Vec3& b, double scale) {
    const double tolerance = 1e-9 * std::max({maxAbsComponent(a), maxAbsComponent(b), scale});
    if (!problem_ && !(maxAbsComponent(a - b) <= tolerance)) {
      problem_ = std::string(what) + ": " + num(a) + " vs " + num(b);
    }
  }
  const std::optional<std::string>& problem() const { return problem_; }

private:
  std::optional<std::string> problem_;
};

// Triangle i's surface coordinates: its own, or the barycentric ones.
std::array<Vec2, 3> uvsOf(const Scene& scene, std::uint32_t i) {
  if (i < scene.triangleUvs.size()) return scene.triangleUvs[i];
  return {Vec2(0.0), Vec2(1.0, 0.0), Vec2(0.0, 1.0)};
}

// Primitives in the order the writer visits them (a group's own, then its
// sub-groups), which is the file order of the text it writes and so the order
// in which parseScene stores them.
void writerOrder(const Scene& scene, std::uint32_t group, std::vector<PrimitiveRef>& out) {
  const Group& g = scene.groups[group];
  out.insert(out.end(), g.primitives.begin(), g.primitives.end());
  for (const std::uint32_t child : g.children) {
    writerOrder(scene, child, out);
  }
}

void compare(const Scene& a, const Scene& b, Comparison& c) {
  c.same("resolutions", std::pair(a.width, a.height), std::pair(b.width, b.height));
  c.same("eyes", a.camera.eye, b.camera.eye);
  c.same("lookats", a.camera.lookat, b.camera.lookat);
  c.same("ups", a.camera.up, b.camera.up);
  c.same("fovs", a.camera.fov, b.camera.fov);
  c.same("backgrounds", a.background, b.background);
  c.same("ambients", a.ambient, b.ambient);
  c.same("light counts", a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < std::min(a.lights.size(), b.lights.size()); ++i) {
    c.same("light positions", a.lights[i].position, b.lights[i].position);
    c.same("light intensities", a.lights[i].intensity, b.lights[i].intensity);
  }
  c.same("sphere counts", a.shapes<Sphere>().size(), b.shapes<Sphere>().size());
  c.same("ellipsoid counts", a.shapes<Ellipsoid>().size(), b.shapes<Ellipsoid>().size());
  c.same("polygon counts", a.shapes<Polygon>().size(), b.shapes<Polygon>().size());
  c.same("cone counts", a.shapes<Cone>().size(), b.shapes<Cone>().size());
  c.same("triangle counts", a.shapes<Triangle>().size(), b.shapes<Triangle>().size());
  c.same("torus counts", a.shapes<Torus>().size(), b.shapes<Torus>().size());
  c.same("box counts", a.shapes<Box>().size(), b.shapes<Box>().size());
  c.same("disc counts", a.shapes<Disc>().size(), b.shapes<Disc>().size());
  c.same("capped cone counts", a.shapes<CappedCone>().size(), b.shapes<CappedCone>().size());
  c.same("quadric counts", a.shapes<Quadric>().size(), b.shapes<Quadric>().size());
  c.same("csg counts", a.shapes<Csg>().size(), b.shapes<Csg>().size());
  c.same("csg operand counts", a.csgOperands.size(), b.csgOperands.size());
  c.same("nested csg counts", a.csgNodes.size(), b.csgNodes.size());
  c.same("blob counts", a.shapes<Blob>().size(), b.shapes<Blob>().size());
  c.same("blob component counts", a.blobComponents.size(), b.blobComponents.size());
  c.same("mesh operand triangle counts", a.meshTriangles.size(), b.meshTriangles.size());
  if (c.problem()) return;

  std::vector<PrimitiveRef> order;
  writerOrder(a, 0, order);
  c.same("primitive counts (some primitive is in no group)", order.size(), a.primitiveCount());
  std::array<std::uint32_t, kShapeKindCount> next{}; // per kind, the next index in b
  for (const PrimitiveRef& ra : order) {
    if (c.problem()) return;
    const PrimitiveRef rb{ra.kind, next[std::size_t(ra.kind)]++};
    c.same("materials", a.material(ra), b.material(rb));
    const Aabb boxA = a.bounds(ra), boxB = b.bounds(rb);
    const double size = maxAbsComponent(boxA.hi - boxA.lo);
    switch (ra.kind) {
    case kindOf<Sphere>:
      c.same("sphere centres", a.shapes<Sphere>()[ra.index].center,
             b.shapes<Sphere>()[rb.index].center);
      c.same("sphere radii", a.shapes<Sphere>()[ra.index].radius,
             b.shapes<Sphere>()[rb.index].radius);
      break;
    case kindOf<Polygon>: {
      const Polygon& pa = a.shapes<Polygon>()[ra.index];
      const Polygon& pb = b.shapes<Polygon>()[rb.index];
      c.same("polygon vertex counts", pa.vertexCount, pb.vertexCount);
      for (std::uint32_t i = 0; i < std::min(pa.vertexCount, pb.vertexCount); ++i) {
        c.same("polygon vertices", a.polygonVertices[pa.firstVertex + i],
               b.polygonVertices[pb.firstVertex + i]);
      }
      break;
    }
    case kindOf<Triangle>: {
      const Triangle& ta = a.shapes<Triangle>()[ra.index];
      const Triangle& tb = b.shapes<Triangle>()[rb.index];
      c.same("triangle smoothness", ta.smooth(), tb.smooth());
      c.same("triangle uvs", uvsOf(a, ra.index), uvsOf(b, rb.index));
      for (std::size_t i = 0; i < 3 && !c.problem(); ++i) {
        c.same("triangle vertices", a.meshVertices[ta.vertex[i]], b.meshVertices[tb.vertex[i]]);
        if (ta.smooth() && tb.smooth()) {
          c.near("vertex normals", a.meshNormals[ta.normal[i]], b.meshNormals[tb.normal[i]], 1.0);
        }
      }
      break;
    }
    case kindOf<Quadric>: {
      // The coefficients and the clip box are written as given: exact; the
      // frame's map decomposed, so its bounds to round-off.
      const Quadric& qa = a.shapes<Quadric>()[ra.index];
      const Quadric& qb = b.shapes<Quadric>()[rb.index];
      c.same("quadric coefficients", qa.coef, qb.coef);
      c.same("quadric clip boxes (lo)", qa.lo, qb.lo);
      c.same("quadric clip boxes (hi)", qa.hi, qb.hi);
      c.near("quadric bounds (lo)", boxA.lo, boxB.lo, size);
      c.near("quadric bounds (hi)", boxA.hi, boxB.hi, size);
      break;
    }
    case kindOf<Blob>: {
      // The components as stored (in the world, or in the frame of a
      // stretched blob) are written exactly; a frame through its map.
      const Blob& ba = a.shapes<Blob>()[ra.index];
      const Blob& bb = b.shapes<Blob>()[rb.index];
      c.same("blob thresholds", ba.threshold, bb.threshold);
      c.same("blob frames", ba.placed, bb.placed);
      c.same("blob component counts", ba.componentCount, bb.componentCount);
      for (std::uint32_t i = 0; i < std::min(ba.componentCount, bb.componentCount); ++i) {
        const BlobComponent& ca = a.blobComponents[ba.firstComponent + i];
        const BlobComponent& cb = b.blobComponents[bb.firstComponent + i];
        c.same("blob component centres", ca.center, cb.center);
        c.same("blob component radii", ca.radius, cb.radius);
        c.same("blob component strengths", ca.strength, cb.strength);
      }
      c.near("blob bounds (lo)", boxA.lo, boxB.lo, size);
      c.near("blob bounds (hi)", boxA.hi, boxB.hi, size);
      break;
    }
    case kindOf<Ellipsoid>:
    case kindOf<Cone>:
    case kindOf<Torus>:
    case kindOf<Box>:
    case kindOf<Disc>:
    case kindOf<CappedCone>:
      c.near("placed shape bounds (lo)", boxA.lo, boxB.lo, size);
      c.near("placed shape bounds (hi)", boxA.hi, boxB.hi, size);
      break;
    case kindOf<Csg>: {
      // The operation, the operands' count and what the node can cover (its
      // operands come back in the order written, so their places too).
      const Csg& na = a.shapes<Csg>()[ra.index];
      const Csg& nb = b.shapes<Csg>()[rb.index];
      c.same("csg operations", int(na.op), int(nb.op));
      c.same("csg operand counts", na.operandCount, nb.operandCount);
      c.same("csg first operands", na.firstOperand, nb.firstOperand);
      if (!boxA.empty() && !boxB.empty()) {
        c.near("csg bounds (lo)", boxA.lo, boxB.lo, size);
        c.near("csg bounds (hi)", boxA.hi, boxB.hi, size);
      }
      break;
    }
    }
  }
}

std::optional<Scene> load(std::string_view text) {
  try {
    if (text.starts_with("#!nff\n")) return parseNff(text, "fuzz.nff");
    if (text.starts_with("#!obj\n")) {
      if (fuzz::mtllibLeavesSandbox(text)) return std::nullopt;
      return loadObj(fuzz::stageObj(text));
    }
    if (fuzz::includeLeavesSandbox(text)) return std::nullopt;
    return parseScene(text, (fuzz::sandbox() / "main.sc").string());
  } catch (const SceneError&) {
    return std::nullopt; // the readers' own targets check rejections
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input = fuzz::asText(data, size);
  const std::optional<Scene> scene = load(input);
  if (!scene) return 0;
  std::ostringstream out;
  writeScene(out, *scene, "written by the round-trip fuzzer\nsecond line");
  const std::string written = out.str();
  Scene back;
  try {
    back = parseScene(written, (fuzz::sandbox() / "written.sc").string());
  } catch (const SceneError& e) {
    fuzz::fail(std::string("the written scene does not read back:\n") + e.what() +
                   "\n==prism-fuzz== written text:\n" + written.substr(0, 4096),
               input);
  }
  Comparison c;
  compare(*scene, back, c);
  if (c.problem()) {
    fuzz::fail("the scene read back differs: " + *c.problem() + "\n==prism-fuzz== written text:\n" +
                   written.substr(0, 4096),
               input);
  }
  return 0;
}

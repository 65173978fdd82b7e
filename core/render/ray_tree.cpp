#include "core/render/ray_tree.h"

#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace prism {

namespace {

std::string fmt(const Vec3& v) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// ", operand sphere (csg.sc:73)": the leaf of a CSG node the ray met, found
// again here (only the ray tree asks, so tracing never pays for it); "" for
// other kinds.
std::string operandOf(const RayTreeNode& node, const Scene& scene) {
  const PrimitiveRef ref = node.where.primitive;
  if (ref.kind != kindOf<Csg>) return "";
  const CsgOperand* leaf =
      operandAlong(scene.shapes<Csg>()[ref.index], scene.arrays(), node.ray, node.where.t);
  if (leaf == nullptr) return "";
  return std::visit(
      [&](const auto& shape) -> std::string {
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>)
          return ""; // never: nested nodes are not leaves
        else
          return std::string(", operand ") + shape.kName + scene.placeOf(shape.origin);
      },
      leaf->shape);
}

// The line saying what the segment's fog or absorbing solid did.
void printMedium(std::ostream& out, const std::string& pad, const RayTreeNode& node,
                 const Scene& scene) {
  switch (node.medium) {
  case SegmentMedium::Unrecorded: return;
  case SegmentMedium::Clear:
    out << pad << "  through clear space (d = " << node.segmentLength << ")";
    break;
  case SegmentMedium::Fog:
    out << pad << "  through fog: d = " << node.segmentLength
        << ", exp(-density d) = " << node.transmittance.r << ", fog colour "
        << fmt(scene.fog.color);
    break;
  case SegmentMedium::Absorber:
    out << pad << "  inside a solid: d = " << node.segmentLength
        << ", exp(-absorption d) = " << fmt(node.transmittance);
    break;
  }
  out << ": at the origin " << fmt(node.atOrigin) << "\n";
}

void printNode(std::ostream& out, const RayTreeNode& node, const Scene& scene, int indent) {
  const std::string pad(std::size_t(indent) * 2, ' ');
  out << pad << rayKindName(node.kind) << " ray, depth " << node.depth << ": origin "
      << fmt(node.ray.origin) << " dir " << fmt(node.ray.dir) << "\n";
  if (!node.hit) {
    out << pad << "  misses everything: background " << fmt(node.radiance) << "\n";
    printMedium(out, pad, node, scene);
    return;
  }
  out << pad << "  hits " << scene.describe(node.where.primitive) << operandOf(node, scene)
      << " at t = " << node.where.t << ", point " << fmt(node.point) << "\n";
  out << pad << "  outward normal " << fmt(node.normal) << ", "
      << (node.leaving ? "leaving (N.D > 0)" : "entering (N.D <= 0)") << ", shading normal "
      << fmt(node.shadingNormal) << "\n";
  out << pad << "  surface (u, v) = (" << node.uv.x << ", " << node.uv.y << ")";
  if (node.part != 0) out << ", part " << node.part;
  out << "\n";
  if (node.textureKind != TextureKind::None) {
    out << pad << "  texture " << textureKindName(node.textureKind) << " (scale "
        << node.textureScale << ") at texture-space point " << fmt(node.texture.point) << ": value "
        << node.texture.value << ", the material blended to it:\n";
  }
  if (const ImageLookup& i = node.image; i.image != kNoImage) {
    const ImageInfo& info = scene.images->info(i.image);
    out << pad << "  image '" << info.path << "' (" << info.width << " x " << info.height << ", "
        << imageEncodingName(info.decoded) << ") at (s, t) = (" << i.st.x << ", " << i.st.y
        << "), footprint " << i.footprint << " wide, axes (" << i.dx.x << ", " << i.dx.y
        << ") and (" << i.dy.x << ", " << i.dy.y << "): linear " << fmt(i.value) << ", times C:\n";
  }
  const Material& m = node.material;
  out << pad << "  material C " << fmt(m.color) << " kdr " << m.kdr << " ksr " << m.ksr << " kst "
      << m.kst << " e " << m.e << " ir " << m.ir << "\n";
  for (const LightTerm& t : node.lights) {
    out << pad << "  light " << t.light << ": r = " << t.distance << ", N.L = " << t.cosine;
    if (t.behind) {
      out << ", behind the surface: s = 0, no shadow ray\n";
    } else if (t.skipped) {
      out << ", material reflects no light: no shadow ray\n";
    } else if (t.shadowed) {
      out << ", shadowed by " << scene.describe(t.blocker.primitive) << " at t = " << t.blocker.t
          << ": s = 0\n";
    } else {
      out << ", lit: s = 1, diffuse I*N.L/r^2 = " << fmt(t.diffuse)
          << ", specular I*(N.H)^e/r^2 = " << fmt(t.specular) << "\n";
    }
  }
  out << pad << "  C kdr [Ia + sum diffuse] = " << fmt(node.ambientDiffuse) << "\n";
  out << pad << "  ksr sum specular        = " << fmt(node.highlight) << "\n";
  out << pad << "  ksr I_r                 = " << fmt(node.reflected) << "\n";
  out << pad << "  kst I_t                 = " << fmt(node.transmitted)
      << (node.totalInternalReflection ? "  (total internal reflection: no transmitted ray)" : "")
      << "\n";
  out << pad << "  radiance                = " << fmt(node.radiance) << "\n";
  printMedium(out, pad, node, scene);
  for (const RayTreeNode& child : node.children)
    printNode(out, child, scene, indent + 1);
}

} // namespace

void printRayTree(std::ostream& out, const RayTreeNode& root, const Scene& scene) {
  printNode(out, root, scene, 0);
}

} // namespace prism

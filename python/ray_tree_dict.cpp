#include "ray_tree_dict.h"

#include "core/texture/image_library.h"

#include <string>

namespace py = pybind11;

namespace prism::python {

py::tuple tupleOf(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }

namespace {

py::dict materialDict(const Material& m) {
  py::dict d;
  d["color"] = tupleOf(m.color);
  d["kdr"] = m.kdr;
  d["ksr"] = m.ksr;
  d["kst"] = m.kst;
  d["exponent"] = m.e;
  d["index"] = m.ir;
  return d;
}

py::dict lightDict(const LightTerm& t, const Scene& scene) {
  py::dict d;
  d["light"] = t.light; // 1-based, as the scene file numbers lights
  d["distance"] = t.distance;
  d["cosine"] = t.cosine;
  d["behind"] = t.behind;
  d["skipped"] = t.skipped;
  d["shadowed"] = t.shadowed;
  if (t.shadowed) {
    d["blocker"] = scene.describe(t.blocker.primitive);
    d["blocker_t"] = t.blocker.t;
  }
  d["diffuse"] = tupleOf(t.diffuse);
  d["specular"] = tupleOf(t.specular);
  return d;
}

const char* mediumName(SegmentMedium medium) {
  switch (medium) {
  case SegmentMedium::Unrecorded: break;
  case SegmentMedium::Clear: return "clear";
  case SegmentMedium::Fog: return "fog";
  case SegmentMedium::Absorber: return "absorber";
  }
  return nullptr;
}

void addMedium(py::dict& d, const RayTreeNode& node) {
  const char* name = mediumName(node.medium);
  if (name == nullptr) return; // a scene without fog or absorbing solids
  py::dict m;
  m["kind"] = name;
  m["length"] = node.segmentLength;
  m["transmittance"] = tupleOf(node.transmittance);
  m["at_origin"] = tupleOf(node.atOrigin);
  d["medium"] = m;
}

void addSurface(py::dict& d, const RayTreeNode& node, const Scene& scene) {
  d["primitive"] = scene.describe(node.where.primitive);
  d["t"] = node.where.t;
  d["point"] = tupleOf(node.point);
  d["normal"] = tupleOf(node.normal);
  d["shading_normal"] = tupleOf(node.shadingNormal);
  d["uv"] = py::make_tuple(node.uv.x, node.uv.y);
  d["part"] = node.part;
  d["leaving"] = node.leaving;
  if (node.textureKind != TextureKind::None) {
    py::dict t;
    t["kind"] = std::string(textureKindName(node.textureKind));
    t["scale"] = node.textureScale;
    t["point"] = tupleOf(node.texture.point);
    t["value"] = node.texture.value;
    d["texture"] = t;
  }
  if (node.image.image != kNoImage && scene.images) {
    py::dict i;
    i["path"] = scene.images->info(node.image.image).path;
    i["st"] = py::make_tuple(node.image.st.x, node.image.st.y);
    i["footprint"] = node.image.footprint;
    i["value"] = tupleOf(node.image.value);
    d["image"] = i;
  }
  d["material"] = materialDict(node.material);
  py::list lights;
  for (const LightTerm& t : node.lights)
    lights.append(lightDict(t, scene));
  d["lights"] = lights;
  d["ambient_diffuse"] = tupleOf(node.ambientDiffuse);
  d["highlight"] = tupleOf(node.highlight);
  d["reflected"] = tupleOf(node.reflected);
  d["transmitted"] = tupleOf(node.transmitted);
  d["total_internal_reflection"] = node.totalInternalReflection;
}

} // namespace

py::dict rayTreeDict(const RayTreeNode& node, const Scene& scene) {
  py::dict d;
  d["kind"] = rayKindName(node.kind);
  d["depth"] = node.depth;
  d["origin"] = tupleOf(node.ray.origin);
  d["direction"] = tupleOf(node.ray.dir);
  d["hit"] = node.hit;
  if (node.hit) addSurface(d, node, scene);
  d["radiance"] = tupleOf(node.radiance); // leaving the hit point, or the background
  addMedium(d, node);
  py::list children;
  for (const RayTreeNode& child : node.children)
    children.append(rayTreeDict(child, scene));
  d["children"] = children;
  return d;
}

} // namespace prism::python

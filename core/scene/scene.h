// A parsed scene: immutable once built, shared read-only by every render thread.
#pragma once

#include "core/scene/camera.h"
#include "core/scene/material.h"
#include "core/shapes/polygon_edges.h"
#include "core/shapes/shape_kinds.h"
#include "core/texture/image_library.h"

#include <array>
#include <memory>

#include <string>
#include <vector>

namespace prism {

struct Light {
  Vec3 position{0.0}; // world space (the scene transform already applied)
  Color intensity{1.0};
};

// Homogeneous fog filling the space outside every solid (`fog`): radiance L
// arriving along a segment of length d in it becomes
// exp(-density d) L + (1 - exp(-density d)) color. Density 0: no fog.
struct Fog {
  Color color{0.0};
  double density = 0.0; // per unit of world length

  bool active() const { return density > 0.0; }
};

// One push/pop group: the modeller's hint for the bounding-volume hierarchy.
// Scene::groups[0] is the top level of the main file.
struct Group {
  std::vector<PrimitiveRef> primitives; // written directly in this group
  std::vector<std::uint32_t> children;  // indices into Scene::groups
  Origin origin;                        // where its `push` was written
};

struct Scene {
  CameraSpec camera;
  int width = 512; // `resolution`; the command line may override it
  int height = 512;
  Color background{0.0};
  Color ambient{0.0};
  Fog fog;

  std::vector<Light> lights; // light i of the user interface is lights[i - 1]
  std::vector<Material> materials;
  // Some material absorbs (Material::absorbs). SceneBuilder keeps it as it
  // adds materials (every reader and generator adds them through it); code
  // that fills `materials` itself sets it too.
  bool absorbingMaterials = false;
  // Some material is textured (Material::textured), kept the same way: the
  // tracer then looks at each hit's material for a texture, and otherwise
  // not at all.
  bool texturedMaterials = false;
  ShapeStorage<ShapeKinds> storage; // the primitives, a vector per kind: use shapes<Kind>()
  std::vector<Vec3> polygonVertices;
  std::vector<PolygonEdgeIndex> polygonEdgeIndices; // of the polygons with many vertices
  std::vector<Vec3> meshVertices;                   // shared by triangles (Triangle::vertex)
  std::vector<Vec3> meshNormals;                    // unit vertex normals of smooth triangles
  // Per-vertex surface coordinates of the triangles (OBJ `vt`, .sc
  // `triangle_uv`), parallel to shapes<Triangle>(); empty when no triangle
  // has them, and it may end before the last triangles. A triangle without
  // its own has (0, 0), (1, 0), (0, 1): its barycentric coordinates.
  std::vector<std::array<Vec2, 3>> triangleUvs;
  // The images the materials' image maps read (ImageMap::image); null when
  // there are none. Shared by the scene's copies.
  std::shared_ptr<ImageLibrary> images;
  // The operands of every CSG node and the nested nodes (csg.h); the roots
  // are primitives, in shapes<Csg>().
  std::vector<CsgOperand> csgOperands;
  std::vector<Csg> csgNodes;
  std::vector<BlobComponent> blobComponents; // of the blobs (Blob::firstComponent)
  // The triangles of the closed meshes that are CSG operands and their trees
  // (solid_mesh.h); the vertices and normals are in meshVertices/meshNormals.
  std::vector<Triangle> meshTriangles;
  std::vector<MeshTreeNode> meshTreeNodes;
  std::vector<std::uint32_t> meshTreeOrder; // parallel to meshTriangles
  std::vector<Group> groups{Group{}};
  std::vector<std::string> files; // files[0] is the main scene file

  template <class Kind> std::vector<Kind>& shapes() {
    return std::get<std::vector<Kind>>(storage.vectors);
  }
  template <class Kind> const std::vector<Kind>& shapes() const {
    return std::get<std::vector<Kind>>(storage.vectors);
  }
  // Fog or an absorbing material: radiance changes along the segments of
  // rays (core/render/media.h). Cheap, for a tracer of every tile; the fog
  // is read as it is now (the previewer edits it live).
  bool hasMedia() const { return fog.active() || absorbingMaterials; }

  std::size_t primitiveCount() const {
    return std::apply([](const auto&... v) { return (v.size() + ...); }, storage.vectors);
  }
  // The arrays shapes index into, as the shape functions take them.
  ShapeArrays arrays() const {
    return {polygonVertices, polygonEdgeIndices, meshVertices,  meshNormals,   csgOperands,
            csgNodes,        blobComponents,     meshTriangles, meshTreeNodes, meshTreeOrder};
  }

  // Calls f with the shape `ref` names, as its own type: the one place that
  // dispatches on the kind. Every kind's call must return the same type.
  template <class F> decltype(auto) visit(PrimitiveRef ref, F&& f) const {
    return visitFrom<0>(ref, f);
  }

  Aabb bounds(PrimitiveRef ref) const;
  std::uint32_t materialIndex(PrimitiveRef ref) const;
  const Material& material(PrimitiveRef ref) const { return materials[materialIndex(ref)]; }
  Origin origin(PrimitiveRef ref) const;
  // The surface record at `point` on the primitive: normals, ray starts,
  // part and material, and with SurfaceDetail::WithCoordinates also (u, v).
  // (Inline: the tracer calls it for every hit, and what it does not use of
  // the record is then never stored.)
  SurfacePoint surfaceAt(PrimitiveRef ref, const Vec3& point,
                         SurfaceDetail detail = SurfaceDetail::Shading) const;
  // The same where `ray` hits the primitive at `t` (the tracer's way in):
  // exact for kinds whose record depends on how the point was reached (a CSG
  // node's operand, see csg.h), and for every other kind surfaceAt at
  // ray.at(t).
  SurfacePoint surfaceAt(PrimitiveRef ref, const Ray& ray, double t,
                         SurfaceDetail detail = SurfaceDetail::Shading) const;
  // The surface coordinates an image map reads at `point` on the primitive:
  // uvAt, and for a triangle with per-vertex coordinates their blend.
  Vec2 imageCoordinates(PrimitiveRef ref, const Vec3& point) const;
  // The material stored for a surface point: the one place shading looks it
  // up. A textured one still has to be blended at the point (textureAt in
  // core/scene/material_blend.h), which the tracer does.
  const Material& materialAt(const SurfacePoint& surface) const {
    return materials[surface.material];
  }
  // "sphere #3 (table.sc:12)" and the like, for diagnostics and the ray tree.
  std::string describe(PrimitiveRef ref) const;
  // " (table.sc:12)", or "" for a shape read from no file.
  std::string placeOf(Origin origin) const;
  // The count of every kind the scene has, "2 spheres, 1 cone" ("" if none),
  // for summaries.
  std::string kindCounts() const;
  // Every primitive, in the order of the kinds, for brute-force queries.
  std::vector<PrimitiveRef> allPrimitives() const;

private:
  template <std::size_t I, class F> decltype(auto) visitFrom(PrimitiveRef ref, F& f) const {
    using Kind = ShapeKinds::At<I>;
    if constexpr (I + 1 == kShapeKindCount) {
      return f(shapes<Kind>()[ref.index]);
    } else {
      if (ref.kind == kindOf<Kind>) return f(shapes<Kind>()[ref.index]);
      return visitFrom<I + 1>(ref, f);
    }
  }
};

inline SurfacePoint Scene::surfaceAt(PrimitiveRef ref, const Vec3& point,
                                     SurfaceDetail detail) const {
  return visit(ref, [&](const auto& shape) {
    SurfacePoint surface = prism::surfaceAt(shape, arrays(), point);
    // A CSG node's record carries its operand's material.
    if constexpr (!std::is_same_v<std::decay_t<decltype(shape)>, Csg>)
      surface.material = shape.material;
    if (detail == SurfaceDetail::WithCoordinates) surface.uv = uvAt(shape, arrays(), point);
    return surface;
  });
}

inline SurfacePoint Scene::surfaceAt(PrimitiveRef ref, const Ray& ray, double t,
                                     SurfaceDetail detail) const {
  if (ref.kind == kindOf<Csg>)
    return surfaceAlong(shapes<Csg>()[ref.index], arrays(), ray, t, detail);
  return surfaceAt(ref, ray.at(t), detail);
}

} // namespace prism

// The one way to add to a Scene: the .sc parser, the NFF and OBJ readers, the
// generators in tools/ and the tests all build scenes through it, so the
// bookkeeping that must agree between them (materials interned in the order
// of first use, every primitive in exactly one group, polygons with their
// vertices and edge index, mesh triangles wound as their normals say) is
// written once. It checks nothing about the input: readers report problems
// in their own terms before they add.
#pragma once

#include "core/scene/material_table.h"
#include "core/scene/scene.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace prism {

class SceneBuilder {
public:
  // Adds to `scene`, which may already hold materials, groups and primitives
  // (a builder can continue what another started).
  explicit SceneBuilder(Scene& scene) : scene_(scene), materials_(scene.materials) {
    for (const Material& m : scene_.materials) {
      scene_.absorbingMaterials = scene_.absorbingMaterials || m.absorbs();
      scene_.texturedMaterials = scene_.texturedMaterials || m.textured();
    }
  }
  SceneBuilder(const SceneBuilder&) = delete;
  SceneBuilder& operator=(const SceneBuilder&) = delete;

  Scene& scene() { return scene_; }

  // --- Materials

  // The index of `m` in the scene's one material table (see MaterialTable).
  std::uint32_t material(const Material& m) { return intern(m); }

  // The current material of readers that have one (.sc `surface`, NFF `f`).
  // It is interned when a primitive first uses it, so a material no
  // primitive uses takes no index.
  void setMaterial(const Material& m) {
    current_ = m;
    currentIndex_.reset();
  }
  const Material& currentMaterialValue() const { return current_; }
  // The index of the current material as the primitives added next use it:
  // a textured one with the object space composed into its texture's map.
  std::uint32_t currentMaterial() {
    if (!currentIndex_) currentIndex_ = intern(inObjectSpace(current_));
    return *currentIndex_;
  }
  // The world-to-object map (x -> linear x + offset) of the primitives added
  // next: the inverse of a reader's current transform. A texture is
  // evaluated in its primitive's object space, so it moves with the
  // primitive; textured primitives under the same map share a material.
  // Identity unless set; untextured materials and textures whose map is
  // given from the world (Texture::fromWorld) ignore it.
  void setObjectSpace(const Mat3& linear, const Vec3& offset) {
    objectLinear_ = linear;
    objectOffset_ = offset;
    if (current_.texture.active()) currentIndex_.reset();
  }

  // --- Groups (the push/pop hierarchy)

  // Where primitives go: group 0, the top level, to begin with.
  std::uint32_t group() const { return group_; }
  // A new empty group below `parent`, not entered.
  std::uint32_t addGroup(std::uint32_t parent, Origin origin = {});
  // Makes `group` the current one (for generators that fill groups out of
  // order). push and pop are unaffected.
  void enter(std::uint32_t group) { group_ = group; }
  // A new group below the current one, entered; the current group and
  // material are saved for pop. Returns the new group.
  std::uint32_t push(Origin origin);
  // Back to the group and material of the matching push.
  void pop();
  // The pushes not yet popped.
  std::size_t openPushes() const { return saved_.size(); }

  // --- Primitives, each added to the current group

  // A kind that needs none of the scene's arrays (sphere, ellipsoid, cone),
  // with its material and origin already set.
  // Inside a CSG node (beginCsg), a closed kind becomes the node's next
  // operand instead, and the reference returned names no primitive.
  template <class Kind>
  requires SelfContainedShape<Kind> PrimitiveRef add(const Kind& shape) {
    if constexpr (std::is_constructible_v<decltype(CsgOperand::shape), Kind>) {
      if (!csgOpen_.empty()) {
        csgOpen_.back().operands.push_back(CsgOperand{shape});
        return {kindOf<Csg>, kNoPrimitive};
      }
    }
    std::vector<Kind>& shapes = scene_.shapes<Kind>();
    shapes.push_back(shape);
    return inGroup({kindOf<Kind>, std::uint32_t(shapes.size() - 1)});
  }

  // A polygon whose vertices passed polygonProblem, with an edge index when
  // it has many vertices.
  PrimitiveRef polygon(std::span<const Vec3> vertices, std::uint32_t material, Origin origin);

  // A blob made by makeBlob, with its material and origin already set: its
  // components go to the scene's array. Inside a CSG node it becomes the
  // node's next operand, as the closed kinds of add do.
  PrimitiveRef blob(const PlacedBlob& placed);

  // A triangle with vertices of its own (and, when `normals` is given, unit
  // vertex normals of its own), in the order given: the caller has checked
  // them with triangleProblem.
  PrimitiveRef triangle(const std::array<Vec3, 3>& vertices, const std::array<Vec3, 3>* normals,
                        std::uint32_t material, Origin origin);

  // A triangle over three existing mesh vertices (and, when `normals` is
  // given, three existing unit normals). When the vertex normals all lie on
  // the other side of the face than its winding says, the winding is
  // reversed: the normals are what the modeller saw, and the tracer's
  // entering/leaving test must agree with them. Surface coordinates `uvs`,
  // when given, are stored with it (setTriangleUvs), each staying with its
  // vertex when the winding is reversed. Nothing (and no primitive) for a
  // zero-area triangle.
  std::optional<PrimitiveRef> meshTriangle(std::array<std::uint32_t, 3> vertex,
                                           const std::array<std::uint32_t, 3>* normals,
                                           std::uint32_t material, Origin origin,
                                           const std::array<Vec2, 3>* uvs = nullptr);

  // Gives triangle `index` (of shapes<Triangle>()) per-vertex surface
  // coordinates, in its vertices' order (Scene::triangleUvs; the others keep
  // their barycentric ones).
  void setTriangleUvs(std::uint32_t index, const std::array<Vec2, 3>& uvs);

  // --- CSG nodes (core/shapes/csg.h)

  // Opens a node: until the matching endCsg, closed shapes added are its
  // operands (and nodes closed inside it, nested operands). The current
  // material is saved, as by push.
  void beginCsg(CsgOp op, Origin origin);
  bool inCsg() const { return !csgOpen_.empty(); }
  std::size_t openCsgs() const { return csgOpen_.size(); }
  // Closes the innermost node and restores the material: a root becomes a
  // primitive of the current group, a nested node an operand of the one
  // around it. Returns the count of its operands; with fewer than two the
  // node is dropped (the reader reports it).
  std::size_t endCsg();

  // A closed mesh, checked and wound outward by the reader (mesh_closure.h),
  // as the open node's next operand: its vertices (and the unit vertex
  // normals of its smooth triangles) go to the scene's mesh arrays, its
  // triangles and their tree (mesh_tree.h) to the closed meshes' arrays.
  // Requires inCsg().
  struct ClosedMesh {
    std::span<const Vec3> vertices;
    std::span<const std::array<std::uint32_t, 3>> triangles;     // into vertices
    std::span<const std::optional<std::array<Vec3, 3>>> normals; // per triangle, or none
    std::uint32_t material = 0;
    Origin origin;
  };
  void solidMesh(const ClosedMesh& mesh);

  // --- Lights and files

  void addLight(const Light& light) { scene_.lights.push_back(light); }
  // Appends a file name to Scene::files (the main file first); returns its
  // index, for Origin::file.
  std::uint32_t addFile(std::string name);

private:
  // Every material enters here: the table, and Scene::absorbingMaterials
  // and texturedMaterials.
  std::uint32_t intern(const Material& m) {
    if (m.absorbs()) scene_.absorbingMaterials = true;
    if (m.textured()) scene_.texturedMaterials = true;
    return materials_.intern(m);
  }

  // `m` with the object space composed in after its texture's own map,
  // unless that map is already from the world.
  Material inObjectSpace(Material m) const {
    Texture& t = m.texture;
    if (!t.active()) return m;
    if (t.fromWorld) {
      t.fromWorld = false;
      return m;
    }
    t.offset = t.linear * objectOffset_ + t.offset;
    t.linear = t.linear * objectLinear_;
    return m;
  }

  PrimitiveRef inGroup(PrimitiveRef ref) {
    scene_.groups[group_].primitives.push_back(ref);
    return ref;
  }

  struct Saved {
    std::uint32_t group;
    Material material;
    std::optional<std::uint32_t> materialIndex;
  };

  static constexpr std::uint32_t kNoPrimitive = ~std::uint32_t(0);
  struct OpenCsg {
    CsgOp op;
    Origin origin;
    std::uint32_t material; // the node's
    std::vector<CsgOperand> operands;
    Saved saved; // the material to restore (its group is unused)
  };

  Scene& scene_;
  std::vector<OpenCsg> csgOpen_;
  MaterialTable materials_;
  Material current_;
  std::optional<std::uint32_t> currentIndex_; // current_ interned, once a primitive used it
  Mat3 objectLinear_{1.0};
  Vec3 objectOffset_{0.0};
  std::uint32_t group_ = 0;
  std::vector<Saved> saved_;
};

} // namespace prism

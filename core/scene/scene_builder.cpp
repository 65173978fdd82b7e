#include "core/scene/scene_builder.h"

#include <algorithm>

namespace prism {

std::uint32_t SceneBuilder::addGroup(std::uint32_t parent, Origin origin) {
  const auto index = std::uint32_t(scene_.groups.size());
  Group group;
  group.origin = origin;
  scene_.groups.push_back(std::move(group));
  scene_.groups[parent].children.push_back(index);
  return index;
}

std::uint32_t SceneBuilder::push(Origin origin) {
  saved_.push_back({group_, current_, currentIndex_});
  // Inside a CSG node the shapes are its operands, in no group: a push there
  // scopes the material (and the reader's transform) only.
  if (csgOpen_.empty()) group_ = addGroup(group_, origin);
  return group_;
}

void SceneBuilder::pop() {
  const Saved& s = saved_.back();
  group_ = s.group;
  current_ = s.material;
  currentIndex_ = s.materialIndex;
  saved_.pop_back();
}

PrimitiveRef SceneBuilder::polygon(std::span<const Vec3> vertices, std::uint32_t material,
                                   Origin origin) {
  Polygon p = makePolygon(vertices);
  p.firstVertex = std::uint32_t(scene_.polygonVertices.size());
  p.material = material;
  p.origin = origin;
  if (p.vertexCount >= kIndexedPolygonVertices) {
    p.edgeIndex = std::uint32_t(scene_.polygonEdgeIndices.size());
    scene_.polygonEdgeIndices.emplace_back(vertices, polygonAxes(p).u, polygonAxes(p).v);
  }
  scene_.polygonVertices.insert(scene_.polygonVertices.end(), vertices.begin(), vertices.end());
  scene_.shapes<Polygon>().push_back(p);
  return inGroup({kindOf<Polygon>, std::uint32_t(scene_.shapes<Polygon>().size() - 1)});
}

PrimitiveRef SceneBuilder::blob(const PlacedBlob& placed) {
  Blob b = placed.blob;
  b.firstComponent = std::uint32_t(scene_.blobComponents.size());
  b.componentCount = std::uint32_t(placed.components.size());
  scene_.blobComponents.insert(scene_.blobComponents.end(), placed.components.begin(),
                               placed.components.end());
  if (!csgOpen_.empty()) {
    csgOpen_.back().operands.push_back(CsgOperand{b});
    return {kindOf<Csg>, kNoPrimitive};
  }
  scene_.shapes<Blob>().push_back(b);
  return inGroup({kindOf<Blob>, std::uint32_t(scene_.shapes<Blob>().size() - 1)});
}

PrimitiveRef SceneBuilder::triangle(const std::array<Vec3, 3>& vertices,
                                    const std::array<Vec3, 3>* normals, std::uint32_t material,
                                    Origin origin) {
  Triangle t;
  for (std::size_t i = 0; i < 3; ++i) {
    t.vertex[i] = std::uint32_t(scene_.meshVertices.size());
    scene_.meshVertices.push_back(vertices[i]);
    if (normals != nullptr) {
      t.normal[i] = std::uint32_t(scene_.meshNormals.size());
      scene_.meshNormals.push_back((*normals)[i]);
    }
  }
  t.material = material;
  t.origin = origin;
  scene_.shapes<Triangle>().push_back(t);
  return inGroup({kindOf<Triangle>, std::uint32_t(scene_.shapes<Triangle>().size() - 1)});
}

void SceneBuilder::setTriangleUvs(std::uint32_t index, const std::array<Vec2, 3>& uvs) {
  static constexpr std::array<Vec2, 3> kBarycentric = {Vec2(0.0), Vec2(1.0, 0.0), Vec2(0.0, 1.0)};
  scene_.triangleUvs.resize(scene_.shapes<Triangle>().size(), kBarycentric);
  scene_.triangleUvs[index] = uvs;
}

std::optional<PrimitiveRef> SceneBuilder::meshTriangle(std::array<std::uint32_t, 3> vertex,
                                                       const std::array<std::uint32_t, 3>* normals,
                                                       std::uint32_t material, Origin origin,
                                                       const std::array<Vec2, 3>* uvs) {
  const Vec3& a = scene_.meshVertices[vertex[0]];
  const Vec3& b = scene_.meshVertices[vertex[1]];
  const Vec3& c = scene_.meshVertices[vertex[2]];
  if (triangleProblem(a, b, c)) return std::nullopt;
  Triangle t;
  t.vertex = vertex;
  bool reversed = false;
  if (normals != nullptr) {
    t.normal = *normals;
    const Vec3 face = glm::cross(b - a, c - a);
    const Vec3 sum = scene_.meshNormals[t.normal[0]] + scene_.meshNormals[t.normal[1]] +
                     scene_.meshNormals[t.normal[2]];
    if (glm::dot(face, sum) < 0.0) {
      std::swap(t.vertex[1], t.vertex[2]);
      std::swap(t.normal[1], t.normal[2]);
      reversed = true;
    }
  }
  t.material = material;
  t.origin = origin;
  scene_.shapes<Triangle>().push_back(t);
  const auto index = std::uint32_t(scene_.shapes<Triangle>().size() - 1);
  if (uvs != nullptr) {
    std::array<Vec2, 3> kept = *uvs;
    if (reversed) std::swap(kept[1], kept[2]);
    setTriangleUvs(index, kept);
  }
  return inGroup({kindOf<Triangle>, index});
}

void SceneBuilder::solidMesh(const ClosedMesh& mesh) {
  const auto base = std::uint32_t(scene_.meshVertices.size());
  scene_.meshVertices.insert(scene_.meshVertices.end(), mesh.vertices.begin(), mesh.vertices.end());
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    Triangle t;
    for (std::size_t k = 0; k < 3; ++k) {
      t.vertex[k] = base + mesh.triangles[i][k];
      if (mesh.normals[i]) {
        t.normal[k] = std::uint32_t(scene_.meshNormals.size());
        scene_.meshNormals.push_back((*mesh.normals[i])[k]);
      }
    }
    t.material = mesh.material;
    t.origin = mesh.origin;
    triangles.push_back(t);
  }
  SolidMesh m;
  m.firstNode = std::uint32_t(scene_.meshTreeNodes.size());
  buildMeshTree(triangles, scene_.meshVertices.data(), scene_.meshTreeNodes, scene_.meshTreeOrder);
  m.nodeCount = std::uint32_t(scene_.meshTreeNodes.size()) - m.firstNode;
  m.firstTriangle = std::uint32_t(scene_.meshTriangles.size());
  m.triangleCount = std::uint32_t(triangles.size());
  scene_.meshTriangles.insert(scene_.meshTriangles.end(), triangles.begin(), triangles.end());
  for (const Vec3& v : mesh.vertices) {
    m.bounds.extend(v);
    m.roundoff = std::max(m.roundoff, maxAbsComponent(v));
  }
  m.material = mesh.material;
  m.origin = mesh.origin;
  csgOpen_.back().operands.push_back(CsgOperand{m});
}

std::uint32_t SceneBuilder::addFile(std::string name) {
  scene_.files.push_back(std::move(name));
  return std::uint32_t(scene_.files.size() - 1);
}

void SceneBuilder::beginCsg(CsgOp op, Origin origin) {
  const std::uint32_t nodeMaterial = currentMaterial();
  csgOpen_.push_back({op, origin, nodeMaterial, {}, {group_, current_, currentIndex_}});
}

std::size_t SceneBuilder::endCsg() {
  OpenCsg open = std::move(csgOpen_.back());
  csgOpen_.pop_back();
  current_ = open.saved.material;
  currentIndex_ = open.saved.materialIndex;
  const std::size_t count = open.operands.size();
  if (count < 2) return count;
  Csg node;
  node.op = open.op;
  node.firstOperand = std::uint32_t(scene_.csgOperands.size());
  node.operandCount = std::uint32_t(count);
  node.material = open.material;
  node.origin = open.origin;
  scene_.csgOperands.insert(scene_.csgOperands.end(), open.operands.begin(), open.operands.end());
  finishCsg(node, scene_.arrays());
  if (!csgOpen_.empty()) {
    scene_.csgNodes.push_back(node);
    csgOpen_.back().operands.push_back(
        CsgOperand{CsgNodeIndex{std::uint32_t(scene_.csgNodes.size() - 1)}});
  } else {
    scene_.shapes<Csg>().push_back(node);
    inGroup({kindOf<Csg>, std::uint32_t(scene_.shapes<Csg>().size() - 1)});
  }
  return count;
}

} // namespace prism

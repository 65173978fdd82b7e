#include "bench/embree/embree_scene.h"

#include "core/shapes/triangulate.h"

#include <chrono>
#include <stdexcept>

namespace prism::bench {

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(int(error)) + ")");
}

void setFloat3(float* out, const Vec3& v) {
  out[0] = float(v.x);
  out[1] = float(v.y);
  out[2] = float(v.z);
}

// A committed triangle mesh over `vertices`, or null when there are no triangles.
RTCGeometry makeTriangles(RTCDevice device, const std::vector<Vec3>& vertices,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles,
                          RTCBuildQuality quality) {
  if (triangles.empty()) return nullptr;
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    setFloat3(v + 3 * i, vertices[i]);
  auto* index = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      index[3 * i + k] = triangles[i][k];
  rtcSetGeometryBuildQuality(geometry, quality);
  rtcCommitGeometry(geometry);
  return geometry;
}

// Every polygon split into triangles over Scene::polygonVertices: fans for
// convex ones, Prism's own triangulation for concave ones. `polygonOf`
// receives each triangle's polygon.
std::vector<std::array<std::uint32_t, 3>> polygonTriangles(const Scene& scene,
                                                           std::vector<std::uint32_t>& polygonOf) {
  std::vector<std::array<std::uint32_t, 3>> out;
  const auto& polygons = scene.shapes<Polygon>();
  for (std::uint32_t i = 0; i < polygons.size(); ++i) {
    const Polygon& p = polygons[i];
    const std::span<const Vec3> points(scene.polygonVertices.data() + p.firstVertex, p.vertexCount);
    for (const auto& tri : triangulate(points)) {
      out.push_back({p.firstVertex + tri[0], p.firstVertex + tri[1], p.firstVertex + tri[2]});
      polygonOf.push_back(i);
    }
  }
  return out;
}

RTCGeometry makeSpheres(RTCDevice device, const std::vector<Sphere>& spheres) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    setFloat3(v + 4 * i, spheres[i].center);
    v[4 * i + 3] = float(spheres[i].radius);
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

} // namespace

EmbreeScene::EmbreeScene(const Scene& scene, const EmbreeOptions& options) {
  // One build thread: the machine is shared, and only the queries are compared.
  const std::string config =
      "threads=1" + (options.deviceConfig.empty() ? "" : "," + options.deviceConfig);
  device_ = rtcNewDevice(config.c_str());
  if (device_ == nullptr)
    throw std::runtime_error("embree: rtcNewDevice(\"" + config + "\") failed");
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, options.quality);

  auto attach = [&](RTCGeometry geometry, Source source) {
    if (geometry == nullptr) return;
    const unsigned int id = rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    if (sources_.size() <= id) sources_.resize(id + 1);
    sources_[id] = source;
  };
  std::vector<std::array<std::uint32_t, 3>> mesh;
  for (const Triangle& t : scene.shapes<Triangle>())
    mesh.push_back(t.vertex);
  contents_.meshTriangles = mesh.size();
  attach(makeTriangles(device_, scene.meshVertices, mesh, options.quality), {kindOf<Triangle>});
  const auto polygons = polygonTriangles(scene, polygonOf_);
  contents_.polygonTriangles = polygons.size();
  attach(makeTriangles(device_, scene.polygonVertices, polygons, options.quality),
         {kindOf<Polygon>, true});

  const auto& spheres = scene.shapes<Sphere>();
  if (!spheres.empty() && options.spheres == SphereMode::Native) {
    attach(makeSpheres(device_, spheres), {kindOf<Sphere>});
    contents_.nativeSpheres = spheres.size();
  }
  auto addUser = [&](PrimitiveKind kind, std::size_t count) {
    if (count == 0) return;
    user_.push_back(std::make_unique<UserPrimitives>(UserPrimitives{&scene, kind}));
    attach(makeUserGeometry(device_, *user_.back(), unsigned(count)), {kind});
    contents_.userPrimitives += count;
  };
  if (options.spheres == SphereMode::User) addUser(kindOf<Sphere>, spheres.size());
  addUser(kindOf<Ellipsoid>, scene.shapes<Ellipsoid>().size());
  addUser(kindOf<Cone>, scene.shapes<Cone>().size());
  addUser(kindOf<Torus>, scene.shapes<Torus>().size());
  addUser(kindOf<Box>, scene.shapes<Box>().size());
  addUser(kindOf<Disc>, scene.shapes<Disc>().size());
  addUser(kindOf<CappedCone>, scene.shapes<CappedCone>().size());
  addUser(kindOf<Quadric>, scene.shapes<Quadric>().size());
  addUser(kindOf<Blob>, scene.shapes<Blob>().size());
  check(device_, "building the geometry");

  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene_);
  contents_.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  check(device_, "rtcCommitScene");
}

EmbreeScene::~EmbreeScene() {
  if (scene_ != nullptr) rtcReleaseScene(scene_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

PrimitiveRef EmbreeScene::primitiveOf(unsigned int geomID, unsigned int primID) const {
  const Source& source = sources_.at(geomID);
  return {source.kind, source.throughPolygonOf ? polygonOf_.at(primID) : primID};
}

std::vector<RTCRay> toEmbreeRays(const std::vector<Query>& queries) {
  std::vector<RTCRay> rays(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    RTCRay& r = rays[i];
    r.org_x = float(q.ray.origin.x);
    r.org_y = float(q.ray.origin.y);
    r.org_z = float(q.ray.origin.z);
    r.dir_x = float(q.ray.dir.x);
    r.dir_y = float(q.ray.dir.y);
    r.dir_z = float(q.ray.dir.z);
    r.tnear = float(q.range.min);
    r.tfar = float(q.range.max);
    r.time = 0.0f;
    r.mask = ~0u;
    r.id = unsigned(i);
    r.flags = 0;
  }
  return rays;
}

} // namespace prism::bench

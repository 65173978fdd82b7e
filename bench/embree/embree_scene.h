// A Prism scene built as an Embree 3 scene, and its one-ray queries
// (rtcIntersect1, rtcOccluded1) over the harness's rays.
#pragma once

#include "bench/embree/ray_sets.h"
#include "bench/embree/user_geometry.h"

#include <embree3/rtcore.h>
#include <xmmintrin.h>

#include <memory>
#include <string>
#include <vector>

namespace prism::bench {

// How spheres enter Embree: as user geometry calling Prism's test (the
// default: the same arithmetic per sphere on both sides, and Embree's faster
// choice on the shipped scenes, where the spheres then share one hierarchy
// with the ellipsoids instead of adding one of their own), or as its own
// sphere primitive (RTC_GEOMETRY_TYPE_SPHERE_POINT, single precision, faster
// on scenes of spheres alone).
enum class SphereMode { Native, User };

struct EmbreeOptions {
  RTCBuildQuality quality = RTC_BUILD_QUALITY_HIGH;
  SphereMode spheres = SphereMode::User;
  // Passed to rtcNewDevice, e.g. "isa=avx2" to run a narrower ISA than the
  // host's best. The device always builds on one thread ("threads=1").
  std::string deviceConfig;
};

// What went into the Embree scene, for the report.
struct EmbreeContents {
  std::size_t meshTriangles = 0, polygonTriangles = 0, nativeSpheres = 0, userPrimitives = 0;
  double buildSeconds = 0.0; // rtcCommitScene
};

class EmbreeScene {
public:
  // Throws std::runtime_error with Embree's message if the device or scene fails.
  EmbreeScene(const Scene& scene, const EmbreeOptions& options);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCDevice device() const { return device_; }
  const EmbreeContents& contents() const { return contents_; }

  // The nearest hit's t (Embree's, single precision), one ray at a time, and
  // when asked, the Prism primitive Embree's hit belongs to.
  bool closestHit(const RTCRay& ray, float& t, PrimitiveRef* primitive = nullptr) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit;
    rayHit.ray = ray;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rayHit);
    t = rayHit.ray.tfar;
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    if (primitive != nullptr) *primitive = primitiveOf(rayHit.hit.geomID, rayHit.hit.primID);
    return true;
  }
  bool anyHit(const RTCRay& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay copy = ray;
    rtcOccluded1(scene_, &context, &copy);
    return copy.tfar < 0.0f; // rtcOccluded1 sets tfar to -infinity on a hit
  }

private:
  PrimitiveRef primitiveOf(unsigned int geomID, unsigned int primID) const;

  // What each geometry (by geomID) holds: primitives of one kind, numbered as
  // Prism numbers them, or (the polygons' triangles) numbered through `polygonOf_`.
  struct Source {
    PrimitiveKind kind{};
    bool throughPolygonOf = false;
  };
  std::vector<Source> sources_;
  std::vector<std::uint32_t> polygonOf_; // the polygon each polygon triangle comes from

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  // The user geometries' callback data, at fixed addresses.
  std::vector<std::unique_ptr<UserPrimitives>> user_;
  EmbreeContents contents_;
};

// While alive, the thread flushes denormal floats to zero, as Embree asks of
// the threads that call it (its documentation: denormals slow its kernels).
// Only around Embree's queries: Prism's own run in the renderer's default mode.
class EmbreeFloatMode {
public:
  EmbreeFloatMode() : saved_(_mm_getcsr()) {
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
  }
  ~EmbreeFloatMode() { _mm_setcsr(saved_); }
  EmbreeFloatMode(const EmbreeFloatMode&) = delete;
  EmbreeFloatMode& operator=(const EmbreeFloatMode&) = delete;

private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
};

// The queries as Embree's rays (the values are floats already: ray_sets.h).
std::vector<RTCRay> toEmbreeRays(const std::vector<Query>& queries);

} // namespace prism::bench

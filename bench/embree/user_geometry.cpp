#include "bench/embree/user_geometry.h"

#include "core/accel/accel.h"

#include <cmath>
#include <limits>

namespace prism::bench {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float roundedDown(double x) {
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -kInfinity) : f;
}
float roundedUp(double x) {
  float f = float(x);
  return double(f) < x ? std::nextafter(f, kInfinity) : f;
}

// Prism's box, rounded outward to floats, so Embree's culls nothing Prism's test hits.
void bounds(const RTCBoundsFunctionArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  const Aabb box = user.scene->bounds({user.kind, args->primID});
  RTCBounds& out = *args->bounds_o;
  out.lower_x = roundedDown(box.lo.x);
  out.lower_y = roundedDown(box.lo.y);
  out.lower_z = roundedDown(box.lo.z);
  out.upper_x = roundedUp(box.hi.x);
  out.upper_y = roundedUp(box.hi.y);
  out.upper_z = roundedUp(box.hi.z);
}

// Lane i of Embree's ray as Prism's ray and range (float to double is exact).
Ray rayOf(RTCRayN* ray, unsigned int n, unsigned int i) {
  return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
          {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)}};
}
Interval rangeOf(RTCRayN* ray, unsigned int n, unsigned int i) {
  return {RTCRayN_tnear(ray, n, i), RTCRayN_tfar(ray, n, i)};
}

void intersect(const RTCIntersectFunctionNArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    double t;
    if (!intersectPrimitive(*user.scene, {user.kind, args->primID}, rayOf(ray, args->N, i),
                            rangeOf(ray, args->N, i), t))
      continue;
    RTCRayN_tfar(ray, args->N, i) = float(t);
    // Prism's closestHit finds no normal either (shading asks for it after),
    // so neither engine pays for one here: any non-zero vector will do.
    RTCHitN_Ng_x(hit, args->N, i) = -RTCRayN_dir_x(ray, args->N, i);
    RTCHitN_Ng_y(hit, args->N, i) = -RTCRayN_dir_y(ray, args->N, i);
    RTCHitN_Ng_z(hit, args->N, i) = -RTCRayN_dir_z(ray, args->N, i);
    RTCHitN_u(hit, args->N, i) = 0.0f;
    RTCHitN_v(hit, args->N, i) = 0.0f;
    RTCHitN_primID(hit, args->N, i) = args->primID;
    RTCHitN_geomID(hit, args->N, i) = args->geomID;
    RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
  }
}

void occluded(const RTCOccludedFunctionNArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    double t;
    if (intersectPrimitive(*user.scene, {user.kind, args->primID}, rayOf(args->ray, args->N, i),
                           rangeOf(args->ray, args->N, i), t))
      RTCRayN_tfar(args->ray, args->N, i) = -kInfinity; // Embree's mark for "occluded"
  }
}

} // namespace

RTCGeometry makeUserGeometry(RTCDevice device, const UserPrimitives& primitives,
                             unsigned int count) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, count);
  rtcSetGeometryUserData(geometry, const_cast<UserPrimitives*>(&primitives));
  rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, intersect);
  rtcSetGeometryOccludedFunction(geometry, occluded);
  rtcCommitGeometry(geometry);
  return geometry;
}

} // namespace prism::bench

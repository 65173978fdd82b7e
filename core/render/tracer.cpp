#include "core/render/tracer.h"

#include "core/render/media.h"
#include "core/scene/material_blend.h"

#include <limits>
#include <stdexcept>

namespace prism {

// Where a new ray may start: the hit point moved off the surface to one side.
// Not in the anonymous namespace: Tracer::Incidence, a member of a class with
// external linkage, holds one.
struct SurfaceFrame {
  Vec3 above; // on the side the incoming ray came from
  Vec3 below; // on the far side (for refraction)
};

namespace {

// `scale` is the primitive's SurfacePoint::roundoffScale. The offset is at
// least 512 u of the point's largest coordinate, a few hundred of its ulps, so
// adding it always moves the point, whichever component carries the normal.
// The tiny floor keeps it positive for a point, origin and plane all at 0.
SurfaceFrame frameAt(const Vec3& point, const Vec3& normal, const Vec3& rayOrigin, double scale) {
  const double offset =
      kRayOffsetRoundoff * (maxAbsComponent(point) + maxAbsComponent(rayOrigin) + scale) + 1e-300;
  return {point + offset * normal, point - offset * normal};
}

// Mirror direction of unit `d` about unit `n`.
Vec3 reflect(const Vec3& d, const Vec3& n) { return glm::normalize(d - 2.0 * glm::dot(d, n) * n); }

constexpr double kGrazingCos2 = 1e-12;

// Refracted direction of unit `d` through a surface with unit normal `n` facing
// the incoming ray, for the index ratio eta = n_from / n_to; false on total
// internal reflection.
[[gnu::always_inline]] inline bool refract(const Vec3& d, const Vec3& n, double eta, Vec3& out) {
  const double cosIn = -glm::dot(d, n);
  const double k = 1.0 - eta * eta * (1.0 - cosIn * cosIn); // cos^2 of the refracted angle
  // At the critical angle the refracted ray would run along the surface; k is 0
  // only up to round-off there, so a margin makes the critical angle itself
  // reflect totally whichever way the rounding goes (it grazes within 1e-6 rad).
  // Written so that a NaN k is total reflection too: with an index so large
  // that eta * eta overflows, inf * 0 is NaN at normal incidence, and the
  // critical angle of such an index is far below what a double resolves.
  if (!(k > kGrazingCos2)) return false;
  out = glm::normalize(eta * d + (eta * cosIn - std::sqrt(k)) * n);
  return true;
}

// A new ray's node in the ray tree, when one is recorded.
[[gnu::always_inline]] inline RayTreeNode* childOf(RayTreeNode* record, RayKind kind) {
  if (record == nullptr) return nullptr;
  RayTreeNode* child = &record->children.emplace_back();
  child->kind = kind;
  return child;
}

} // namespace

Tracer::Tracer(const Scene& scene, const Accel& accel, int maxDepth, BlockerCache cache)
    : scene_(scene), accel_(accel), maxDepth_(maxDepth) {
  if (cache == BlockerCache::On) lastBlocker_.resize(std::size_t(maxDepth) * scene.lights.size());
  media_ = scene.hasMedia();
  textured_ = scene.texturedMaterials;
  images_ = scene.images != nullptr;
  if (images_) cones_.resize(std::size_t(maxDepth) + 2);
}

// Eye rays start in the air. A mirror ray travels where the ray it mirrors
// did; a refracted ray entering a solid (N.D <= 0) travels inside it, one
// leaving it in the air: the same rule as refraction's index ratio (air
// outside every solid, no solid inside another).
namespace {
// Sets a per-ray member of the tracer (the medium) for a new
// ray and restores the parent's when the new ray is done.
template <class T> class ScopedValue {
public:
  ScopedValue(T& value, const T& now) : value_(value), saved_(value) { value = now; }
  ~ScopedValue() { value_ = saved_; }
  ScopedValue(const ScopedValue&) = delete;
  ScopedValue& operator=(const ScopedValue&) = delete;

private:
  T& value_;
  T saved_;
};
} // namespace

Color Tracer::alongSegment(const Color& far, double length, RayTreeNode* record) const {
  const Color near = inside_ != nullptr    ? throughAbsorber(far, length, inside_->absorption)
                     : scene_.fog.active() ? throughFog(far, length, scene_.fog)
                                           : far;
  if (record != nullptr) {
    record->medium = inside_ != nullptr    ? SegmentMedium::Absorber
                     : scene_.fog.active() ? SegmentMedium::Fog
                                           : SegmentMedium::Clear;
    record->segmentLength = length;
    const Color coefficient = inside_ != nullptr ? inside_->absorption : Color(scene_.fog.density);
    record->transmittance = {transmittance(coefficient.r, length),
                             transmittance(coefficient.g, length),
                             transmittance(coefficient.b, length)};
    record->atOrigin = near;
  }
  return near;
}

Color Tracer::trace(const Ray& ray, int depth, RayCounts& counts, RayTreeNode* record,
                    const PrimitiveRef* skip) {
  if (record != nullptr) {
    record->ray = ray;
    record->depth = depth;
  }
  Hit hit;
  if (!accel_.closestHit(ray, Interval{}, skip, hit)) {
    if (record != nullptr) record->radiance = scene_.background;
    if (media_)
      return alongSegment(scene_.background, std::numeric_limits<double>::infinity(), record);
    return scene_.background;
  }
  if (media_) return alongSegment(shade(ray, hit, depth, counts, record), hit.t, record);
  return shade(ray, hit, depth, counts, record);
}

void Tracer::traceBundle(std::span<const Ray> rays, std::span<Color> out, RayCounts& counts) {
  if (rays.size() > Accel::kMaxBundle || out.size() < rays.size())
    throw std::length_error("traceBundle: at most Accel::kMaxBundle rays, a colour for each");
  Hit hits[Accel::kMaxBundle];
  const std::uint64_t found = accel_.closestHits(rays, std::span(hits, rays.size()));
  for (std::size_t i = 0; i < rays.size(); ++i)
    out[i] =
        (found >> i & 1u) != 0 ? shade(rays[i], hits[i], 1, counts, nullptr) : scene_.background;
  if (!media_) return;
  // Eye rays start in the air (inside_ is null between rays).
  for (std::size_t i = 0; i < rays.size(); ++i)
    out[i] = alongSegment(
        out[i], (found >> i & 1u) != 0 ? hits[i].t : std::numeric_limits<double>::infinity(),
        nullptr);
}

void Tracer::setBailout(const BailoutBound& bound) {
  bailout_ = bound.active() ? &bound : nullptr;
  allowance_ = bound.allowance;
}

// The proof (docs/rendering-model.md#bailout): a ray of weight w and
// allowance a gives each new ray c (coefficient k_c) the allowance
// a / (ksr + kst), so w k_c a / (ksr + kst) summed over its new rays is at
// most w a. A skipped ray brings back at most beyond[depth + 1], so skipping
// it when beyond[depth + 1] <= a / (ksr + kst) keeps its loss within its
// share; a traced one keeps its descendants' within it by induction.

// Out of line, so the exact trace keeps its code and pays one test of
// bailout_ per new ray: the rest of reflection() or transmission() with a
// bailout, skipping `ray` or tracing it with its share of the allowance.
[[gnu::noinline]] Color Tracer::traceOrSkip(const Ray& ray, RayKind kind, const Material& m,
                                            int depth, RayCounts& counts, RayTreeNode* record,
                                            const PrimitiveRef* skip) {
  const bool mirror = kind == RayKind::Reflected;
  if (bailout_->beyond[std::size_t(depth) + 1] * (m.ksr + m.kst) <= allowance_) {
    ++(mirror ? counts.reflectedSkipped : counts.transmittedSkipped);
    return Color(0.0);
  }
  ++(mirror ? counts.reflected : counts.transmitted);
  const double parent = allowance_;
  allowance_ = parent / (m.ksr + m.kst);
  const Color radiance = trace(ray, depth + 1, counts, childOf(record, kind), skip);
  allowance_ = parent;
  return radiance;
}

bool Tracer::blocked(const Ray& ray, double length, const PrimitiveRef* skip, std::size_t light,
                     int depth) {
  const Interval range{0.0, length};
  if (lastBlocker_.empty()) return accel_.anyHit(ray, range, skip);
  std::optional<PrimitiveRef>& last =
      lastBlocker_[std::size_t(std::min(depth, maxDepth_) - 1) * scene_.lights.size() + light];
  double t;
  if (last && !(skip != nullptr && *skip == *last) &&
      intersectPrimitive(scene_, *last, ray, range, t))
    return true;
  PrimitiveRef blocker;
  if (!accel_.anyHit(ray, range, skip, &blocker)) return false;
  last = blocker;
  return true;
}

// The hit surface seen from the incoming ray: which side it meets, the
// normals turned toward it, and where new rays start.
struct Tracer::Incidence {
  Vec3 point;
  bool leaving; // N.D > 0: the ray leaves the solid (or meets a back face)
  Vec3 n;       // the shading normal, facing the ray
  Vec3 nr;      // the normal mirror and refracted rays turn about
  SurfaceFrame frame;
  const PrimitiveRef* skip; // the flat primitive new rays leave, or null
  double t;                 // the hit's distance along the incoming ray
};

Color Tracer::shade(const Ray& ray, const Hit& hit, int depth, RayCounts& counts,
                    RayTreeNode* record) {
  const Vec3 point = ray.at(hit.t);
  // The ray tree shows the surface coordinates; rendering needs none yet.
  const SurfacePoint surface =
      scene_.surfaceAt(hit.primitive, ray, hit.t,
                       record != nullptr ? SurfaceDetail::WithCoordinates : SurfaceDetail::Shading);
  // A textured material is blended at the point, out of line; every other
  // one is used in place: in a scene without textures at the cost of one
  // test of a flag.
  const Material& m = scene_.materialAt(surface);
  if (textured_ && m.textured()) [[unlikely]]
    return shadeTextured(ray, hit, point, surface, m, depth, counts, record);
  return shadeWith(ray, hit, point, surface, m, depth, counts, record);
}

[[gnu::noinline]] Color Tracer::shadeTextured(const Ray& ray, const Hit& hit, const Vec3& point,
                                              const SurfacePoint& surface, const Material& stored,
                                              int depth, RayCounts& counts, RayTreeNode* record) {
  Material blended = textureAt(stored, point, record != nullptr ? &record->texture : nullptr);
  if (stored.image.active()) {
    blended.color *= imageColor(ray, hit, point, surface, stored.image, depth,
                                record != nullptr ? &record->image : nullptr);
    blended.image = ImageMap{};
  }
  const Color radiance = shadeWith(ray, hit, point, surface, blended, depth, counts, record);
  if (record != nullptr) {
    record->textureKind = stored.texture.kind;
    record->textureScale = stored.texture.scale;
  }
  return radiance;
}

namespace {
// Which of a kind's surface coordinates run around it (an angle's fraction
// of a turn), so that two points across the seam differ by about a whole
// turn: u, the angle about the axis, of every round kind; v too on a torus
// (the angle round its tube). A sphere's v is a latitude from pole to pole:
// a footprint wider than half of it (a globe a few pixels wide) is a wide
// footprint, not a short one the other way round. A CSG solid's coordinates
// are those of the operand at the point, which may be a torus: both wrap.
struct Seams {
  bool u, v;
};
Seams seamsOf(PrimitiveKind kind) {
  if (kind == kindOf<Polygon> || kind == kindOf<Triangle> || kind == kindOf<Box>)
    return {false, false};
  return {true, kind == kindOf<Torus> || kind == kindOf<Csg>};
}

// `d` taken the short way round where coordinates wrap.
Vec2 acrossSeam(Vec2 d, Seams seams) {
  return {seams.u ? d.x - std::round(d.x) : d.x, seams.v ? d.y - std::round(d.y) : d.y};
}
} // namespace

// A new ray starts as wide as its parent's cone is at the hit, `t` along
// it, and spreads `turn` times as fast.
void Tracer::setChildCone(int depth, double t, double turn) {
  const RayCone& cone = cones_[std::size_t(depth)];
  cones_[std::size_t(depth) + 1] = {cone.width + cone.spread * t, cone.spread * turn};
}

// The footprint of the ray cone on the surface is an ellipse: its width
// across the ray's plane of incidence, and the width over cos(theta) along
// it. Its two half-axes, carried into image coordinates through the kind's
// own surface coordinates (a difference across each axis, the short way
// round a seam), are the derivatives the TextureSystem filters over.
Color Tracer::imageColor(const Ray& ray, const Hit& hit, const Vec3& point,
                         const SurfacePoint& surface, const ImageMap& map, int depth,
                         ImageLookup* lookup) const {
  const RayCone& cone = cones_[std::size_t(depth)];
  const double width = cone.width + cone.spread * hit.t;
  const Vec3& n = surface.outward;
  Vec3 across = glm::cross(n, ray.dir);
  const double sine = glm::length(across);
  if (sine > 1e-12) {
    across /= sine;
  } else { // straight on: any tangent will do
    across = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  }
  const Vec3 along = glm::cross(n, across);
  // Beyond 1000:1 the filter's own anisotropy limit blurs anyway.
  const double cosine = std::max(std::abs(glm::dot(n, ray.dir)), 1e-3);
  const Vec3 a = (0.5 * width) * across;
  const Vec3 b = (0.5 * width / cosine) * along;
  const PrimitiveRef ref = hit.primitive;
  auto uv = [&](const Vec3& p) { return scene_.imageCoordinates(ref, p); };
  const Seams seams = seamsOf(ref.kind);
  const Vec2 st = uv(point) * map.scale + map.offset;
  const Vec2 dx = acrossSeam(uv(point + a) - uv(point - a), seams) * map.scale;
  const Vec2 dy = acrossSeam(uv(point + b) - uv(point - b), seams) * map.scale;
  const Color value = scene_.images->lookup(map, st, dx, dy);
  if (lookup != nullptr) *lookup = {map.image, st, dx, dy, width, value};
  return value;
}

[[gnu::always_inline]] inline Color
Tracer::shadeWith(const Ray& ray, const Hit& hit, const Vec3& point, const SurfacePoint& surface,
                  const Material& m, int depth, RayCounts& counts, RayTreeNode* record) {
  // Leaving iff N.D > 0; shade with the normal facing the ray.
  // Both the test and where new rays start use the geometric normal `g`.
  const bool leaving = glm::dot(surface.outward, ray.dir) > 0.0;
  const Vec3 g = leaving ? -surface.outward : surface.outward;
  SurfaceFrame frame = frameAt(point, g, ray.origin, surface.roundoffScale);
  // The shading normal (a smooth triangle's interpolated one), turned the same
  // way; one that faces away from the ray's side of the surface (vertex
  // normals bent past the face) would light the wrong side: `g` then.
  const Vec3 turned = leaving ? -surface.shading : surface.shading;
  const Vec3 n = glm::dot(turned, g) > 0.0 ? turned : g;
  // Shadow and reflected rays start where the surface says (a smooth
  // triangle's curved surface, see liftedPoint), on the outward side only.
  if (!leaving && surface.outwardStart)
    frame.above = frameAt(*surface.outwardStart, g, ray.origin, surface.roundoffScale).above;
  // A grazing ray can meet a bent shading normal from behind; mirroring or
  // refracting about it would send the ray through the surface, so those use
  // `g` there. (For every other primitive n is g and this changes nothing.)
  const Vec3 nr = glm::dot(ray.dir, n) < 0.0 ? n : g;
  const Incidence at{
      point, leaving, n, nr, frame, isFlat(hit.primitive.kind) ? &hit.primitive : nullptr, hit.t};

  const DirectLight direct = directLighting(ray, at, m, depth, counts, record);
  if (record != nullptr) record->children.reserve(2); // keeps the child pointers valid
  const Color reflected = reflection(ray, at, m, depth, counts, record);
  const Color transmitted = transmission(ray, at, m, depth, counts, record);
  const Color radiance = direct.ambientDiffuse + direct.highlight + reflected + transmitted;
  if (record != nullptr) {
    record->hit = true;
    record->where = hit;
    record->point = point;
    record->normal = surface.outward;
    record->shadingNormal = n;
    record->uv = surface.uv;
    record->part = surface.part;
    record->material = m;
    record->leaving = leaving;
    record->ambientDiffuse = direct.ambientDiffuse;
    record->highlight = direct.highlight;
    record->reflected = reflected;
    record->transmitted = transmitted;
    record->radiance = radiance;
  }
  return radiance;
}

[[gnu::always_inline]] inline Tracer::DirectLight
Tracer::directLighting(const Ray& ray, const Incidence& at, const Material& m, int depth,
                       RayCounts& counts, RayTreeNode* record) {
  Color diffuse(0.0), specular(0.0);
  // A material with kdr = ksr = 0 cannot reflect light, so no shadow ray could
  // change the result: none is traced (or counted).
  const bool reflectsLight = m.kdr > 0.0 || m.ksr > 0.0;
  for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
    const Light& light = scene_.lights[i];
    LightTerm term;
    term.light = int(i) + 1;
    const Vec3 toLight = light.position - at.point;
    const double r2 = glm::dot(toLight, toLight);
    term.distance = std::sqrt(r2);
    const double invR2 = 1.0 / r2;
    const Vec3 l = toLight / term.distance;
    term.cosine = std::isfinite(invR2) ? glm::dot(at.n, l) : 0.0;
    // A light behind the surface, or at the shaded point itself, adds nothing.
    term.behind = !(term.cosine > 0.0);
    term.skipped = !term.behind && !reflectsLight;
    if (!term.behind && !term.skipped) {
      const Vec3 shadowToLight = light.position - at.frame.above;
      const double shadowLength = glm::length(shadowToLight);
      ++counts.shadow;
      // A blocker at or beyond the light does not count: the range ends there.
      term.shadowed = shadowLength > 0.0 && blocked({at.frame.above, shadowToLight / shadowLength},
                                                    shadowLength, at.skip, i, depth);
      if (term.shadowed && record != nullptr) {
        accel_.closestHit({at.frame.above, shadowToLight / shadowLength},
                          Interval{0.0, shadowLength}, at.skip, term.blocker);
      }
      if (!term.shadowed) {
        term.diffuse = light.intensity * (term.cosine * invR2);
        const Vec3 halfway = l - ray.dir;
        const double length = glm::length(halfway);
        const double cosH = length > 0.0 ? glm::dot(at.n, halfway / length) : 0.0;
        term.specular = light.intensity * (powNonNegative(std::max(cosH, 0.0), m.e) * invR2);
        diffuse += term.diffuse;
        specular += term.specular;
      }
    }
    if (record != nullptr) record->lights.push_back(term);
  }
  return {saturated(m.color * m.kdr) * saturated(scene_.ambient + diffuse),
          m.ksr * saturated(specular)};
}

[[gnu::always_inline]] inline Color Tracer::reflection(const Ray& ray, const Incidence& at,
                                                       const Material& m, int depth,
                                                       RayCounts& counts, RayTreeNode* record) {
  if (!(depth < maxDepth_ && m.ksr > 0.0)) return Color(0.0);
  const Ray r{at.frame.above, reflect(ray.dir, at.nr)};
  if (images_) [[unlikely]]
    setChildCone(depth, at.t, 1.0);
  // A mirror keeps the cone's spread: exact for a flat one; a curved mirror
  // would spread it further, which this leaves out (the image reflected in a
  // ball is filtered as if the ball were flat).
  if (bailout_ != nullptr)
    return m.ksr * traceOrSkip(r, RayKind::Reflected, m, depth, counts, record, at.skip);
  ++counts.reflected;
  return m.ksr * trace(r, depth + 1, counts, childOf(record, RayKind::Reflected), at.skip);
}

[[gnu::always_inline]] inline Color Tracer::transmission(const Ray& ray, const Incidence& at,
                                                         const Material& m, int depth,
                                                         RayCounts& counts, RayTreeNode* record) {
  if (!(depth < maxDepth_ && m.kst > 0.0)) return Color(0.0);
  // Entering a solid from air the index ratio is 1/ir; leaving it, ir.
  const double eta = at.leaving ? m.ir : 1.0 / m.ir;
  Vec3 dir;
  if (!refract(ray.dir, at.nr, eta, dir)) {
    ++counts.tirEvents; // TIR moves no energy: I_t = 0, reflection unchanged
    if (record != nullptr) record->totalInternalReflection = true;
    return Color(0.0);
  }
  const Ray t{at.frame.below, dir};
  // Through a flat interface the cone's angle changes as the ray's does:
  // d(theta_t) / d(theta_i) = eta cos(theta_i) / cos(theta_t).
  if (images_) [[unlikely]]
    setChildCone(depth, at.t,
                 eta * std::abs(glm::dot(ray.dir, at.nr)) /
                     std::max(std::abs(glm::dot(dir, at.nr)), 1e-3));
  const ScopedValue<const Material*> medium(inside_, at.leaving ? nullptr : &m);
  // After the test for total internal reflection, which is counted as usual.
  if (bailout_ != nullptr)
    return m.kst * traceOrSkip(t, RayKind::Transmitted, m, depth, counts, record, at.skip);
  ++counts.transmitted;
  return m.kst * trace(t, depth + 1, counts, childOf(record, RayKind::Transmitted), at.skip);
}

} // namespace prism

#include "core/shapes/blob.h"

#include "core/shapes/axis_frame.h"
#include "core/shapes/refine_root.h"
#include "core/shapes/roundoff.h"
#include "core/shapes/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

namespace {

// A component's sphere entered or left by the ray's line.
struct Event {
  double t;
  std::uint32_t index; // into the blob's components
  bool enter;
};

// The round-off of the field's polynomial coefficients on one stretch, as a
// fraction of their magnitude (see below): 2^-44 is 512 u, far above the few
// dozen roundings each coefficient and each level of subdivision adds.
constexpr double kFieldRoundoff = 0x1p-44;
// The deepest subdivision of a stretch: 2^-60 of it is below the
// resolution of its parameter.
constexpr int kMaxDepth = 60;

// The walk along the ray: the field minus the threshold is, on each stretch
// between consecutive sphere entries and exits, a polynomial of degree 4 in
// the stretch's parameter u in [0, 1] (a sum of squares of quadratics). Its
// Bernstein coefficients bound it on the stretch (the convex hull property)
// and split exactly by de Casteljau's rule, so a piece is set aside only
// when its coefficients prove the sign: all above the round-off bound (inside
// throughout) or all below its negative (outside throughout). A piece whose
// coefficients' differences (the derivative's Bernstein coefficients) all
// exceed the bound with one sign is monotone and holds at most one root,
// which safeguarded Newton refines when its ends differ in sign. Any other
// piece is halved, until its coefficients agree to within the bound (the
// field is zero there up to round-off) or it reaches kMaxDepth; such a piece
// is decided by the signs at its ends. The side the walk is on is carried
// from piece to piece, so a crossing at a boundary between stretches is
// counted once.
class Walk {
public:
  Walk(const std::function<bool(double, bool)>& visit, Interval range)
      : visit_(visit), range_(range) {}

  bool stopped() const { return stopped_; }
  void outside() { inside_ = false; }

  // The stretch [ta, tb] with the polynomial a[0] + a[1] u + ... + a[4] u^4
  // of t = ta + u (tb - ta), whose coefficients err by at most `err`.
  void stretch(double ta, double tb, const double (&a)[5], double err) {
    ta_ = ta;
    h_ = tb - ta;
    for (int i = 0; i < 5; ++i)
      a_[i] = a[i];
    err_ = err;
    double b[5];
    b[0] = a[0];
    b[1] = a[0] + a[1] / 4.0;
    b[2] = a[0] + a[1] / 2.0 + a[2] / 6.0;
    b[3] = a[0] + 0.75 * a[1] + a[2] / 2.0 + a[3] / 4.0;
    b[4] = a[0] + a[1] + a[2] + a[3] + a[4];
    if (!started_) {
      inside_ = b[0] >= 0.0;
      started_ = true;
    }
    piece(b, 0.0, 1.0, 0);
  }

private:
  void piece(const double (&b)[5], double ua, double ub, int depth) {
    if (stopped_) return;
    if (ta_ + ua * h_ >= range_.max) {
      stopped_ = true;
      return;
    }
    if (ta_ + ub * h_ <= range_.min) {
      // Nothing to report: only the side at its end, which is where every
      // way below leaves the walk.
      inside_ = b[4] >= 0.0;
      return;
    }
    const auto [lo, hi] = std::minmax({b[0], b[1], b[2], b[3], b[4]});
    if (lo > err_ || hi < -err_) { // the sign is proven
      settle(lo > err_, ua);
      return;
    }
    bool rising = true, falling = true;
    for (int k = 0; k < 4; ++k) {
      rising = rising && b[k + 1] - b[k] > 2.0 * err_;
      falling = falling && b[k + 1] - b[k] < -2.0 * err_;
    }
    if (rising || falling || hi - lo <= 4.0 * err_ || depth >= kMaxDepth) {
      // At most one root (monotone), or the field is zero up to round-off:
      // the ends decide.
      const bool endInside = b[4] >= 0.0;
      if (endInside != inside_) cross(ua, ub, endInside);
      return;
    }
    // de Casteljau at the middle.
    double left[5], right[5], w[5];
    for (int i = 0; i < 5; ++i)
      w[i] = b[i];
    for (int level = 0; level < 5; ++level) {
      left[level] = w[0];
      right[4 - level] = w[4 - level];
      for (int i = 0; i < 4 - level; ++i)
        w[i] = 0.5 * (w[i] + w[i + 1]);
    }
    const double um = 0.5 * (ua + ub);
    piece(left, ua, um, depth + 1);
    piece(right, um, ub, depth + 1);
  }

  // The sign of a piece proven from `ua` on: a change there (only possible
  // through round-off at the piece's start) is a crossing at ua.
  void settle(bool inside, double ua) {
    if (inside == inside_) return;
    report(ua, inside);
  }

  // The root in [ua, ub], where the side changes to `endInside`.
  void cross(double ua, double ub, bool endInside) {
    const auto f = [this](double u) {
      const double* a = a_;
      return FunctionValue{(((a[4] * u + a[3]) * u + a[2]) * u + a[1]) * u + a[0],
                           ((4.0 * a[4] * u + 3.0 * a[3]) * u + 2.0 * a[2]) * u + a[1]};
    };
    const double fa = f(ua).value, fb = f(ub).value;
    const double chord = fa != fb && std::isfinite(fa / (fa - fb))
                             ? ua + (ub - ua) * (fa / (fa - fb))
                             : 0.5 * (ua + ub);
    // Newton steps of 2^-40 leave errors of order 2^-80 in u.
    report(refineRoot(f, ua, ub, !inside_, chord, 0x1p-40), endInside);
  }

  void report(double u, bool entering) {
    inside_ = entering;
    const double t = ta_ + u * h_;
    if (range_.contains(t) && !visit_(t, entering)) stopped_ = true;
  }

  const std::function<bool(double, bool)>& visit_;
  Interval range_;
  bool started_ = false;
  bool inside_ = false;
  bool stopped_ = false;
  double ta_ = 0.0, h_ = 0.0, err_ = 0.0;
  double a_[5] = {};
};

// Scratch for the walk, reused by each thread's rays.
thread_local std::vector<Event> tEvents;
thread_local std::vector<std::uint32_t> tActive;

} // namespace

std::optional<std::string> blobProblem(std::span<const BlobComponent> components,
                                       double threshold) {
  if (components.empty()) return "a blob needs at least one component";
  if (components.size() > kMaxBlobComponents)
    return "more than " + std::to_string(kMaxBlobComponents) + " components";
  if (!std::isfinite(threshold)) return "not finite";
  if (!(threshold > 0.0)) return "the threshold must be positive";
  double positive = 0.0;
  for (const BlobComponent& c : components) {
    if (!isFinite(c.center) || !std::isfinite(c.radius) || !std::isfinite(c.strength))
      return "not finite";
    if (!(c.radius > 0.0)) return "the radii must be positive";
    if (c.strength == 0.0) return "the strengths must not be zero";
    if (c.strength > 0.0) positive += c.strength;
  }
  if (positive == 0.0) return "no component has a positive strength";
  if (!(positive > threshold))
    return "the positive strengths add up to at most the threshold, so the field never reaches "
           "it";
  return std::nullopt;
}

PlacedBlob makeBlob(std::span<const BlobComponent> components, double threshold, const Mat3& linear,
                    const Vec3& offset) {
  PlacedBlob out;
  Blob& b = out.blob;
  b.threshold = threshold;
  b.componentCount = std::uint32_t(components.size());
  out.components.assign(components.begin(), components.end());
  const double scale = glm::length(linear[0]);
  const bool similarity =
      hasRoundSections(linear) && std::abs(glm::length(linear[2]) - scale) <= 1e-12 * scale;
  if (similarity) {
    for (BlobComponent& c : out.components) {
      c.center = linear * c.center + offset;
      c.radius *= scale;
    }
  } else {
    b.frame = makeAffineFrame(linear, offset);
    b.placed = true;
  }
  // Each sphere of positive strength, carried by the frame's map: along world
  // axis i it reaches r |row i| from its centre (an ellipsoid's exact box).
  const Mat3& m = b.frame.objectToWorld;
  double size = 0.0;
  for (const BlobComponent& c : out.components) {
    size = std::max(size, maxAbsComponent(c.center) + c.radius);
    if (c.strength <= 0.0) continue;
    const Vec3 center = b.frame.objectToWorld * c.center + b.frame.objectToWorldOffset;
    for (int i = 0; i < 3; ++i) {
      const double half = c.radius * std::hypot(m[0][i], m[1][i], m[2][i]);
      b.bounds.lo[i] = std::min(b.bounds.lo[i], center[i] - half);
      b.bounds.hi[i] = std::max(b.bounds.hi[i], center[i] + half);
    }
  }
  b.roundoff = frameRoundoffScale(b.frame.objectToWorld, b.frame.worldToObject,
                                  b.frame.objectToWorldOffset, size);
  return out;
}

double fieldExcess(const Blob& b, std::span<const BlobComponent> components, const Vec3& p) {
  double field = 0.0;
  for (const BlobComponent& c : components) {
    const Vec3 w = (p - c.center) / c.radius;
    const double g = 1.0 - glm::dot(w, w);
    if (g > 0.0) field += c.strength * g * g;
  }
  return field - b.threshold;
}

void visitBlobCrossings(const Blob& b, std::span<const BlobComponent> components, const Ray& ray,
                        Interval range, const std::function<bool(double, bool)>& visit) {
  const Vec3 o = b.placed ? b.frame.pointToObject(ray.origin) : ray.origin;
  const Vec3 d = b.placed ? b.frame.directionToObject(ray.dir) : ray.dir;
  const double dd = glm::dot(d, d);
  if (!(dd > 0.0) || !std::isfinite(dd)) return;

  // Where the line meets each component's sphere, from its point nearest the
  // centre (stable for far-away origins). Not clipped to the range: the
  // stretches, and so the roots' round-off, are the same for every range,
  // so a query up to a crossing's t does not find it again a hair earlier.
  std::vector<Event>& events = tEvents;
  events.clear();
  for (std::uint32_t i = 0; i < components.size(); ++i) {
    const BlobComponent& c = components[i];
    const Vec3 oc = o - c.center;
    const double tm = -glm::dot(oc, d) / dd;
    const Vec3 nearest = oc + tm * d;
    const double h2 = (c.radius - glm::length(nearest)) * (c.radius + glm::length(nearest));
    if (!(h2 > 0.0)) continue;
    const double half = std::sqrt(h2 / dd);
    const double t0 = tm - half, t1 = tm + half;
    if (!(t0 < t1)) continue;
    events.push_back({t0, i, true});
    events.push_back({t1, i, false});
  }
  if (events.empty()) return;
  std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) { return x.t < y.t; });

  Walk walk(visit, range);
  std::vector<std::uint32_t>& active = tActive;
  active.clear();
  double from = events.front().t;
  for (const Event& e : events) {
    if (from >= range.max) return;
    if (e.t > from && !active.empty()) {
      // The stretch [from, e.t]: the active components' polynomial in u.
      double positive = 0.0;
      for (const std::uint32_t i : active)
        positive += std::max(components[i].strength, 0.0);
      if (positive < b.threshold) {
        // Each term is at most its strength: the field stays below the
        // threshold throughout.
        double a[5] = {-b.threshold, 0.0, 0.0, 0.0, 0.0};
        walk.stretch(from, e.t, a, 0.0);
      } else {
        const double h = e.t - from;
        const Vec3 start = o + from * d;
        double a[5] = {-b.threshold, 0.0, 0.0, 0.0, 0.0};
        double magnitude = b.threshold;
        for (const std::uint32_t i : active) {
          const BlobComponent& c = components[i];
          // g(u) = 1 - |w + u e|^2 = A + B u + C u^2, each of order 1 (the
          // stretch lies inside the sphere, whose chord is at most 2 r).
          const Vec3 w = (start - c.center) / c.radius;
          const Vec3 step = (h / c.radius) * d;
          const double A = 1.0 - glm::dot(w, w);
          const double B = -2.0 * glm::dot(w, step);
          const double C = -glm::dot(step, step);
          const double s = c.strength;
          a[0] += s * A * A;
          a[1] += 2.0 * s * A * B;
          a[2] += s * (B * B + 2.0 * A * C);
          a[3] += 2.0 * s * B * C;
          a[4] += s * C * C;
          const double sum = std::abs(A) + std::abs(B) + std::abs(C);
          magnitude += std::abs(s) * sum * sum;
        }
        walk.stretch(from, e.t, a, kFieldRoundoff * magnitude);
      }
      if (walk.stopped()) return;
    }
    if (e.enter) {
      active.push_back(e.index);
    } else {
      active.erase(std::find(active.begin(), active.end(), e.index));
      // Outside every sphere the field is 0, below the threshold.
      if (active.empty()) walk.outside();
    }
    from = e.t;
  }
}

bool intersect(const Blob& b, const ShapeArrays& arrays, const Ray& ray, Interval range,
               double& t) {
  bool found = false;
  visitBlobCrossings(b, componentsOf(b, arrays), ray, range, [&](double crossing, bool) {
    t = crossing;
    found = true;
    return false;
  });
  return found;
}

namespace {

// The outward direction in the frame (minus the field's gradient, up to a
// positive factor), the size of the field's terms there, and the component
// contributing most.
struct FieldSlope {
  Vec3 outward{0.0};
  double magnitude = 0.0;
  std::uint32_t strongest = 0;
};
FieldSlope fieldSlope(std::span<const BlobComponent> components, const Vec3& p) {
  FieldSlope f;
  double best = -std::numeric_limits<double>::infinity();
  double bestDistance = std::numeric_limits<double>::infinity();
  std::uint32_t nearest = 0;
  for (std::uint32_t i = 0; i < components.size(); ++i) {
    const BlobComponent& c = components[i];
    const Vec3 w = (p - c.center) / c.radius;
    const double w2 = glm::dot(w, w);
    if (w2 < bestDistance) {
      bestDistance = w2;
      nearest = i;
    }
    const double g = 1.0 - w2;
    if (!(g > 0.0)) continue;
    // d/dp s g^2 = -4 s g w / r.
    f.outward += (4.0 * c.strength * g / c.radius) * w;
    f.magnitude += std::abs(c.strength);
    if (c.strength * g * g > best) {
      best = c.strength * g * g;
      f.strongest = i;
    }
  }
  if (best == -std::numeric_limits<double>::infinity()) f.strongest = nearest;
  return f;
}

Vec3 framePoint(const Blob& b, const Vec3& point) {
  return b.placed ? b.frame.pointToObject(point) : point;
}

Vec3 worldNormal(const Blob& b, std::span<const BlobComponent> components, const Vec3& p,
                 const FieldSlope& f) {
  Vec3 g = f.outward;
  // Where the gradient vanishes (a saddle of the field exactly at the
  // threshold, or round-off far from any surface), away from the strongest
  // component's centre.
  if (!(maxAbsComponent(g) > 0.0)) g = p - components[f.strongest].center;
  if (!(maxAbsComponent(g) > 0.0)) g = Vec3(0.0, 0.0, 1.0);
  return b.placed ? b.frame.normalToWorldUnit(g) : unitLength(g);
}

} // namespace

Vec3 outwardNormal(const Blob& b, const ShapeArrays& arrays, const Vec3& point) {
  const std::span<const BlobComponent> components = componentsOf(b, arrays);
  const Vec3 p = framePoint(b, point);
  return worldNormal(b, components, p, fieldSlope(components, p));
}

Vec2 uvAt(const Blob& b, const ShapeArrays& arrays, const Vec3& point) {
  const std::span<const BlobComponent> components = componentsOf(b, arrays);
  const Vec3 p = framePoint(b, point);
  const Vec3 away = p - components[fieldSlope(components, p).strongest].center;
  return longitudeLatitude(maxAbsComponent(away) > 0.0 ? unitLength(away) : Vec3(0.0, 1.0, 0.0));
}

SurfacePoint surfaceAt(const Blob& b, const ShapeArrays& arrays, const Vec3& point) {
  const std::span<const BlobComponent> components = componentsOf(b, arrays);
  const Vec3 p = framePoint(b, point);
  const FieldSlope f = fieldSlope(components, p);
  SurfacePoint s;
  s.point = point;
  s.outward = worldNormal(b, components, p, f);
  s.shading = s.outward;
  // The crossing is a root of the field minus the threshold, whose value errs
  // by about kFieldRoundoff times its terms' size (Walk): along the normal
  // the point is then off by that over the gradient's length, carried to the
  // world by the frame's longest axis. In units of u (the offset multiplies
  // this by kRayOffsetRoundoff) that is 512 (threshold + terms) / |gradient|.
  const double gradient = glm::length(f.outward);
  const Mat3& m = b.frame.objectToWorld;
  const double stretch =
      std::sqrt(std::max({glm::dot(m[0], m[0]), glm::dot(m[1], m[1]), glm::dot(m[2], m[2])}));
  const double field = 512.0 * (b.threshold + f.magnitude) * stretch;
  s.roundoffScale = b.roundoff + (gradient > 0.0 ? std::min(field / gradient, 1e300) : 0.0);
  return s;
}

} // namespace prism

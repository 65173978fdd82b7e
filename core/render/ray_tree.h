// The record of one traced ray and everything it spawned, kept only when asked
// for (`prism render --pixel X Y`): every hit, each term of the shading formula
// per light, and the secondary rays with their depth.
#pragma once

#include "core/accel/accel.h"
#include "core/scene/material_blend.h"

#include <iosfwd>
#include <vector>

namespace prism {

struct LightTerm {
  int light = 0; // 1-based, as users number lights
  double distance = 0.0;
  double cosine = 0.0;   // N.L with the shading normal
  bool behind = false;   // N.L <= 0 or zero distance: no shadow ray was cast
  bool skipped = false;  // the material cannot reflect light: no shadow ray was cast
  bool shadowed = false; // a shadow ray found a blocker before the light
  Hit blocker;           // valid when shadowed
  Color diffuse{0.0};    // I_i max(N.L,0) / r^2 (before C_mat kdr)
  Color specular{0.0};   // I_i max(N.H,0)^e / r^2 (before ksr)
};

// What the ray's segment crossed (media.h): nothing is recorded for a scene
// without fog or absorbing materials (Unrecorded).
enum class SegmentMedium : std::uint8_t { Unrecorded, Clear, Fog, Absorber };

struct RayTreeNode {
  RayKind kind = RayKind::Eye;
  int depth = 1;
  Ray ray;
  bool hit = false;
  Hit where;
  Vec3 point{0.0};
  Vec3 normal{0.0};        // outward
  Vec3 shadingNormal{0.0}; // flipped to face the incoming ray
  Vec2 uv{0.0};            // the surface coordinates of the hit (SurfacePoint::uv)
  std::uint32_t part = 0;  // the face of a compound shape
  Material material;       // as looked up at the hit, a texture's blend (Scene::materialAt)
  TextureLookup texture;   // the lookup, when the stored material had a texture
  TextureKind textureKind = TextureKind::None;
  double textureScale = 1.0;
  ImageLookup image; // the image lookup, when the stored material had an image
  bool leaving = false;
  bool totalInternalReflection = false;
  std::vector<LightTerm> lights;
  // The four terms of the shading formula (docs/rendering-model.md), already multiplied by their
  // coefficients.
  Color ambientDiffuse{0.0}; // C_mat kdr [I_a + sum diffuse]
  Color highlight{0.0};      // ksr sum specular
  Color reflected{0.0};      // ksr I_r
  Color transmitted{0.0};    // kst I_t
  Color radiance{0.0};       // leaving the hit point (or the background)
  // Through the medium back to the ray's origin (scenes with fog or
  // absorbing materials only).
  SegmentMedium medium = SegmentMedium::Unrecorded;
  double segmentLength = 0.0; // infinite for a miss
  Color transmittance{1.0};   // exp(-coefficient d) per channel
  Color atOrigin{0.0};
  std::vector<RayTreeNode> children;
};

void printRayTree(std::ostream& out, const RayTreeNode& root, const Scene& scene);

} // namespace prism

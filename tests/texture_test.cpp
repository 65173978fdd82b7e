// Procedural solid textures (core/texture/, core/scene/material_blend.h):
// the noise's proven bounds (noise.cpp derives them), the patterns at
// hand-picked points and cell boundaries, a texture moving with its object,
// hit radiance on a checker mirror against the shading formula written out
// by hand, the bailout bound over blends, the .sc keywords and errors, and
// `prism convert`'s round trip. No expected value is the code's own output.
#include "core/accel/accel.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/bailout.h"
#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/scene/material_blend.h"
#include "core/scene/texture_groups.h"
#include "core/texture/noise.h"
#include "core/texture/pattern.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

namespace prism {
namespace {

constexpr TextureKind kKinds[] = {TextureKind::Checker, TextureKind::Stripes, TextureKind::Gradient,
                                  TextureKind::Noise,   TextureKind::Marble,  TextureKind::Wood};

double l1(const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

TEST(Texture, NoiseIsZeroOnTheLattice) {
  for (const Vec3 p : {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-7, 255, 256), Vec3(-1000, 513, -3),
                       Vec3(1e15, -1e15, 4)}) {
    EXPECT_EQ(gradientNoise(p), 0.0) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(fractalNoise(p), 0.0); // every octave's point is on the lattice too
    EXPECT_EQ(turbulence(p), 0.0);
    EXPECT_EQ(patternValue(TextureKind::Noise, p), 0.5);
  }
  // Nor is it zero everywhere: off the lattice it takes both signs.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  double lo = 0.0, hi = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double n = gradientNoise({u(rng), u(rng), u(rng)});
    lo = std::min(lo, n);
    hi = std::max(hi, n);
  }
  EXPECT_LT(lo, -0.3);
  EXPECT_GT(hi, 0.3);
}

// |n| <= 2 and |n(p) - n(q)| <= 8.5 |p - q|_1 (noise.cpp). The fractal sum
// of six octaves at frequency 2^i and amplitude 2^-i changes by at most
// 6 * 8.5 per unit, and the noise pattern (0.5 + 0.5 sum) by half that.
TEST(Texture, NoiseIsBoundedAndLipschitz) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-300.0, 300.0), step(-0.02, 0.02);
  const double slack = 1e-12;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const Vec3 q = p + Vec3(step(rng), step(rng), step(rng));
    const double np = gradientNoise(p);
    ASSERT_LE(std::abs(np), 2.0);
    ASSERT_LE(std::abs(np - gradientNoise(q)), kNoiseLipschitz * l1(p - q) + slack) << i;
    const double sp = patternValue(TextureKind::Noise, p);
    const double sq = patternValue(TextureKind::Noise, q);
    ASSERT_LE(std::abs(sp - sq), 0.5 * kNoiseOctaves * kNoiseLipschitz * l1(p - q) + slack);
    ASSERT_GE(turbulence(p), 0.0);
  }
}

TEST(Texture, EveryPatternStaysInTheUnitInterval) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const TextureKind kind : kKinds) {
    for (int i = 0; i < 5000; ++i) {
      const double v = patternValue(kind, {u(rng), u(rng), u(rng)});
      ASSERT_TRUE(v >= 0.0 && v <= 1.0) << textureKindName(kind) << " " << v;
    }
    // Far beyond any integer type, and not finite: still a value, never NaN.
    for (const Vec3 p :
         {Vec3(1e300, -1e300, 3e250), Vec3(-1e-300, 0, 0), Vec3(kNaN, 0, 0), Vec3(0, kInf, 0)}) {
      const double v = patternValue(kind, p);
      EXPECT_TRUE(v >= 0.0 && v <= 1.0) << textureKindName(kind);
    }
    EXPECT_EQ(patternValue(kind, {kNaN, 0, 0}), 0.0);
  }
}

TEST(Texture, PatternsAtHandPickedPoints) {
  const auto at = [](TextureKind k, double x, double y, double z) {
    return patternValue(k, {x, y, z});
  };
  // Checker: unit cubes, 0 on the one at the origin; a boundary belongs to
  // the cell above it.
  EXPECT_EQ(at(TextureKind::Checker, 0.5, 0.5, 0.5), 0.0);
  EXPECT_EQ(at(TextureKind::Checker, 1.5, 0.5, 0.5), 1.0);
  EXPECT_EQ(at(TextureKind::Checker, 1.5, 1.5, 0.5), 0.0);
  EXPECT_EQ(at(TextureKind::Checker, 1.5, 1.5, 1.5), 1.0);
  EXPECT_EQ(at(TextureKind::Checker, -0.5, 0.5, 0.5), 1.0);
  EXPECT_EQ(at(TextureKind::Checker, -0.5, -0.5, 0.5), 0.0);
  EXPECT_EQ(at(TextureKind::Checker, 0.0, 0.0, 0.0), 0.0);
  EXPECT_EQ(at(TextureKind::Checker, 1.0, 0.0, 0.0), 1.0);
  EXPECT_EQ(at(TextureKind::Checker, -1e-300, 0.0, 0.0), 1.0); // floor is -1
  // Stripes: slabs across x only.
  EXPECT_EQ(at(TextureKind::Stripes, 0.5, 7.5, -3.5), 0.0);
  EXPECT_EQ(at(TextureKind::Stripes, 1.0, 0, 0), 1.0);
  EXPECT_EQ(at(TextureKind::Stripes, 1.99, 0, 0), 1.0);
  EXPECT_EQ(at(TextureKind::Stripes, 2.0, 0, 0), 0.0);
  EXPECT_EQ(at(TextureKind::Stripes, -0.25, 0, 0), 1.0);
  EXPECT_EQ(at(TextureKind::Stripes, -1.0, 0, 0), 1.0);
  EXPECT_EQ(at(TextureKind::Stripes, -2.0, 0, 0), 0.0);
  // Gradient: the fractional part of x.
  EXPECT_EQ(at(TextureKind::Gradient, 0.25, 9, 9), 0.25);
  EXPECT_EQ(at(TextureKind::Gradient, 1.75, 0, 0), 0.75);
  EXPECT_EQ(at(TextureKind::Gradient, -0.25, 0, 0), 0.75);
  EXPECT_EQ(at(TextureKind::Gradient, 3.0, 0, 0), 0.0);
  // Marble and wood on the lattice, where the turbulence is 0: marble is
  // (1 - |sin(pi x)|)^3, 1 (a vein) at integer x; wood is the fractional
  // part of the radius, 0 at (3, 4) (radius 5) and on the axis.
  EXPECT_NEAR(at(TextureKind::Marble, 3, -2, 7), 1.0, 1e-15);
  EXPECT_EQ(at(TextureKind::Wood, 3, 4, -6), 0.0);
  EXPECT_EQ(at(TextureKind::Wood, 0, 0, 11), 0.0);
}

TEST(Texture, KindNames) {
  for (const TextureKind kind : kKinds)
    EXPECT_EQ(textureKindNamed(textureKindName(kind)), kind);
  EXPECT_FALSE(textureKindNamed("none"));
  EXPECT_FALSE(textureKindNamed("Checker"));
}

// --- The scene language and the blend

const Material& materialOf(const Scene& scene, std::size_t sphere) {
  return scene.materials[scene.shapes<Sphere>().at(sphere).material];
}

// The texture lookup of a sphere's material at a world point.
TextureLookup lookupAt(const Scene& scene, std::size_t sphere, const Vec3& world) {
  TextureLookup lookup;
  textureAt(materialOf(scene, sphere), world, &lookup);
  return lookup;
}

TEST(Texture, KeywordsAmendTheCurrentSurface) {
  const Scene scene = parseScene(R"(
surface 0.8 0.6 0.4  1 0 0  1 1.5
texture checker 2  0.1 0.2 0.3  0.5 0.25 0.125  8
sphere 0 0 0 1
push
  texture stripes 1  1 1 1  1 0 0  1
  sphere 3 0 0 1
pop
sphere 6 0 0 1
surface 0.8 0.6 0.4  1 0 0  1 1.5
sphere 9 0 0 1
)",
                                 "k.sc");
  const Texture& t = materialOf(scene, 0).texture;
  EXPECT_EQ(t.kind, TextureKind::Checker);
  EXPECT_EQ(t.scale, 2.0);
  EXPECT_EQ(t.color, Color(0.1, 0.2, 0.3));
  EXPECT_EQ(t.kdr, 0.5);
  EXPECT_EQ(t.ksr, 0.25);
  EXPECT_EQ(t.kst, 0.125);
  EXPECT_EQ(t.e, 8.0);
  EXPECT_EQ(materialOf(scene, 0).ir, 1.5); // the material's own values stay
  EXPECT_EQ(materialOf(scene, 0).color, Color(0.8, 0.6, 0.4));
  EXPECT_EQ(materialOf(scene, 1).texture.kind, TextureKind::Stripes);
  // pop restores the texture as it was at push; `surface` replaces it.
  EXPECT_EQ(scene.shapes<Sphere>()[2].material, scene.shapes<Sphere>()[0].material);
  EXPECT_FALSE(materialOf(scene, 3).texture.active());
}

TEST(Texture, Errors) {
  EXPECT_EQ(test::sceneErrorsOf("texture plaid 1  1 1 1  1 0 0  1\n"),
            "t.sc:1:9: error: texture: expected a kind (checker, stripes, gradient, noise, "
            "marble, wood) but found 'plaid'");
  EXPECT_EQ(test::sceneErrorsOf("texture\n"),
            "t.sc:1:1: error: texture: expected a kind (checker, stripes, gradient, noise, "
            "marble, wood) but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("texture wood 0  1 1 1  1 0 0  1\n"),
            "t.sc:1:14: error: texture: SCALE must be positive, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("texture wood 1  1 1 1  -1 0 0  1\n"),
            "t.sc:1:24: error: texture: KDR must not be negative, found '-1'");
  EXPECT_EQ(test::sceneErrorsOf("texture checker big  1 1 1  1 0 0  1\n"),
            "t.sc:1:17: error: texture: expected SCALE (a number) but found 'big'");
  EXPECT_EQ(test::sceneErrorsOf("texture checker 1  1 1 1  1 0 0  1e999\n"),
            "t.sc:1:34: error: texture: E is not a finite number ('1e999')");
  EXPECT_EQ(test::sceneErrorsOf("texture wood 1  1 1 1  1 0 0\n"),
            "t.sc:1:1: error: texture: expected E but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("texture_space 1 0 0 0  0 1 0 0  0 0 1 0\n"),
            "t.sc:1:1: error: texture_space: the current surface has no texture (give "
            "'texture' first)");
  // The next command still parses after a bad kind.
  EXPECT_EQ(test::sceneErrorsOf("texture plaid 1 1 1 1 1 0 0 1\nsphere 0 0 0 -1\n"),
            "t.sc:1:9: error: texture: expected a kind (checker, stripes, gradient, noise, "
            "marble, wood) but found 'plaid'\n"
            "t.sc:2:14: error: sphere: negative radius '-1'");
}

// The previewer edits "a texture" (core/scene/texture_groups.h): the
// materials one `texture` line made, one per object space, are one group;
// a line alike under a surface alike joins it; one coefficient apart is
// another group; untextured materials are in none.
TEST(Texture, GroupsGatherWhatOneTextureLineMadeInEveryObjectSpace) {
  const Scene scene = parseScene(R"(
surface 0.8 0.6 0.4  1 0 0  1 1
texture checker 2  0.1 0.2 0.3  0.5 0 0  8
sphere 0 0 0 1
push
  translate 3 0 0
  sphere 0 0 0 1
pop
push
  rotate 0 1 0 30
  sphere 0 0 0 1
pop
surface 0.8 0.6 0.4  1 0 0  1 1
sphere 0 9 0 1
texture marble 1  1 1 1  1 0 0  1
push
  translate 0 -5 0
  sphere 0 0 0 1
pop
surface 0.8 0.6 0.4  1 0 0  1 1
texture checker 2  0.1 0.2 0.3  0.5 0 0  8
push
  translate 0 5 0
  sphere 0 0 0 1
pop
texture checker 2  0.1 0.2 0.3  0.5 0 0  9
sphere 0 0 -5 1
)",
                                 "g.sc");
  const auto materialIndex = [&](std::size_t sphere) {
    return scene.shapes<Sphere>().at(sphere).material;
  };
  // Three object spaces of the first line, and the fourth of the line alike.
  ASSERT_EQ(scene.materials.size(), 7u);
  const std::vector<TextureGroup> groups = textureGroups(scene);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].kind, TextureKind::Checker);
  EXPECT_EQ(groups[0].materials, (std::vector<std::uint32_t>{materialIndex(0), materialIndex(1),
                                                             materialIndex(2), materialIndex(5)}));
  EXPECT_EQ(groups[1].kind, TextureKind::Marble);
  EXPECT_EQ(groups[1].materials, std::vector<std::uint32_t>{materialIndex(4)});
  EXPECT_EQ(groups[2].kind, TextureKind::Checker);
  EXPECT_EQ(groups[2].materials, std::vector<std::uint32_t>{materialIndex(6)});
  EXPECT_FALSE(scene.materials[materialIndex(3)].texture.active());

  // The values an edit changes, and nothing else: the map stays.
  Material m = scene.materials[materialIndex(1)];
  EXPECT_EQ(textureValuesOf(m), (TextureValues{2.0, Color(0.1, 0.2, 0.3), Color(0.8, 0.6, 0.4)}));
  const TextureValues edited{0.25, Color(1, 0.5, 0), Color(0, 0, 1)};
  setTextureValues(m, edited, groups[0]);
  EXPECT_EQ(textureValuesOf(m), edited);
  EXPECT_EQ(m.texture.offset, scene.materials[materialIndex(1)].texture.offset);
  EXPECT_NE(m.texture.offset, Vec3(0.0)); // translated: the check above could fail
  // The identity leaves out the map and the edited values, not the rest.
  EXPECT_EQ(textureIdentity(m), textureIdentity(scene.materials[materialIndex(0)]));
  EXPECT_FALSE(textureIdentity(m) == textureIdentity(scene.materials[materialIndex(6)]));
}

// A scene without textures has untextured materials, shared across
// transforms exactly as before.
TEST(Texture, UntexturedScenesAreUnchanged) {
  const Scene scene = parseScene(R"(
surface 1 0 0  1 0 0  1 1
sphere 0 0 0 1
push
  translate 3 0 0
  rotate 0 1 0 30
  sphere 0 0 0 1
pop
)",
                                 "u.sc");
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_FALSE(scene.materials[0].texture.active());
  EXPECT_EQ(scene.materials[0].texture, Texture{});
}

// Object space: the same sphere moved shows the same pattern at the
// corresponding point; primitives under one map share one material.
TEST(Texture, TheTextureMovesWithItsObject) {
  const Scene scene = parseScene(R"(
surface 1 1 1  1 0 0  1 1
texture gradient 4  0 0 0  1 0 0  1
sphere 0 0 0 1
push
  translate 5 1 0
  sphere 0 0 0 1
  sphere 0 0 0 0.5
pop
push
  translate 5 1 0
  rotate 0 1 0 90
  sphere 0 0 0 1
pop
sphere 5 1 0 1
)",
                                 "m.sc");
  const auto& spheres = scene.shapes<Sphere>();
  EXPECT_EQ(spheres[1].material, spheres[2].material);
  EXPECT_NE(spheres[0].material, spheres[1].material);
  EXPECT_NE(spheres[1].material, spheres[3].material);
  const auto valueAt = [&](std::size_t sphere, const Vec3& world) {
    return lookupAt(scene, sphere, world);
  };
  // The top of each sphere: object point (0, 1, 0), gradient 0.
  // The point (0.5, 0, 0.866) of object space: x / 4 = 0.125.
  const Vec3 p(0.5, 0.0, 0.866);
  EXPECT_EQ(valueAt(0, p).value, 0.125);
  EXPECT_EQ(valueAt(1, p + Vec3(5, 1, 0)).value, 0.125);
  test::expectCloseTo(valueAt(1, p + Vec3(5, 1, 0)).point, p, 1e-15);
  // Rotated 90 degrees about y: object (x, y, z) is at world (z, y, -x)
  // around the centre, so object (0.5, 0, 0.866) is at world
  // (5.866, 1, -0.5).
  EXPECT_NEAR(valueAt(3, Vec3(5.866, 1, -0.5)).value, 0.125, 1e-14);
  test::expectCloseTo(valueAt(3, Vec3(5.866, 1, -0.5)).point, p, 1e-14);
  // The last sphere, written at (5, 1, 0) without a transform, is textured
  // in world coordinates: 5.5 / 4 = 1.375, fractional part 0.375.
  EXPECT_EQ(valueAt(4, p + Vec3(5, 1, 0)).value, 0.375);
}

// texture_space gives the map from the world, whatever the transform: at
// world x = 10.75 the gradient is 0.75 with it, 0.25 (object x) without.
TEST(Texture, TextureSpaceIsFromTheWorld) {
  const Scene scene = parseScene(R"(
texture gradient 1  0 0 0  1 0 0  1
push
  translate 10.5 0 0
  sphere 0 0 0 1
  texture_space 1 0 0 0  0 1 0 0  0 0 1 0
  sphere 0 0 0 1
  texture_space 2 0 0 0.5  0 1 0 0  0 0 1 0
  sphere 0 0 0 1
pop
)",
                                 "s.sc");
  const auto valueAt = [&](std::size_t sphere, const Vec3& world) {
    return lookupAt(scene, sphere, world).value;
  };
  EXPECT_EQ(valueAt(0, {10.75, 0, 0}), 0.25);
  EXPECT_EQ(valueAt(1, {10.75, 0, 0}), 0.75);
  EXPECT_EQ(valueAt(2, {10.75, 0, 0}), 0.0); // 2 * 10.75 + 0.5 = 22
  EXPECT_EQ(valueAt(2, {10.875, 0, 0}), 0.25);
  EXPECT_FALSE(materialOf(scene, 1).texture.fromWorld); // never in a scene's materials
}

// A mesh block is one primitive for its texture: object space is the
// transform at `mesh` (a push inside scopes only its triangles' placement),
// as a CSG operand too.
TEST(Texture, AMeshIsTexturedInTheSpaceOfItsBlock) {
  const std::string tetrahedron = R"(
  mesh
    push
      scale 2 2 2
      triangle 0 0 0  0 1 0  1 0 0
      triangle 0 0 0  1 0 0  0 0 1
      triangle 0 0 0  0 0 1  0 1 0
      triangle 1 0 0  0 1 0  0 0 1
    pop
  end
)";
  const std::string head = "texture gradient 1  0 0 0  1 0 0  1\npush\n  translate 10.5 0 0\n";
  const Scene plain = parseScene(head + tetrahedron + "pop\n", "m.sc");
  ASSERT_EQ(plain.shapes<Triangle>().size(), 4u);
  for (const Triangle& t : plain.shapes<Triangle>()) {
    TextureLookup lookup;
    textureAt(plain.materials[t.material], {10.75, 0.5, 0.5}, &lookup);
    EXPECT_EQ(lookup.value, 0.25); // object x 0.25, not world 10.75 or 0.125
  }
  const Scene operand =
      parseScene(head + "csg union\n" + tetrahedron + "  sphere 0 0 0 0.5\nend\npop\n", "c.sc");
  for (const Material& m : operand.materials) {
    TextureLookup lookup;
    textureAt(m, {10.75, 0.5, 0.5}, &lookup);
    EXPECT_EQ(lookup.value, 0.25);
  }
}

Color traced(const Scene& scene, const Vec3& origin, const Vec3& dir,
             RayTreeNode* record = nullptr) {
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  Tracer tracer(scene, *accel, 5);
  RayCounts counts;
  return tracer.trace({origin, glm::normalize(dir)}, 1, counts, record);
}

void expectColor(const Color& got, const Color& want) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-15) << "channel " << c;
}

// A floor at y = 0.5 (inside the checker's y cell 0), lit by ambient 0.25
// only, under a background of (0.1, 0.2, 0.3). The material's own end is
// diffuse, the texture's a perfect mirror, so with no lights
//   diffuse tile: C kdr Ia           = (0.8, 0.6, 0.4) * 0.25
//   mirror tile:  ksr * background   = (0.1, 0.2, 0.3)
// (the mirror ray goes straight up into the background).
constexpr const char* kCheckerMirror = R"(
background 0.1 0.2 0.3
ambient 0.25 0.25 0.25
surface 0.8 0.6 0.4  1 0 0  1 1
texture checker 1  1 1 1  0 1 0  1
polygon 4  -50 0.5 -50  50 0.5 -50  50 0.5 50  -50 0.5 50
)";

TEST(Texture, CheckerMirrorShadesEachTileWithItsEnd) {
  const Scene scene = parseScene(kCheckerMirror, "c.sc");
  const Vec3 down(0, -1, 0);
  expectColor(traced(scene, {0.5, 5, 0.5}, down), Color(0.2, 0.15, 0.1));
  expectColor(traced(scene, {1.5, 5, 0.5}, down), Color(0.1, 0.2, 0.3));
  expectColor(traced(scene, {1.5, 5, 1.5}, down), Color(0.2, 0.15, 0.1));
  expectColor(traced(scene, {-0.5, 5, 0.5}, down), Color(0.1, 0.2, 0.3));
  // The ray tree shows the lookup and the blended material.
  RayTreeNode root;
  traced(scene, {1.5, 5, 0.5}, down, &root);
  std::ostringstream tree;
  printRayTree(tree, root, scene);
  EXPECT_NE(tree.str().find("texture checker (scale 1) at texture-space point (1.5, 0.5, 0.5): "
                            "value 1"),
            std::string::npos)
      << tree.str();
  EXPECT_NE(tree.str().find("material C (1, 1, 1) kdr 0 ksr 1 kst 0"), std::string::npos);
}

// Between the ends: a gradient at x = 0.25 blends a quarter of the way,
//   C = 0.75 (0.8, 0.6, 0.4) + 0.25 (1, 1, 1) = (0.85, 0.7, 0.55),
//   kdr = 0.75, ksr = 0.25,
// radiance C kdr Ia + ksr background.
TEST(Texture, GradientBlendsTheShadingFormulaLinearly) {
  std::string text = kCheckerMirror;
  text.replace(text.find("checker"), 7, "gradient");
  const Scene scene = parseScene(text, "g.sc");
  const Color c(0.85, 0.7, 0.55);
  expectColor(traced(scene, {0.25, 5, 3.5}, {0, -1, 0}),
              c * 0.75 * 0.25 + 0.25 * Color(0.1, 0.2, 0.3));
}

// C kdr of a blend can exceed both ends (here 0 at both ends, 0.25 halfway):
// the bound takes each coefficient's larger end, C = 1, kdr = 1, and
// with ambient 1 and no lights the bound is 1.
TEST(Texture, TheBailoutBoundCoversEveryBlend) {
  const Scene scene = parseScene(R"(
ambient 1 1 1
surface 1 1 1  0 0 0  1 1
texture gradient 1  0 0 0  1 0 0  1
polygon 4  -50 0.5 -50  50 0.5 -50  50 0.5 50  -50 0.5 50
)",
                                 "b.sc");
  expectColor(traced(scene, {0.5, 5, 0.5}, {0, -1, 0}), Color(0.25));
  const std::vector<double> beyond = radianceBounds(scene, 3);
  EXPECT_NEAR(beyond[1], 1.0, 1e-8);
  EXPECT_GE(beyond[1], 0.25);
}

// --- prism convert

constexpr const char* kTextured = R"(
surface 0.8 0.6 0.4  1 0 0  1 1.5
texture marble 0.75  0.1 0.2 0.3  0.5 0.25 0  8
sphere 0 0 0 1
push
  translate 5 1 -2
  rotate 1 2 3 37
  scale 1 2 0.5
  sphere 0 0 0 1
  box -1 -1 -1  1 1 1
  texture checker 0.3  1 1 1  0 1 0  1
  texture_space 1 0.5 0  0.25  0 1 0  -1  0 0 2 3
  cylinder 0 0 0  0 1 0  0.5
  csg difference
    sphere 0 0 0 1
    texture wood 0.2  0.3 0.2 0.1  1 0 0  1
    box 0 0 0  2 2 2
  end
pop
)";

TEST(Texture, WriterRoundTripIsExact) {
  const Scene scene = parseScene(kTextured, "r.sc");
  std::ostringstream text;
  writeScene(text, scene);
  const Scene again = parseScene(text.str(), "again.sc");
  EXPECT_EQ(again.materials, scene.materials) << text.str();
  // Four textured materials: marble in world space (the first sphere),
  // marble under the push's transform (its sphere and box share it), the
  // checker pinned by texture_space (the cylinder, the csg node and its
  // sphere), and wood under the transform (the csg's box).
  std::size_t textured = 0;
  for (const Material& m : again.materials)
    textured += m.texture.active() ? 1 : 0;
  EXPECT_EQ(textured, 4u);
  EXPECT_NE(text.str().find("texture_space"), std::string::npos);
  // Nothing of textures for a scene without one.
  std::ostringstream plain;
  writeScene(plain, parseScene("sphere 0 0 0 1\n", "p.sc"));
  EXPECT_EQ(plain.str().find("texture"), std::string::npos);
}

TEST(Texture, ConvertWritesPovRayPatterns) {
  std::ostringstream out;
  writePov(out, parseScene(kTextured, "p.sc"));
  const std::string text = out.str();
  EXPECT_NE(text.find("    checker\n"), std::string::npos) << text;
  EXPECT_NE(text.find("// approximate: POV-Ray's marble is not Prism's marble pattern"),
            std::string::npos);
  EXPECT_NE(text.find("    wood turbulence 0.1\n"), std::string::npos);
  // The untransformed marble sphere: the pattern scaled by 0.75, no more.
  EXPECT_NE(text.find("    matrix <0.75, 0, 0, 0, 0.75, 0, 0, 0, 0.75, 0, 0, 0>\n"),
            std::string::npos);
}

} // namespace
} // namespace prism

// Image textures (core/texture/image_map.h, image_library.h, the tracer's
// ray cone): the sRGB transfer function against its definition, texel
// values of small images written here against hand-decoded ones, the wrap
// modes, filtering that averages light rather than code values, the ray
// cone's width written out by hand through a flat mirror and a glass slab,
// the footprint's axes on a plane seen straight on and at 60 degrees, the
// .sc keywords and their errors, `prism convert`'s round trip, and no NaN
// from a float image holding NaN and infinities.
#include "core/accel/accel.h"
#include "core/io/image_io.h"
#include "core/io/oiio_module.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/bailout.h"
#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/scene/material_blend.h"
#include "core/scene/texture_groups.h"
#include "core/texture/image_library.h"
#include "core/texture/srgb.h"
#include "tests/test_expect.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace prism {
namespace {

namespace fs = std::filesystem;
using test::expectVecNear;

// The definition (IEC 61966-2-1), written out.
double decoded(int code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

TEST(ImageTexture, SrgbTransferFunction) {
  EXPECT_EQ(srgbToLinear(0.0), 0.0);
  EXPECT_NEAR(srgbToLinear(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgbToLinear(0.04045), 0.04045 / 12.92, 1e-15); // the linear segment's end
  EXPECT_NEAR(srgbToLinear(0.5), 0.21404114048223255, 1e-12); // ((0.555 / 1.055)^2.4)
  for (int code = 0; code <= 255; code += 15)
    EXPECT_NEAR(linearToSrgb(srgbToLinear(code / 255.0)), code / 255.0, 1e-12);
}

// A 2 x 2 PNG, rows from the top: red, green / blue, grey 128.
struct SmallImage {
  test::ScratchDir dir;
  fs::path png = dir.path() / "small.png";
  SmallImage() { writeImage8(png, 2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 128, 128, 128}); }
};

ImageMap mapOf(std::uint32_t image, ImageWrap wrap = ImageWrap::Repeat) {
  ImageMap map;
  map.image = image;
  map.wrap = wrap;
  return map;
}

TEST(ImageTexture, TexelsAreDecodedFromSrgb) {
  SmallImage small;
  ImageLibrary library(oiioTextureBackend());
  const auto loaded = library.load(small.png.string(), ImageEncoding::Auto);
  ASSERT_TRUE(std::holds_alternative<std::uint32_t>(loaded)) << std::get<std::string>(loaded);
  const std::uint32_t image = std::get<std::uint32_t>(loaded);
  EXPECT_EQ(library.info(image).width, 2);
  EXPECT_EQ(library.info(image).decoded, ImageEncoding::Srgb);
  EXPECT_EQ(library.info(image).peak, Color(1.0, 1.0, 1.0));
  // Loaded once: the same path and encoding give the same index.
  EXPECT_EQ(std::get<std::uint32_t>(library.load(small.png.string(), ImageEncoding::Auto)), image);
  // Texel centres with a point footprint; t runs up, so the top row is at 0.75.
  const ImageMap map = mapOf(image);
  const double grey = decoded(128);
  expectVecNear(library.lookup(map, {0.25, 0.75}, {}, {}), {1, 0, 0}, 1e-6);
  expectVecNear(library.lookup(map, {0.75, 0.75}, {}, {}), {0, 1, 0}, 1e-6);
  expectVecNear(library.lookup(map, {0.25, 0.25}, {}, {}), {0, 0, 1}, 1e-6);
  expectVecNear(library.lookup(map, {0.75, 0.25}, {}, {}), Vec3(grey), 1e-6);
  // `linear` takes the codes as they are.
  const auto raw = std::get<std::uint32_t>(library.load(small.png.string(), ImageEncoding::Linear));
  EXPECT_NE(raw, image);
  expectVecNear(library.lookup(mapOf(raw), {0.75, 0.25}, {}, {}), Vec3(128 / 255.0), 1e-6);
}

TEST(ImageTexture, WrapModes) {
  SmallImage small;
  ImageLibrary library(oiioTextureBackend());
  const auto image = std::get<std::uint32_t>(library.load(small.png.string(), ImageEncoding::Auto));
  const Vec2 outside{1.25, 0.75}; // a quarter beyond the right edge, top row
  expectVecNear(library.lookup(mapOf(image, ImageWrap::Repeat), outside, {}, {}), {1, 0, 0}, 1e-6);
  expectVecNear(library.lookup(mapOf(image, ImageWrap::Clamp), outside, {}, {}), {0, 1, 0}, 1e-6);
  expectVecNear(library.lookup(mapOf(image, ImageWrap::Mirror), outside, {}, {}), {0, 1, 0}, 1e-6);
  expectVecNear(library.lookup(mapOf(image, ImageWrap::Black), outside, {}, {}), {0, 0, 0}, 1e-6);
  const Vec2 twoOver{2.75, 0.75}; // mirrored twice: the right column again
  expectVecNear(library.lookup(mapOf(image, ImageWrap::Mirror), twoOver, {}, {}), {0, 1, 0}, 1e-6);
}

// A footprint covering the whole image gives its mean in light: for black
// and white texels 0.5, where averaging the sRGB codes would give
// decode(127.5 / 255) = 0.21.
TEST(ImageTexture, FilteringAveragesLight) {
  test::ScratchDir dir;
  const fs::path png = dir.path() / "bw.png";
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c)
        rgb.push_back((x + y) % 2 == 0 ? 255 : 0);
  writeImage8(png, 16, 16, rgb);
  ImageLibrary library(oiioTextureBackend());
  const auto image = std::get<std::uint32_t>(library.load(png.string(), ImageEncoding::Auto));
  const Color wide = library.lookup(mapOf(image), {0.5, 0.5}, {1.0, 0.0}, {0.0, 1.0});
  expectVecNear(wide, Vec3(0.5), 0.02);
  // Unfiltered, the same lookup is one texel: black or white.
  ImageMap point = mapOf(image);
  point.filtered = false;
  const Color one = library.lookup(point, {0.5 + 1.0 / 32, 0.5 + 1.0 / 32}, {1, 0}, {0, 1});
  EXPECT_TRUE(one == Color(0.0) || one == Color(1.0)) << one.r;
}

TEST(ImageTexture, FloatImagesAreLinearAndNeverNaN) {
  test::ScratchDir dir;
  const fs::path tif = dir.path() / "f.tif";
  const double inf = std::numeric_limits<double>::infinity();
  writeImageFloat(tif, 2, 1,
                  {Rgb{2.5f, float(std::nan("")), float(-1.0)}, Rgb{float(inf), 0.25f, 0.5f}});
  ImageLibrary library(oiioTextureBackend());
  const auto image = std::get<std::uint32_t>(library.load(tif.string(), ImageEncoding::Auto));
  EXPECT_EQ(library.info(image).decoded, ImageEncoding::Linear);
  // NaN, infinity and negative values are 0; everything else as written.
  expectVecNear(library.lookup(mapOf(image), {0.25, 0.5}, {}, {}), {2.5, 0, 0}, 1e-6);
  expectVecNear(library.lookup(mapOf(image), {0.75, 0.5}, {}, {}), {0, 0.25, 0.5}, 1e-6);
  EXPECT_EQ(library.info(image).peak, Color(2.5, 0.25, 0.5));
  // A footprint over both texels stays finite.
  const Color mean = library.lookup(mapOf(image), {0.5, 0.5}, {1, 0}, {0, 1});
  EXPECT_TRUE(std::isfinite(mean.r) && std::isfinite(mean.g) && std::isfinite(mean.b));
}

// A camera-free trace: one eye ray with a footprint of spread 0.01 per unit.
RayTreeNode traced(const Scene& scene, const Ray& ray, double spread = 0.01) {
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  Tracer tracer(scene, *accel, 5);
  tracer.setEyeFootprint(spread);
  RayCounts counts;
  RayTreeNode root;
  tracer.trace(ray, 1, counts, &root);
  return root;
}

// The textured floor polygon at z = 0 facing +z, with (u, v) = world (x, y)
// from its first vertex (its first edge runs along +x).
std::string floorAt(const std::string& image, double scale) {
  std::ostringstream s;
  s << "surface 1 1 1  1 0 0  1 1\nimage \"" << image << "\"\nuv " << scale << " " << scale
    << " 0 0\npolygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0\n";
  return s.str();
}

const RayTreeNode* lastHit(const RayTreeNode& root) {
  const RayTreeNode* node = &root;
  while (!node->children.empty())
    node = &node->children.back();
  return node;
}

TEST(ImageTexture, FootprintStraightOnAndOblique) {
  SmallImage small;
  const Scene scene = parseScene(floorAt("small.png", 0.5), (small.dir.path() / "f.sc").string());
  // Straight on from 4 units: width 0.04, both axes 0.04 world units, 0.02 in s and t.
  const RayTreeNode straight = traced(scene, {{0.3, 0.2, 4.0}, {0, 0, -1}});
  ASSERT_TRUE(straight.hit);
  EXPECT_NEAR(straight.image.footprint, 0.04, 1e-12);
  EXPECT_NEAR(std::hypot(straight.image.dx.x, straight.image.dx.y), 0.02, 1e-12);
  EXPECT_NEAR(std::hypot(straight.image.dy.x, straight.image.dy.y), 0.02, 1e-12);
  EXPECT_NEAR(straight.image.st.x, (0.3 + 10) * 0.5, 1e-12);
  EXPECT_NEAR(straight.image.st.y, (0.2 + 10) * 0.5, 1e-12);
  // At 60 degrees from the normal, 4 units along the ray: the axis in the
  // plane of incidence is stretched by 1 / cos 60 = 2.
  const Vec3 dir = glm::normalize(Vec3(0.0, std::sin(M_PI / 3), -std::cos(M_PI / 3)));
  const RayTreeNode oblique = traced(scene, {Vec3(0, 0, 0) - 4.0 * dir, dir});
  ASSERT_TRUE(oblique.hit);
  EXPECT_NEAR(oblique.image.footprint, 0.04, 1e-12);
  EXPECT_NEAR(std::abs(oblique.image.dx.x), 0.02, 1e-12); // across: along x
  EXPECT_NEAR(std::abs(oblique.image.dx.y), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(oblique.image.dy.y), 0.04, 1e-9); // along: y, doubled
}

// On a sphere only the longitude wraps. Straight on at (0, 0, 1) of the unit
// sphere, 3 units from the eye with a spread of 1, the footprint is 3 wide:
// its half-axes reach 1.5 from the point on the tangent plane, up to
// latitudes +-atan(1.5), so t spans 2 atan(1.5) / pi = 0.626 (more than
// half the image, which must not be read as 0.374 the other way round), and
// s spans 2 atan(1.5) / 2 pi = 0.313.
TEST(ImageTexture, FootprintOnASphereWrapsOnlyTheLongitude) {
  SmallImage small;
  const Scene scene = parseScene("surface 1 1 1  1 0 0  1 1\nimage small.png\nsphere 0 0 0 1\n",
                                 (small.dir.path() / "g.sc").string());
  const RayTreeNode hit = traced(scene, {{0.0, 0.0, 4.0}, {0, 0, -1}}, 1.0);
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.image.footprint, 3.0, 1e-12);
  const Vec2 dx = hit.image.dx, dy = hit.image.dy;
  // One axis runs along the latitude, the other along the longitude.
  const Vec2 latitude = std::abs(dx.y) > std::abs(dy.y) ? dx : dy;
  const Vec2 longitude = std::abs(dx.y) > std::abs(dy.y) ? dy : dx;
  EXPECT_NEAR(std::abs(latitude.y), 2.0 * std::atan(1.5) / M_PI, 1e-12);
  EXPECT_NEAR(latitude.x, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(longitude.x), std::atan(1.5) / M_PI, 1e-12);
  EXPECT_NEAR(longitude.y, 0.0, 1e-12);
}

// Through a flat mirror the cone keeps its spread: the width at the floor is
// the spread times the whole path. Through a slab of index 1.5 at normal
// incidence the spread is divided by 1.5 inside and restored outside.
TEST(ImageTexture, ConeWidthThroughMirrorAndSlab) {
  SmallImage small;
  const std::string floor = floorAt("small.png", 1.0);
  // A mirror at z = 3 facing -z; the eye at z = 1 looks up at it: 2 up, 3 down.
  const Scene mirrored =
      parseScene(floor + "surface 0 0 0  0 1 0  1 1\npolygon 4  -5 -5 3  -5 5 3  5 5 3  5 -5 3\n",
                 (small.dir.path() / "m.sc").string());
  const RayTreeNode viaMirror = traced(mirrored, {{0.1, 0.1, 1.0}, {0, 0, 1}});
  const RayTreeNode* floorHit = lastHit(viaMirror);
  ASSERT_EQ(floorHit->kind, RayKind::Reflected);
  EXPECT_NEAR(floorHit->image.footprint, 0.01 * (2.0 + 3.0), 1e-12);
  // A glass slab from z = 1 to z = 1.6 (0.6 thick) above the floor; the eye at z = 3.
  const Scene slabbed = parseScene(floor + "surface 0 0 0  0 0 1  1 1.5\nbox -5 -5 1  5 5 1.6\n",
                                   (small.dir.path() / "s.sc").string());
  const RayTreeNode throughSlab = traced(slabbed, {{0.1, 0.1, 3.0}, {0, 0, -1}});
  const RayTreeNode* below = lastHit(throughSlab);
  ASSERT_EQ(below->kind, RayKind::Transmitted);
  ASSERT_TRUE(below->hit);
  EXPECT_NEAR(below->image.footprint, 0.01 * (1.4 + 0.6 / 1.5 + 1.0), 1e-12);
}

TEST(ImageTexture, ShadedColourIsTheMaterialTimesTheTexel) {
  SmallImage small;
  const Scene scene = parseScene("surface 0.5 1 1  1 0 0  1 1\nimage small.png\nuv 0.05 0.05 0 0\n"
                                 "polygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0\n",
                                 (small.dir.path() / "c.sc").string());
  // uv 0.05: the polygon's 20 units are one image; (5, 5) from the corner
  // (world (-5, -5)) is the bottom-left texel, blue, at its centre.
  const RayTreeNode hit = traced(scene, {{-5.0, -5.0, 1.0}, {0, 0, -1}}, 0.0);
  ASSERT_TRUE(hit.hit);
  expectVecNear(hit.image.value, {0, 0, 1}, 1e-6);
  expectVecNear(hit.material.color, {0, 0, 1}, 1e-6); // C (0.5, 1, 1) times the texel
  const RayTreeNode red = traced(scene, {{-5.0, 5.0, 1.0}, {0, 0, -1}}, 0.0);
  expectVecNear(red.material.color, {0.5, 0, 0}, 1e-6);
}

// The --pixel ray tree names the image and prints the lookup.
TEST(ImageTexture, RayTreePrintsTheLookup) {
  SmallImage small;
  const Scene scene = parseScene(floorAt("small.png", 0.5), (small.dir.path() / "p.sc").string());
  const RayTreeNode root = traced(scene, {{0.3, 0.2, 4.0}, {0, 0, -1}});
  std::ostringstream out;
  printRayTree(out, root, scene);
  const std::string text = out.str();
  EXPECT_NE(text.find("image '" + small.png.string() + "' (2 x 2, srgb) at (s, t) = (5.15, 5.1)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("footprint 0.04 wide"), std::string::npos) << text;
}

TEST(ImageTexture, UnusedCostsNothing) {
  const Scene plain = parseScene("sphere 0 0 0 1\n", "p.sc");
  EXPECT_EQ(plain.images, nullptr); // no library, no module loaded for it
  SmallImage small;
  const Scene two = parseScene("image \"small.png\"\nsphere 0 0 0 1\nsphere 3 0 0 1\n",
                               (small.dir.path() / "t.sc").string());
  ASSERT_NE(two.images, nullptr);
  EXPECT_EQ(two.images->size(), 1u);
  EXPECT_EQ(two.materials.size(), 1u); // one material for both: images need no object space
}

// The previewer edits an image as a texture (core/scene/texture_groups.h):
// one `image` line is one group, on every primitive it covers (one material:
// an image needs no object space); another file is another group; an image
// with a procedural texture is one group of the texture's object spaces,
// whose edit covers both. Untextured materials are in none.
TEST(ImageTexture, GroupsGatherWhatOneImageLineMade) {
  SmallImage small;
  writeImage8(small.dir.path() / "other.png", 1, 1, {10, 200, 30});
  const Scene scene = parseScene(R"(
surface 0.8 0.6 0.4  1 0 0  1 1
image small.png
uv 2 1  0.1 0.2
sphere 0 0 0 1
push
  translate 3 0 0
  sphere 0 0 0 1
pop
polygon 4  -5 -1 -5  -5 -1 5  5 -1 5  5 -1 -5
image other.png
uv -4 4  0 0
sphere 0 5 0 1
surface 0.8 0.6 0.4  1 0 0  1 1
texture marble 0.5  0.1 0.2 0.3  1 0 0  1
image small.png
uv 2 1  0.1 0.2
push
  translate 0 -5 0
  sphere 0 0 0 1
pop
push
  translate 0 -8 0
  sphere 0 0 0 1
pop
surface 0.8 0.6 0.4  1 0 0  1 1
sphere 0 0 -5 1
)",
                                 (small.dir.path() / "g.sc").string());
  const auto materialIndex = [&](std::size_t sphere) {
    return scene.shapes<Sphere>().at(sphere).material;
  };
  const std::vector<TextureGroup> groups = textureGroups(scene);
  ASSERT_EQ(groups.size(), 3u);
  // One line over two spheres and a polygon: one material, one group.
  EXPECT_TRUE(groups[0].imageOnly());
  EXPECT_EQ(groups[0].materials, std::vector<std::uint32_t>{materialIndex(0)});
  EXPECT_EQ(materialIndex(1), materialIndex(0));
  EXPECT_EQ(scene.shapes<Polygon>().at(0).material, materialIndex(0));
  EXPECT_EQ(groups[0].image, scene.materials[materialIndex(0)].image);
  EXPECT_EQ(groups[0].scale, 0.5); // one repeat of the image: 1 / SU
  // Another file: another group; a negative SU flips the image, its size is 1 / |SU|.
  EXPECT_TRUE(groups[1].imageOnly());
  EXPECT_EQ(groups[1].materials, std::vector<std::uint32_t>{materialIndex(2)});
  EXPECT_NE(groups[1].image.image, groups[0].image.image);
  EXPECT_EQ(groups[1].scale, 0.25);
  // The texture with the image: its two object spaces, one group.
  EXPECT_EQ(groups[2].kind, TextureKind::Marble);
  EXPECT_TRUE(groups[2].image.active());
  EXPECT_EQ(groups[2].materials, (std::vector<std::uint32_t>{materialIndex(3), materialIndex(4)}));
  EXPECT_EQ(groups[2].scale, 0.5); // the pattern's
  EXPECT_FALSE(scene.materials[materialIndex(5)].textured());

  // An image's edit: its size (SU and SV alike, the offset kept) and its
  // tint; the texture's value-1 colour means nothing to it and stays.
  const Material file = scene.materials[materialIndex(0)];
  EXPECT_EQ(textureValuesOf(file), (TextureValues{0.5, Color(1.0), Color(0.8, 0.6, 0.4)}));
  Material m = file;
  setTextureValues(m, {0.25, Color(0.1), Color(0, 0, 1)}, groups[0]);
  EXPECT_EQ(m.image.scale, Vec2(4, 2));
  EXPECT_EQ(m.image.offset, Vec2(0.1, 0.2));
  EXPECT_EQ(m.color, Color(0, 0, 1));
  EXPECT_EQ(m.texture, file.texture);
  // Any edit, then the file's values: the file's material, bit for bit.
  setTextureValues(m, {0.3, Color(1.0), Color(0.5)}, groups[0]);
  setTextureValues(m, textureValuesOf(file), groups[0]);
  EXPECT_EQ(m, file);
  Material flipped = scene.materials[materialIndex(2)];
  setTextureValues(flipped, {1.0, Color(1.0), Color(1.0)}, groups[1]);
  EXPECT_EQ(flipped.image.scale, Vec2(-1, 1));
  // With a texture: the pattern's scale, and the image sized with it.
  Material both = scene.materials[materialIndex(4)];
  setTextureValues(both, {1.0, Color(0.9), Color(0.2)}, groups[2]);
  EXPECT_EQ(both.texture.scale, 1.0);
  EXPECT_EQ(both.texture.color, Color(0.9));
  EXPECT_EQ(both.image.scale, Vec2(1, 0.5));
  EXPECT_EQ(both.texture.offset, scene.materials[materialIndex(4)].texture.offset);
  // The identity leaves out the edited values, the image's scale and which
  // image (the previewer compares the files), not the rest.
  Material elsewhere = file; // another file, size and tint
  elsewhere.image.image = groups[1].image.image;
  elsewhere.image.peak = groups[1].image.peak;
  elsewhere.image.scale = Vec2(-4, 4);
  elsewhere.color = Color(0.1);
  EXPECT_EQ(textureIdentity(elsewhere), textureIdentity(file));
  Material moved = file;
  moved.image.offset = Vec2(0.0);
  EXPECT_FALSE(textureIdentity(moved) == textureIdentity(file));
  EXPECT_FALSE(textureIdentity(both) == textureIdentity(file));
}

TEST(ImageTexture, KeywordsAndErrors) {
  SmallImage small;
  const std::string name = (small.dir.path() / "k.sc").string();
  const Scene scene = parseScene("image small.png mirror linear unfiltered\nuv 2 3 0.5 0.25\n"
                                 "sphere 0 0 0 1\n",
                                 name);
  const ImageMap& map = scene.materials[0].image;
  EXPECT_EQ(map.wrap, ImageWrap::Mirror);
  EXPECT_FALSE(map.filtered);
  EXPECT_EQ(scene.images->info(map.image).asked, ImageEncoding::Linear);
  EXPECT_EQ(map.scale, Vec2(2, 3));
  EXPECT_EQ(map.offset, Vec2(0.5, 0.25));
  EXPECT_EQ(test::sceneErrorsOf("image \"missing.png\"\n"),
            "t.sc:1:7: error: image: cannot read 'missing.png': no such file");
  EXPECT_EQ(test::sceneErrorsOf("image\n"),
            "t.sc:1:1: error: image: expected PATH but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("uv 1 1 0 0\n"),
            "t.sc:1:1: error: uv: the current surface has no image (give 'image' first)");
  EXPECT_EQ(test::sceneErrorsOf("uv 0 1 0 0\n"), "t.sc:1:4: error: uv: SU must not be 0");
  // A file that is no image is named with its path and why.
  test::writeFile(small.dir.path() / "junk.png", "this is not a PNG");
  const std::string junk = test::sceneErrorsOf("image junk.png\n", name);
  EXPECT_EQ(junk.rfind(name + ":1:7: error: image: cannot read '" +
                           (small.dir.path() / "junk.png").string() + "': ",
                       0),
            0u)
      << junk;
}

TEST(ImageTexture, ConvertRoundTrip) {
  SmallImage small;
  const std::string text = "resolution 24 16\neye 0 0 6\nlookat 0 0 0\nlight 2 3 6  40 40 40\n" +
                           floorAt("small.png", 0.25) +
                           "surface 1 1 1  0.8 0.2 0  20 1\nimage small.png clamp srgb\n"
                           "sphere 0 0 1 1\n";
  const Scene scene = parseScene(text, (small.dir.path() / "r.sc").string());
  std::ostringstream written;
  writeScene(written, scene);
  // Written with the absolute path: read back from anywhere.
  const Scene again = parseScene(written.str(), "elsewhere/r2.sc");
  ASSERT_EQ(again.materials.size(), scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const ImageMap& a = scene.materials[i].image;
    const ImageMap& b = again.materials[i].image;
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.offset, b.offset);
    EXPECT_EQ(a.wrap, b.wrap);
    EXPECT_EQ(scene.images->info(a.image).path, again.images->info(b.image).path);
    EXPECT_EQ(scene.images->info(a.image).asked, again.images->info(b.image).asked);
  }
}

// Bounds over materials (the bailout's) take an image at its peak.
TEST(ImageTexture, CeilingUsesThePeak) {
  Material m;
  m.color = Color(0.5, 0.5, 0.5);
  m.image.image = 0;
  m.image.peak = Color(2.0, 1.0, 0.25);
  expectVecNear(coefficientCeiling(m).color, {1.0, 0.5, 0.125}, 0.0);
  expectVecNear(coefficientFloor(m).color, {0.0, 0.0, 0.0}, 0.0);
}

} // namespace
} // namespace prism

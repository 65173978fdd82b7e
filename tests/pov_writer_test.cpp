// `prism convert SCENE OUT.pov`: the POV-Ray 3.7 text written for small
// scenes, checked against values worked out by hand from Prism's model and
// POV-Ray's (docs/vs-povray.md). Only the text is checked: POV-Ray itself is
// a benchmark peer (bench/vs-povray), never needed by the tests.
#include "core/io/pov_mapping.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace prism {
namespace {

// Every corner of the box the size is taken from is named: the eye (0 0 5)
// and the light (3 4 -7) span 3 x 4 x 12, a diagonal of 13, and every
// primitive lies inside.
constexpr const char* kScene = R"(
resolution 40 20
eye 0 0 5
lookat 0 0 0
up 0 1 0
fov 90
background 0.1 0.2 0.3
ambient 0.05 0.06 0.07
light 3 4 -7  1 2 4
surface 0.8 0.6 0.4  0.6 0.3 0.5  20 1.5
sphere 1.5 2 0 0.5
surface 0.9 0.9 0.9  1 0 0  1 1
polygon 6  0 0 0  2 0 0  2 1 0  1 1 0  1 2 0  0 2 0
cone 1 1 -1 0.5  1 1 1 0
triangle 0 0 1  1 0 1  0 1 1
ptriangle 0 0 2 0 0 1  1 0 2 0 0 1  0 1 2 0.6 0 0.8
push
  translate 2 2 0
  scale 0.5 1 0.25
  sphere 0 0 0 1
  cone 0 0 0 1  0 1 0 1
pop
)";

std::string povText(const std::string& sc) {
  std::ostringstream out;
  writePov(out, parseScene(sc, "test.sc"), "a test");
  return out.str();
}

// The first line containing `key`.
std::string lineWith(const std::string& text, const std::string& key) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    if (line.find(key) != std::string::npos) return line;
  ADD_FAILURE() << "no line with '" << key << "' in\n" << text;
  return "";
}

// The numbers of a line, in order ("Prism_M1" counts as 1). Materials are
// numbered in the order the scene first uses them.
std::vector<double> numbersIn(const std::string& line) {
  static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  std::vector<double> found;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), number);
       it != std::sregex_iterator(); ++it)
    found.push_back(std::strtod(it->str().c_str(), nullptr));
  return found;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

void expectNumbers(const std::string& line, const std::vector<double>& expected) {
  const std::vector<double> found = numbersIn(line);
  ASSERT_EQ(found.size(), expected.size()) << line;
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(found[i], expected[i], 1e-12 * (1 + std::abs(expected[i])))
        << "number " << i << " of: " << line;
}

TEST(PovWriter, GlobalsForTheDepthTheAmbientAndTheBackground) {
  const std::string pov = povText(kScene);
  EXPECT_EQ(pov.rfind("// a test\n#version 3.7;\n", 0), 0u) << pov;
  EXPECT_NE(pov.find("#ifndef (Prism_Depth) #declare Prism_Depth = 5; #end"), std::string::npos);
  EXPECT_NE(pov.find("global_settings { assumed_gamma 1.0 max_trace_level Prism_Depth "
                     "adc_bailout 0 ambient_light rgb <0.05, 0.06, 0.07> }"),
            std::string::npos);
  EXPECT_NE(pov.find("background { rgb <0.1, 0.2, 0.3> }"), std::string::npos);
}

// eye (0 0 5) looking at the origin with y up: forward -z, right +x, up +y;
// fov 90 makes the image plane 2 tan(45 deg) = 2 high at distance 1, and as
// wide as POV-Ray's own aspect ratio makes it.
TEST(PovWriter, CameraVectorsSpanPrismsImagePlane) {
  const std::string pov = povText(kScene);
  expectNumbers(lineWith(pov, "location"), {0, 0, 5});
  expectNumbers(lineWith(pov, "direction"), {0, 0, -1});
  const std::string right = lineWith(pov, "right");
  EXPECT_NE(right.find("* image_width / image_height)"), std::string::npos) << right;
  expectNumbers(right, {1, 0, 0, 2});
  expectNumbers(lineWith(pov, "  up "), {0, 1, 0, 2});
  EXPECT_EQ(count(pov, "look_at"), 0); // would rebuild the vectors left-handed
}

// POV-Ray fades a light by 2 / (1 + (d / f)^2); with the colour scaled by
// 1 / (2 f^2) that is 1 / (d^2 + f^2). f is a millionth of the scene's size.
TEST(PovWriter, LightColourScaledSoTheFadeIsOneOverRSquared) {
  const std::vector<double> n = numbersIn(lineWith(povText(kScene), "light_source"));
  ASSERT_EQ(n.size(), 8u); // position, colour, fade distance, fade power
  EXPECT_EQ(std::vector<double>(n.begin(), n.begin() + 3), (std::vector<double>{3, 4, -7}));
  EXPECT_NEAR(n[6], 13e-6, 1e-9 * 13e-6); // the bounds may be padded by round-off
  EXPECT_EQ(n[7], 2);
  const double scale = 0.5 / (n[6] * n[6]);
  EXPECT_NEAR(n[3], 1 * scale, 1e-12 * scale);
  EXPECT_NEAR(n[4], 2 * scale, 2e-12 * scale);
  EXPECT_NEAR(n[5], 4 * scale, 4e-12 * scale);
  // What POV-Ray then computes 2 units from the light, against Prism's I/r^2.
  const double d = 2;
  EXPECT_NEAR(n[3] * 2 / (1 + std::pow(d / n[6], n[7])), 1 / (d * d), 1e-10);
}

// surface 0.8 0.6 0.4  0.6 0.3 0.5  20 1.5: POV-Ray dims the surface's own
// light by the opacity 1 - 0.5, so ambient and diffuse are 0.6 / 0.5; the
// highlight is Blinn's with roughness 1/20; the mirror weight is ksr; the
// refracted ray's weight is the untinted transmit.
TEST(PovWriter, FinishOfAKnownMaterial) {
  const std::string pov = povText(kScene);
  EXPECT_NE(pov.find("#declare Prism_M0 = material {\n"
                     "  texture {\n"
                     "    pigment { rgbt <0.8, 0.6, 0.4, 0.5> }\n"
                     "    finish { ambient 1.2 diffuse 1.2 specular 0.3 roughness 0.05 "
                     "reflection { 0.3 } }\n"
                     "  }\n"
                     "  interior { ior 1.5 }\n"
                     "}\n"),
            std::string::npos)
      << pov;
  // An opaque one has no interior and no highlight exponent.
  EXPECT_NE(pov.find("#declare Prism_M1 = material {\n"
                     "  texture {\n"
                     "    pigment { rgbt <0.9, 0.9, 0.9, 0> }\n"
                     "    finish { ambient 1 diffuse 1 specular 0 reflection { 0 } }\n"
                     "  }\n"
                     "}\n"),
            std::string::npos)
      << pov;
}

TEST(PovWriter, MaterialMappingAtTheEdges) {
  Material m;
  m.kdr = 0.5;
  m.ksr = 0.2;
  m.e = 0; // a constant highlight: an exponent of (nearly) 0
  PovMaterial p = povMaterialOf(m);
  EXPECT_EQ(p.roughness, 1e300);
  EXPECT_TRUE(p.exact);
  m.kst = 1; // nothing left to divide the diffuse light by
  p = povMaterialOf(m);
  EXPECT_FALSE(p.exact);
  EXPECT_EQ(p.diffuse, 0.5);
  m.kdr = 0; // a clear glass: nothing is lost
  EXPECT_TRUE(povMaterialOf(m).exact);
}

// A concave L-shaped hexagon: POV-Ray's polygon takes it whole (no
// triangulation), closed by repeating the first vertex.
TEST(PovWriter, ConcavePolygonClosedByItsFirstVertex) {
  expectNumbers(lineWith(povText(kScene), "polygon {"),
                {7, 0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0, 0, 0, 0, 1});
}

TEST(PovWriter, OpenConeBetweenItsCircles) {
  const std::string cone = lineWith(povText(kScene), "cone {");
  EXPECT_NE(cone.find(" open material { Prism_M1 }"), std::string::npos) << cone;
  expectNumbers(cone, {1, 1, -1, 0.5, 1, 1, 1, 0, 1});
}

// The ellipsoid and the elliptic cone: their own frames under a matrix whose
// four triples are the map's columns and offset.
TEST(PovWriter, TransformedShapesCarryTheirMatrix) {
  const std::string pov = povText(kScene);
  expectNumbers(lineWith(pov, "sphere { <0, 0, 0>, 1 matrix"),
                {0, 0, 0, 1, 0.5, 0, 0, 0, 1, 0, 0, 0, 0.25, 2, 2, 0, 1});
  const std::string cone = lineWith(pov, "open matrix");
  const std::vector<double> n = numbersIn(cone);
  ASSERT_EQ(n.size(), 21u) << cone; // 2 circles, 12 matrix entries, the material
  // The cone's axis (its frame's z) is the world's y, stretched by 1.
  EXPECT_NEAR(n[14], 0, 1e-12);
  EXPECT_NEAR(n[15], 1, 1e-12);
  EXPECT_NEAR(n[16], 0, 1e-12);
  EXPECT_NEAR(n[17], 2, 1e-12); // the base centre
  EXPECT_NEAR(n[18], 2, 1e-12);
}

TEST(PovWriter, EveryShapeKindIsWritten) {
  const Scene scene = parseScene(kScene, "test.sc");
  ASSERT_EQ(scene.shapes<Sphere>().size(), 1u);
  ASSERT_EQ(scene.shapes<Ellipsoid>().size(), 1u);
  ASSERT_EQ(scene.shapes<Polygon>().size(), 1u);
  ASSERT_EQ(scene.shapes<Cone>().size(), 2u);
  ASSERT_EQ(scene.shapes<Triangle>().size(), 2u);
  const std::string pov = povText(kScene);
  EXPECT_EQ(count(pov, "\nsphere {"), 2);
  EXPECT_EQ(count(pov, "\npolygon {"), 1);
  EXPECT_EQ(count(pov, "\ncone {"), 2);
  // The two triangles share a material: one mesh holds both.
  EXPECT_EQ(count(pov, "\nmesh {"), 1);
  EXPECT_EQ(count(pov, "\n  triangle {"), 1);
  EXPECT_EQ(count(pov, "\n  smooth_triangle {"), 1);
  expectNumbers(lineWith(pov, "smooth_triangle"),
                {0, 0, 2, 0, 0, 1, 1, 0, 2, 0, 0, 1, 0, 1, 2, 0.6, 0, 0.8});
  // Every object has a material, and every material is declared.
  EXPECT_EQ(count(pov, "material { Prism_M"), 2 + 1 + 2 + 1);
  EXPECT_EQ(count(pov, "#declare Prism_M"), int(scene.materials.size()));
}

// The solids as POV-Ray's namesakes: a box by its corners, a cylinder, a
// cone without `open`, a disc by centre, normal and radius; a turned box in
// its own frame under its matrix.
TEST(PovWriter, SolidsAsTheirNamesakes) {
  const std::string pov = povText("box 0 0 0  1 2 3\n"
                                  "cylinder 0 0 0  0 0 2  1\n"
                                  "capped_cone 1 1 1 2  1 1 3 0.5\n"
                                  "disc 0 5 0  0 2 0  2\n"
                                  "push rotate 0 0 1 30 box 0 0 0 1 1 1 pop\n");
  expectNumbers(lineWith(pov, "box { <0, 0, 0>, <1, 2, 3> material"), {0, 0, 0, 1, 2, 3, 0});
  expectNumbers(lineWith(pov, "cylinder {"), {0, 0, 0, 0, 0, 2, 1, 0});
  const std::string cone = lineWith(pov, "cone {");
  EXPECT_EQ(cone.find("open"), std::string::npos) << cone;
  expectNumbers(cone, {1, 1, 1, 2, 1, 1, 3, 0.5, 0});
  expectNumbers(lineWith(pov, "disc {"), {0, 5, 0, 0, 1, 0, 2, 0});
  const std::vector<double> turned = numbersIn(lineWith(pov, "box { <0, 0, 0>, <1, 1, 1> matrix"));
  ASSERT_EQ(turned.size(), 19u); // 2 corners, 12 matrix entries, the material
  // The first column is the frame's x turned 30 degrees about z.
  EXPECT_NEAR(turned[6], std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(turned[7], 0.5, 1e-15);
  EXPECT_EQ(count(pov, "material { Prism_M"), 5);
}

// Numbers are written in their shortest exact form, so they read back exactly.
TEST(PovWriter, NumbersRoundTrip) {
  const std::string pov = povText("sphere 0.1 -1e-300 123456789.123 0.3333333333333333\n");
  expectNumbers(lineWith(pov, "sphere {"), {0.1, -1e-300, 123456789.123, 0.3333333333333333, 0});
  EXPECT_NE(pov.find("0.3333333333333333"), std::string::npos);
}

} // namespace
} // namespace prism

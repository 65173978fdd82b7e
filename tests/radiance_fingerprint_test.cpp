// Every shipped scene and every generated scene, under every acceleration kind
// and on one and two threads, against a committed fingerprint of its float
// radiance, its supersampling mask, avgmax and its ray counts.
//
// Why fingerprints and not pictures: restructuring the renderer (new shape
// dispatch, surface records, one pass schedule) must change no bit of any
// picture and no count. A 64-bit hash of every float's bits holds that exactly,
// in a file small enough to review. The build uses no fused multiply-add
// (baseline x86-64) and no fast-math, so the bits are the same in the Release
// and the sanitizer builds. The physics behind the pictures is checked
// independently against hand-computed values in physics_test and
// image_formation_test; these tests only say "nothing changed".
//
// After an intended change of pictures, regenerate with
//   PRISM_UPDATE_REFERENCES=1 ctest -R RadianceFingerprint
// (which rewrites tests/reference/radiance-fingerprints.txt) and say why in the
// commit.
#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/renderer.h"
#include "tools/scene_generators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace prism {
namespace {

const std::string kReferenceFile =
    std::string(PRISM_SOURCE_DIR) + "/tests/reference/radiance-fingerprints.txt";

// FNV-1a over 64 bits: simple, stable across platforms and versions, and
// enough to tell "identical" from "changed" (not a defence against attackers).
class Fingerprint {
public:
  void add(std::uint64_t value) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (value >> (8 * i)) & 0xffu;
      hash_ *= 1099511628211ull;
    }
  }
  void add(float value) { add(std::uint64_t(std::bit_cast<std::uint32_t>(value))); }
  void add(double value) { add(std::bit_cast<std::uint64_t>(value)); }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

std::uint64_t fingerprint(const RenderResult& r) {
  Fingerprint f;
  f.add(std::uint64_t(r.film.width));
  f.add(std::uint64_t(r.film.height));
  for (const Rgb& c : r.film.radiance) {
    f.add(c.r);
    f.add(c.g);
    f.add(c.b);
  }
  for (std::uint8_t s : r.film.supersampled)
    f.add(std::uint64_t(s));
  f.add(r.avgmax);
  f.add(r.counts.eyePrimary);
  f.add(r.counts.eyeAntialias);
  f.add(r.counts.shadow);
  f.add(r.counts.reflected);
  f.add(r.counts.transmitted);
  f.add(r.counts.tirEvents);
  f.add(std::uint64_t(r.supersampledPixels));
  return f.value();
}

struct Case {
  std::string name;
  std::function<Scene()> scene;
  int width, height;
};

// gtest names a failing case by this rather than by its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string shippedScene(const std::string& file) {
  return std::string(PRISM_SOURCE_DIR) + "/scenes/" + file;
}

// Small pictures (each render takes well under a second with a hierarchy) with a
// low threshold and jitter, so that pass 2 supersamples many pixels and every
// ray kind is traced; depth 8 so the glass scenes go deep.
std::vector<Case> cases() {
  return {
      {"table", [] { return loadScene(shippedScene("table.sc")); }, 64, 48},
      {"glass", [] { return loadScene(shippedScene("glass.sc")); }, 40, 30},
      {"chex", [] { return loadScene(shippedScene("chex.sc")); }, 40, 30},
      {"tree", [] { return loadScene(shippedScene("tree.sc")); }, 48, 36},
      {"forest", [] { return loadScene(shippedScene("forest.sc")); }, 40, 30},
      {"sphereflake", [] { return makeSphereflake(820); }, 48, 36},
      {"soup", [] { return makePolygonSoup(1000, 7); }, 32, 24},
      {"scaled-soup", [] { return makeScaledPolygonSoup(1000, 7); }, 32, 24},
  };
}

// Without a hierarchy every ray tests every primitive. Above this many the
// brute-force renders cost more than all the other cases together (chex's
// 7,531 primitives took 80 s under the sanitizers); the smaller scenes still
// hold "the hierarchies change nothing" against brute force, and
// accel_test compares them ray by ray on large random scenes.
constexpr std::size_t kMaxPrimitivesWithoutAccel = 2000;

std::string key(const std::string& scene, AccelKind accel, int threads) {
  return scene + " " + accelKindName(accel) + " " + std::to_string(threads);
}

std::map<std::string, std::string> readReferences() {
  std::map<std::string, std::string> refs;
  std::ifstream in(kReferenceFile);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto last = line.rfind(' ');
    if (last != std::string::npos) refs[line.substr(0, last)] = line.substr(last + 1);
  }
  return refs;
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << v;
  return s.str();
}

bool updating() {
  const char* u = std::getenv("PRISM_UPDATE_REFERENCES");
  return u && *u == '1';
}

class RadianceFingerprint : public ::testing::TestWithParam<Case> {};

TEST_P(RadianceFingerprint, SameUnderEveryAccelAndThreadCount) {
  const Case& c = GetParam();
  const auto refs = readReferences();
  std::map<std::string, std::string> got;
  const Scene scene = c.scene();
  for (AccelKind accel : {AccelKind::Bvh, AccelKind::Groups, AccelKind::None}) {
    if (accel == AccelKind::None && scene.primitiveCount() > kMaxPrimitivesWithoutAccel) continue;
    const auto built = makeAccel(scene, accel);
    for (int threads : {1, 2}) {
      RenderSettings s;
      s.width = c.width;
      s.height = c.height;
      s.maxDepth = 8;
      s.thresh = 0.02;
      s.jitter = true;
      s.threads = threads;
      s.tileSize = 16; // several tiles even at these sizes, so threads share work
      const RenderResult r = render(scene, *built, s);
      const std::string k = key(c.name, accel, threads);
      got[k] = hex(fingerprint(r));
      EXPECT_GT(r.supersampledPixels, 0) << k << ": pass 2 must run for the test to hold it";
    }
  }
  // One picture whatever the hierarchy and the thread count.
  for (const auto& [k, v] : got)
    EXPECT_EQ(v, got.begin()->second) << k << " differs from " << got.begin()->first;
  if (updating()) {
    // Each case rewrites its own lines, keeping the others' (ctest runs the
    // cases as separate processes, one after another when updating).
    auto all = refs;
    for (auto it = all.begin(); it != all.end();)
      it = it->first.starts_with(c.name + " ") ? all.erase(it) : std::next(it);
    all.insert(got.begin(), got.end());
    std::ofstream out(kReferenceFile);
    out << "# scene accel threads fnv1a64(radiance, mask, avgmax, counts): see "
           "tests/radiance_fingerprint_test.cpp\n";
    for (const auto& [k, v] : all)
      out << k << " " << v << "\n";
    GTEST_SKIP() << "wrote " << c.name << "'s lines of " << kReferenceFile;
  }
  std::size_t referenced = 0;
  for (const auto& [k, v] : refs)
    referenced += k.starts_with(c.name + " ");
  EXPECT_EQ(referenced, got.size()) << "lines for " << c.name << " in " << kReferenceFile;
  for (const auto& [k, v] : got) {
    const auto it = refs.find(k);
    ASSERT_NE(it, refs.end()) << k << " has no reference in " << kReferenceFile;
    EXPECT_EQ(v, it->second) << k << ": the picture or its counts changed";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, RadianceFingerprint, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           std::string n = test.param.name;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

} // namespace
} // namespace prism

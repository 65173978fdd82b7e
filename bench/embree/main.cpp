// prism_vs_embree SCENE: Prism's default hierarchy against Intel Embree 3 on
// the same rays, one ray at a time on one thread (docs/vs-embree.md).
#include "bench/embree/comparison.h"
#include "bench/embree/isa.h"
#include "core/accel/bvh.h"

#include "core/io/scene_loader.h"
#include "core/system/system_info.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

namespace prism::bench {

namespace {

struct Options {
  std::string scene;
  std::vector<int> size; // W H; empty: the scene's resolution
  std::size_t rays = 0;
  std::uint64_t seed = 1;
  RTCBuildQuality quality = RTC_BUILD_QUALITY_HIGH;
  SphereMode spheres = SphereMode::User;
  std::string isa;
  TimingOptions timing;
  bool row = false;
};

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}
std::string mrays(double raysPerSecond) { return fixed(raysPerSecond * 1e-6, 2); }

// Whether Prism's one-ray walk tests its nodes in AVX (core/accel/bvh.h).
bool usesAvx(const Accel& accel) {
  const auto* bvh = dynamic_cast<const Bvh*>(&accel);
  return bvh != nullptr && bvh->usesAvx();
}

const char* qualityName(RTCBuildQuality q) {
  switch (q) {
  case RTC_BUILD_QUALITY_LOW: return "low";
  case RTC_BUILD_QUALITY_MEDIUM: return "medium";
  case RTC_BUILD_QUALITY_HIGH: return "high";
  default: return "?";
  }
}

// "tree.sc: 105476 primitives (105476 polygons)"
std::string contentsText(const Scene& scene) {
  return std::to_string(scene.primitiveCount()) + " primitives (" + scene.kindCounts() + ")";
}

void printResults(const std::vector<SetResult>& results) {
  std::cout << "\n| rays | count | query | Prism Mrays/s (best / median) | Embree Mrays/s (best / "
               "median) | Prism / Embree (median) | agreement |\n"
               "|---|---|---|---|---|---|---|\n";
  for (const SetResult& r : results) {
    std::cout << "| " << r.name << " | " << r.rays << " | "
              << (r.kind == QueryKind::Closest ? "closest" : "any") << " | "
              << mrays(r.rates.prism.best) << " / " << mrays(r.rates.prism.median) << " | "
              << mrays(r.rates.embree.best) << " / " << mrays(r.rates.embree.median) << " | "
              << fixed(r.ratio(), 2) << " | " << fixed(100.0 * r.agreement.rate(), 4) << "% |\n";
  }
  for (const SetResult& r : results) {
    const Agreement& a = r.agreement;
    if (a.samePlaceOtherPrimitive > 0)
      std::cout << "\n"
                << r.name << ": " << a.samePlaceOtherPrimitive
                << " rays agree on t but hit different primitives (coincident surfaces or a "
                   "shared edge)\n";
    if (a.disagreements() == 0) continue;
    std::cout << "\n"
              << r.name << ": " << a.disagreements() << " of " << a.rays
              << " disagree: Prism alone hits " << a.onlyPrismHits << ", Embree alone "
              << a.onlyEmbreeHits << ", t differs by more than 1e-6 " << a.differentT;
    if (r.kind == QueryKind::Closest)
      std::cout << " (" << a.differentTSamePrimitive
                << " of them on the same primitive: float round-off)";
    std::cout << (a.examples.empty() ? "" : "; the first on different primitives:") << "\n";
    for (const std::string& e : a.examples)
      std::cout << "  " << e << "\n";
  }
}

// One line for bench/embree/run.sh's table: scene, primitives, then rate
// Prism, rate Embree and their ratio for each ray set (medians).
void printRow(const std::string& name, const Scene& scene, const std::vector<SetResult>& results) {
  std::cout << "row: | " << name << " | " << scene.primitiveCount();
  for (const SetResult& r : results)
    std::cout << " | " << mrays(r.rates.prism.median) << " | " << mrays(r.rates.embree.median)
              << " | " << fixed(r.ratio(), 2);
  std::cout << " |\n";
}

int run(const Options& o) {
  Scene scene;
  try {
    std::vector<Diagnostic> warnings;
    scene = loadAnyScene(o.scene, &warnings);
  } catch (const SceneError& error) {
    for (const Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    return 1;
  }
  const std::string name = std::filesystem::path(o.scene).filename().string();

  const auto start = std::chrono::steady_clock::now();
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  const double prismBuild =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  EmbreeOptions eo;
  eo.quality = o.quality;
  eo.spheres = o.spheres;
  if (!o.isa.empty()) eo.deviceConfig = "isa=" + o.isa;
  const EmbreeScene embree(scene, eo);
  const IsaReport isa = embreeIsa(embree.device(), eo.deviceConfig);
  const EmbreeContents& c = embree.contents();

  RaySetOptions ro;
  ro.width = o.size.empty() ? scene.width : o.size[0];
  ro.height = o.size.empty() ? scene.height : o.size[1];
  ro.maxEyeRays = o.rays;
  ro.seed = o.seed;
  const RaySets sets = makeRaySets(scene, *accel, ro);

  std::cout << "prism_vs_embree " << name << ": " << contentsText(scene) << "\n"
            << "machine: " << machineDescription() << "; CPU extensions: " << isa.cpuFlags << "\n"
            << "Embree " << rtcGetDeviceProperty(embree.device(), RTC_DEVICE_PROPERTY_VERSION_MAJOR)
            << "." << rtcGetDeviceProperty(embree.device(), RTC_DEVICE_PROPERTY_VERSION_MINOR)
            << "." << rtcGetDeviceProperty(embree.device(), RTC_DEVICE_PROPERTY_VERSION_PATCH)
            << ": ISA " << isa.selected << " (compiled: " << isa.compiled
            << "; native packets: " << isa.nativePackets << "), build quality "
            << qualityName(o.quality) << ", spheres "
            << (o.spheres == SphereMode::User ? "as user geometry" : "native") << "\n"
            << "Embree scene: " << c.meshTriangles << " mesh triangles, " << c.polygonTriangles
            << " triangles of polygons, " << c.nativeSpheres << " spheres (native), "
            << c.userPrimitives << " user primitives (Prism's tests); built in "
            << fixed(c.buildSeconds, 3) << " s on 1 thread; Prism's BVH in " << fixed(prismBuild, 3)
            << " s, one ray's node test in " << (usesAvx(*accel) ? "AVX" : "SSE") << "\n"
            << "rays: eye rays through the pixel centres of " << ro.width << " x " << ro.height
            << (o.rays > 0 ? " (a sample of " + std::to_string(sets.eye.size()) + ", seed " +
                                 std::to_string(o.seed) + ")"
                           : std::string())
            << ", their mirror rays and shadow rays from Prism's hits; one thread, thread CPU "
               "time, "
            << o.timing.rounds << " alternating turns each of at least " << o.timing.minSeconds
            << " s\n";
  std::cout.flush();

  std::vector<SetResult> results;
  results.push_back(
      compareSet("eye", QueryKind::Closest, scene, *accel, embree, sets.eye, o.timing));
  results.push_back(
      compareSet("secondary", QueryKind::Closest, scene, *accel, embree, sets.secondary, o.timing));
  results.push_back(
      compareSet("shadow", QueryKind::Any, scene, *accel, embree, sets.shadow, o.timing));
  printResults(results);
  if (o.row) printRow(name, scene, results);
  return 0;
}

} // namespace

} // namespace prism::bench

int main(int argc, char** argv) {
  using namespace prism::bench;
  Options o;
  CLI::App app{"Prism's BVH against Intel Embree 3 on the same rays, one ray at a time on one "
               "thread: eye rays, their mirror rays (closest hit) and shadow rays (any hit). "
               "See docs/vs-embree.md."};
  app.add_option("scene", o.scene, "Scene file (.sc, .nff, .obj)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--size", o.size, "Eye rays' image size W H (default: the scene's resolution)")
      ->expected(2)
      ->check(CLI::Range(1, 16384));
  app.add_option("--rays", o.rays,
                 "At most this many eye rays: a random sample of the pixels (0: all)")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "Seed of the --rays sample")->capture_default_str();
  const std::map<std::string, RTCBuildQuality> qualities{{"low", RTC_BUILD_QUALITY_LOW},
                                                         {"medium", RTC_BUILD_QUALITY_MEDIUM},
                                                         {"high", RTC_BUILD_QUALITY_HIGH}};
  app.add_option("--quality", o.quality, "Embree's build quality [high]")
      ->transform(CLI::CheckedTransformer(qualities, CLI::ignore_case));
  const std::map<std::string, SphereMode> sphereModes{{"native", SphereMode::Native},
                                                      {"user", SphereMode::User}};
  app.add_option("--spheres", o.spheres,
                 "Spheres in Embree: its own sphere primitive, or user geometry calling "
                 "Prism's test [user]")
      ->transform(CLI::CheckedTransformer(sphereModes, CLI::ignore_case));
  app.add_option("--isa", o.isa,
                 "Force Embree's ISA (its device configuration's isa=: sse2, sse4.2, avx, avx2, "
                 "avx512); default: the host's best");
  app.add_option("--turns", o.timing.rounds, "Timed turns per engine and ray set")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--min-seconds", o.timing.minSeconds, "Shortest turn, seconds")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 600.0));
  app.add_flag("--row", o.row, "Also print a \"row: \" line for bench/embree/run.sh's table");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& error) {
    std::cerr << "prism_vs_embree: error: " << error.what() << "\n";
    return 1;
  }
}

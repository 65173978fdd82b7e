#include "fuzz/fuzz_check.h"

#include "core/accel/accel.h"
#include "core/io/image_io.h"
#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace prism::fuzz {

namespace fs = std::filesystem;

namespace {

// A 4x4 image at depth 4: enough for a shadow ray per light at every hit and
// for a reflected ray of a refracted ray of a reflected one, cheap at any
// scene size the fuzzer can write in a few KB. One more ray goes through the
// image's centre, which no pixel centre of an even-sized image does: straight
// along the view axis, it meets a surface centred there at exactly normal
// incidence (the 1x1 render), an edge case of refraction.
constexpr int kSize = 4;
constexpr int kPixels = kSize * kSize;
constexpr int kRays = kPixels + 1;
constexpr int kMaxDepth = 4;

// Escaped so that a reproducer survives being copied from a CI log: printable
// ASCII as is, everything else as \xNN.
std::string escaped(std::string_view input) {
  constexpr std::size_t kMaxShown = 4096;
  std::string out;
  for (std::size_t i = 0; i < input.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(input[i]);
    if (c == '\n') {
      out += "\\n\n";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  if (input.size() > kMaxShown) out += "\n... (" + std::to_string(input.size()) + " bytes)";
  return out;
}

std::string text(const Color& c) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", c.r, c.g, c.b);
  return buffer;
}

bool hasNan(const Color& c) { return std::isnan(c.r) || std::isnan(c.g) || std::isnan(c.b); }

struct Picture {
  std::array<Color, kRays> single;  // Tracer::trace, one eye ray at a time
  std::array<Color, kRays> bundled; // Tracer::traceBundle, all of them at once
  RayCounts singleCounts, bundledCounts;
};

Picture picture(const Scene& scene, const Accel& accel, const char* name) {
  const Camera camera(scene.camera, kSize, kSize);
  std::array<Ray, kRays> rays;
  for (int i = 0; i < kPixels; ++i) {
    rays[std::size_t(i)] = camera.eyeRay(i % kSize + 0.5, i / kSize + 0.5);
  }
  rays[kPixels] = camera.eyeRay(0.5 * kSize, 0.5 * kSize);
  Picture p;
  Tracer tracer(scene, accel, kMaxDepth);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    p.single[i] = tracer.trace(rays[i], 1, p.singleCounts);
  }
  Tracer(scene, accel, kMaxDepth).traceBundle(rays, p.bundled, p.bundledCounts);

  // The --pixel ray tree of one pixel: recording must not change the answer.
  RayTreeNode root;
  RayCounts ignored;
  const std::size_t probe = kPixels / 2 + kSize / 2;
  const Color recorded = Tracer(scene, accel, kMaxDepth).trace(rays[probe], 1, ignored, &root);
  std::ostringstream tree;
  printRayTree(tree, root, scene);

  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::string where =
        std::string(name) + (i < kPixels ? ", pixel " + std::to_string(i) : ", image centre");
    if (hasNan(p.single[i])) fail("NaN colour (" + where + "): " + text(p.single[i]));
    if (hasNan(p.bundled[i])) fail("NaN colour (" + where + ", bundled): " + text(p.bundled[i]));
    if (p.single[i] != p.bundled[i]) {
      fail("traceBundle differs from trace (" + where + "): " + text(p.bundled[i]) + " vs " +
           text(p.single[i]));
    }
  }
  if (!(recorded == p.single[probe]) || !(root.radiance == recorded)) {
    fail(std::string("the ray tree changes the colour (") + name + "): " + text(recorded) + " vs " +
         text(p.single[probe]));
  }
  if (!(p.singleCounts == p.bundledCounts)) {
    fail(std::string("traceBundle counts different rays than trace (") + name + ")");
  }
  return p;
}

void removeSandbox() {
  std::error_code ignored;
  fs::remove_all(sandbox(), ignored);
}

// Parts a fuzzed .sc file may include by name: a valid one, cycles, errors and
// a directory; and an image.
void stageScParts(const fs::path& dir) {
  const std::pair<const char*, const char*> kParts[] = {
      {"part.sc", "surface 1 0.5 0 0.6 0.4 0 20 1\npush\n  translate 0 1 0\n"
                  "  sphere 0 0 0 0.5\npop\ntriangle 0 0 0 1 0 0 0 1 0\n"},
      {"glass.sc", "surface 1 1 1 0.1 0.1 0.9 50 1.5\nsphere 0 0 0 1\n"},
      {"self.sc", "include self.sc\n"},
      {"ab.sc", "include ba.sc\n"},
      {"ba.sc", "include ab.sc\n"},
      {"broken.sc", "push\nsphere 0 0 0 -1\npop\npop\npush\n"},
  };
  for (const auto& [name, body] : kParts) {
    const std::string_view bytes(body);
    writeFile(dir / name, &bytes);
  }
  // An image `image` may name: 2 x 2 texels, red, green / blue, grey.
  writeImage8(dir / "tex.png", 2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 128, 128, 128});
  fs::create_directory(dir / "folder");
}

// A process that crashed (or was killed) never removed its sandbox, and
// -minimize_crash crashes thousands of times. Sandboxes are named for their
// process, so each new one removes those whose process no longer exists.
void removeStaleSandboxes(const fs::path& parent) {
  const std::string prefix = "prism-fuzz-";
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix)) continue;
    const std::string pid =
        name.substr(prefix.size(), name.find('-', prefix.size()) - prefix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (fs::exists("/proc/" + pid, ec)) continue;
    fs::remove_all(entry.path(), ec);
  }
}

} // namespace

void fail(const std::string& what, std::string_view input) {
  std::fprintf(stderr, "\n==prism-fuzz== %s\n", what.c_str());
  if (!input.empty()) {
    std::fprintf(stderr, "==prism-fuzz== input (%zu bytes):\n%s\n", input.size(),
                 escaped(input).c_str());
  }
  std::fflush(stderr);
  std::abort();
}

void renderChecks(const Scene& scene) {
  const std::unique_ptr<Accel> bvh = makeAccel(scene, AccelKind::Bvh);
  const std::unique_ptr<Accel> groups = makeAccel(scene, AccelKind::Groups);
  const Picture a = picture(scene, *bvh, "bvh");
  const Picture b = picture(scene, *groups, "groups");
  for (std::size_t i = 0; i < a.single.size(); ++i) {
    if (a.single[i] != b.single[i]) {
      fail("the BVH and the groups hierarchy give different colours for eye ray " +
           std::to_string(i) + ": " + text(a.single[i]) + " vs " + text(b.single[i]));
    }
  }
  if (!(a.singleCounts == b.singleCounts)) {
    fail("the BVH and the groups hierarchy trace different numbers of rays");
  }
}

const fs::path& sandbox() {
  static const fs::path dir = [] {
    const fs::path parent = fs::temp_directory_path();
    removeStaleSandboxes(parent);
    const std::string name = "prism-fuzz-" + std::to_string(::getpid()) + "-XXXXXX";
    std::string pattern = (parent / name).string();
    if (::mkdtemp(pattern.data()) == nullptr) fail("cannot create a directory in TMPDIR");
    stageScParts(pattern);
    return fs::path(pattern);
  }();
  static const bool registered = std::atexit(removeSandbox) == 0;
  (void)registered;
  return dir;
}

void writeFile(const fs::path& path, const std::string_view* bytes) {
  if (bytes == nullptr) {
    std::error_code ignored;
    fs::remove(path, ignored);
    return;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes->data(), std::streamsize(bytes->size()));
  if (!out.flush()) fail("cannot write " + path.string());
}

bool includeLeavesSandbox(std::string_view scText) {
  return (scText.find("include") != std::string_view::npos ||
          scText.find("image") != std::string_view::npos) &&
         scText.find('/') != std::string_view::npos;
}

// Looks up to the next '\n', where Prism's scan ends a line: tinyobjloader's
// lines, which also end at '\r', are never longer. An MTL `map_Kd` names a
// file too (an image, read when a face uses its material).
bool mtllibLeavesSandbox(std::string_view text) {
  for (const std::string_view keyword : {"mtllib", "map_Kd"}) {
    for (std::size_t at = text.find(keyword); at != std::string_view::npos;
         at = text.find(keyword, at + 1)) {
      const std::size_t end = text.find('\n', at);
      const std::string_view rest = text.substr(at, end == std::string_view::npos ? end : end - at);
      if (rest.find('/') != std::string_view::npos) return true;
    }
  }
  return false;
}

fs::path stageObj(std::string_view text) {
  const std::size_t marker = text.find(kMtlMarker);
  const std::string_view obj = text.substr(0, marker);
  writeFile(sandbox() / "a.obj", &obj);
  if (marker == std::string_view::npos) {
    writeFile(sandbox() / "a.mtl", nullptr);
  } else {
    const std::string_view mtl = text.substr(marker + kMtlMarker.size());
    writeFile(sandbox() / "a.mtl", &mtl);
  }
  return sandbox() / "a.obj";
}

} // namespace prism::fuzz

// Every target works in the sandbox: made once, before the first input, so
// the time it takes is not charged to an input (libFuzzer calls this hook if
// it is defined; this file is linked into every target).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  prism::fuzz::sandbox();
  return 0;
}

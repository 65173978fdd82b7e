// spd_gen: writes benchmark scenes of the kinds of Eric Haines' Standard
// Procedural Databases (sphereflake, gears, fractal mountain, ...) in Prism's
// scene language, at a chosen size. See docs/benchmark-scenes.md.
//
//   spd_gen KIND SIZE OUT.sc   the scene of KIND with about SIZE primitives
//   spd_gen --list             the kinds and what their levels count
//
// Each kind grows by a level (a recursion depth, a grid size, a count); SIZE
// picks the level whose primitive count is nearest to it. The output is the
// same bytes on every run and platform (tools/spd/sc_writer.cpp).
#include "spd/spd_kinds.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using prism::spd::SpdKind;

int usage() {
  std::fprintf(stderr, "usage: spd_gen KIND SIZE OUT.sc\n"
                       "       spd_gen --list\n");
  return 2;
}

void list() {
  for (const SpdKind& kind : prism::spd::spdKinds()) {
    std::printf("%-8s %s\n", kind.name, kind.summary);
    std::printf("%-8s level: %s, %d to %d\n", "", kind.level, kind.minLevel, kind.maxLevel);
    std::printf("%-8s about 10^3, 10^4, 10^5:", "");
    for (long size : {1000L, 10000L, 100000L}) {
      const int level = prism::spd::levelForSize(kind, size);
      std::printf(" level %d = %ld,", level, kind.primitives(level));
    }
    std::printf("\n");
  }
}

} // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--list") {
    list();
    return 0;
  }
  if (argc != 4) return usage();
  const SpdKind* kind = prism::spd::findSpdKind(argv[1]);
  if (!kind) {
    std::fprintf(stderr, "spd_gen: unknown kind '%s' (spd_gen --list shows them)\n", argv[1]);
    return 2;
  }
  char* end = nullptr;
  errno = 0;
  const long size = std::strtol(argv[2], &end, 10);
  if (errno != 0 || *end != '\0' || end == argv[2] || size < 1 || size > 10000000) {
    std::fprintf(stderr, "spd_gen: SIZE must be an integer from 1 to 10000000, found '%s'\n",
                 argv[2]);
    return 2;
  }
  const prism::spd::SpdScene scene = prism::spd::makeSpdScene(*kind, size);
  if (scene.counts.total() != kind->primitives(scene.level)) { // the documented formula
    std::fprintf(stderr, "spd_gen: %s level %d wrote %ld primitives, its formula says %ld\n",
                 kind->name, scene.level, scene.counts.total(), kind->primitives(scene.level));
    return 1;
  }
  std::FILE* f = std::fopen(argv[3], "wb");
  if (!f) {
    std::perror(argv[3]);
    return 1;
  }
  std::fwrite(scene.text.data(), 1, scene.text.size(), f);
  if (std::ferror(f) != 0 || std::fclose(f) != 0) {
    std::perror(argv[3]);
    return 1;
  }
  std::fprintf(stderr, "spd_gen: %s level %d: %ld primitives -> %s\n", kind->name, scene.level,
               scene.counts.total(), argv[3]);
  return 0;
}

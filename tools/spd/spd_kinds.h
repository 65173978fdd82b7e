// The benchmark scene kinds of spd_gen, after Eric Haines' Standard Procedural
// Databases: what each is called, how its size grows with its level, and the
// code that writes it. docs/benchmark-scenes.md describes them all.
#pragma once

#include "sc_writer.h"

#include <string>
#include <string_view>
#include <vector>

namespace prism::spd {

struct SpdKind {
  const char* name;    // as on the command line
  const char* summary; // one line for `spd_gen --list`
  const char* level;   // what the level counts, e.g. "recursion depth"
  int minLevel, maxLevel;
  long (*primitives)(int level); // exactly what write() writes at that level
  void (*write)(ScWriter& out, int level);
};

// One function per kind, each in the file of its name.
SpdKind ballsKind();
SpdKind gearsKind();
SpdKind mountKind();
SpdKind ringsKind();
SpdKind teapotKind();
SpdKind tetraKind();
SpdKind treeKind();
SpdKind latticeKind();
SpdKind jacksKind();
SpdKind shellsKind();
SpdKind hfieldKind();

// Every kind, in the order above.
const std::vector<SpdKind>& spdKinds();
// The kind called `name`, or null.
const SpdKind* findSpdKind(std::string_view name);

// The level whose primitive count is nearest to `size` on a logarithmic scale
// (the smaller level on a tie), within the kind's range.
int levelForSize(const SpdKind& kind, long size);

struct SpdScene {
  int level = 0;
  Counts counts;
  std::string text; // the whole .sc file
};

// The scene of `kind` with about `size` primitives.
SpdScene makeSpdScene(const SpdKind& kind, long size);

} // namespace prism::spd

// Deep scenes shared by tests/bailout_test.cpp and tests/work_estimate_test.cpp:
// mirrors facing each other, with and without glass between them.
#pragma once

#include "core/render/renderer.h"

namespace prism::test {

// What both tests render these scenes with: a square image on two threads.
inline RenderSettings squareSettings(int size, int depth, bool noAa, double bailout) {
  RenderSettings s;
  s.width = s.height = size;
  s.maxDepth = depth;
  s.noAa = noAa;
  s.bailout = bailout;
  s.threads = 2;
  return s;
}

// Two facing mirrors at x = +-3, the eye between them looking along the gap,
// so eye rays bounce from one to the other. kMirrors: wide mirrors (ksr 0.7),
// a narrow view and a diffuse ball between, chains of mirror rays to any
// depth. kGlassMirrors: a glass sphere (ksr 0.1, kst 0.7) between mirrors of
// ksr 0.8: the ray tree doubles at every glass hit, and at depth 64 the exact
// render traces about 4 million rays at 8 x 8 with antialiasing.
inline const char* kMirrors =
    "eye 2.5 0.3 0.4\nlookat -3 0 0\nfov 10\n"
    "background 0.2 0.25 0.3\nambient 0.1 0.1 0.1\nlight 0 6 3  20 20 20\n"
    "surface 0.9 0.9 0.9  0.05 0.7 0  20 1\n"
    "polygon 4  -3 -200 -200  -3 200 -200  -3 200 200  -3 -200 200\n"
    "polygon 4  3 -200 200  3 200 200  3 200 -200  3 -200 -200\n"
    "surface 0.8 0.3 0.2  0.9 0.1 0  20 1\nsphere 0 0 0 1\n";
inline const char* kGlassMirrors = "eye 2.5 0.3 0.4\nlookat -3 0 0\nfov 40\n"
                                   "background 0.2 0.25 0.3\nambient 0.1 0.1 0.1\n"
                                   "light 0 6 3  20 20 20\n"
                                   "surface 0.9 0.9 0.9  0.05 0.8 0  20 1\n"
                                   "polygon 4  -3 -2 -10  -3 2 -10  -3 2 10  -3 -2 10\n"
                                   "polygon 4  3 -2 10  3 2 10  3 2 -10  3 -2 -10\n"
                                   "surface 1 1 1  0.05 0.1 0.7  50 1.5\nsphere 0 0 0 1\n";

} // namespace prism::test

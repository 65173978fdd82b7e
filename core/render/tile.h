// A rectangle of pixels: the pass schedule's unit of work (core/render/image_formation.h
// makes them).
#pragma once

namespace prism {

struct Tile {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // pixels [x0, x1) x [y0, y1)
};

} // namespace prism

// Scenes built in memory, of any size, for the benchmark's scaling series and for
// tests: no file, no parser. Both are deterministic (their own generator, no
// std::*_distribution) and come with a camera and lights, so they can be rendered.
#pragma once

#include "core/scene/scene.h"

#include <cstdint>

namespace prism {

// A sphereflake (Haines' SPD "balls"): a sphere with 9 children a third its size
// on its upper side, recursively, generated breadth first and stopped after
// exactly `spheres` spheres, on a ground square (one polygon). Each level of the
// flake is its own push/pop group, nested, so `--accel groups` has a hierarchy.
Scene makeSphereflake(std::size_t spheres);

// `triangles` random triangles in the cube [-1, 1]^3, each in a random
// orientation, sized so that the whole soup has the same total area at any
// count: a ray crossing the cube meets about 8 of them, so the work per ray
// changes only through the hierarchy, not through the picture. One group.
Scene makePolygonSoup(std::size_t triangles, std::uint64_t seed = 1);

// The same soup at a finer grain: each triangle as big as the mean spacing
// between them (circumradius 0.75 (8 / n)^(1/3)), so the neighbourhood of a
// ray's first hit looks alike at any count and only the hierarchy's depth
// grows. (In makePolygonSoup the triangles shrink faster than their spacing,
// so the boxes a ray passes close to without a hit grow in number as n^(1/3),
// whatever the hierarchy.) Stored in the Morton order of their centres,
// spatially coherent as the triangles of a mesh file usually are.
Scene makeScaledPolygonSoup(std::size_t triangles, std::uint64_t seed = 1);

} // namespace prism

// A UV sphere written as a Wavefront OBJ mesh with vertex normals: the test
// object for smooth shading (it must shade like the analytic sphere) and the
// generator of the million-triangle import benchmark (scenes/sphere_obj).
#pragma once

#include <cstdint>
#include <ostream>

namespace prism {

// Number of triangles of a sphere of `stacks` bands and `slices` sectors:
// one fan of `slices` triangles around each pole, two per cell between.
inline std::uint64_t sphereMeshTriangles(int stacks, int slices) {
  return 2 * std::uint64_t(slices) * std::uint64_t(stacks - 1);
}

// Radius `radius` around `centre`; counterclockwise seen from outside, each
// vertex normal the exact sphere normal. stacks >= 2, slices >= 3.
void writeSphereObj(std::ostream& out, int stacks, int slices, double radius = 1.0, double cx = 0.0,
                    double cy = 0.0, double cz = 0.0);

} // namespace prism

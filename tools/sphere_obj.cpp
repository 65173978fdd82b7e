// sphere_obj STACKS SLICES OUT.obj: writes a UV sphere with vertex normals as
// an OBJ file, for the import benchmark of docs/importing.md ("Importing NFF and
// OBJ"): `sphere_obj 501 1000 sphere.obj` is exactly 1,000,000 triangles.
#include "tools/sphere_mesh.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string_view>

namespace {

bool parseInt(std::string_view text, int min, int& out) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && ptr == text.data() + text.size() && out >= min && out <= 1000000;
}

} // namespace

int main(int argc, char** argv) {
  int stacks = 0, slices = 0;
  if (argc != 4 || !parseInt(argv[1], 2, stacks) || !parseInt(argv[2], 3, slices)) {
    std::cerr << "usage: sphere_obj STACKS SLICES OUT.obj  (STACKS >= 2, SLICES >= 3)\n";
    return 2;
  }
  std::ofstream out(argv[3], std::ios::binary);
  prism::writeSphereObj(out, stacks, slices);
  out.close();
  if (!out) {
    std::cerr << "sphere_obj: cannot write " << argv[3] << "\n";
    return 1;
  }
  std::cerr << "sphere_obj: " << prism::sphereMeshTriangles(stacks, slices) << " triangles in "
            << argv[3] << "\n";
  return 0;
}

// A pixel's ray tree (core/render/ray_tree.h) as nested Python dicts with
// readable keys (docs/python.md#a-pixels-ray-tree): what `prism render
// --pixel` prints, for programs.
#pragma once

#include "core/api/prism.h"

#include <pybind11/pybind11.h>

namespace prism::python {

// Vectors are tuples of three floats; fields that only mean something for a
// hit (the surface, the material, the lights, the terms of the formula) are
// present only when "hit" is True. Needs the GIL.
pybind11::dict rayTreeDict(const RayTreeNode& node, const Scene& scene);

// (x, y, z) of a vector.
pybind11::tuple tupleOf(const Vec3& v);

} // namespace prism::python

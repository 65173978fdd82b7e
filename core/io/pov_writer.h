// Writes a Scene as POV-Ray 3.7 scene description (docs/vs-povray.md): the
// camera with Prism's field of view and pixel centres, point lights that fall
// off as 1/r^2, each material's diffuse, highlight, mirror and refraction
// coefficients, and every primitive. `prism convert SCENE OUT.pov` uses it to
// move a scene to POV-Ray, and bench/vs-povray to race the two renderers.
// The text is streamed out primitive by primitive, so a scene of a million
// primitives converts in about the time it takes to read it.
#pragma once

#include "core/scene/scene.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace prism {

// `header` (may hold several lines) is written first as `//` comments. The
// ray depth is the POV identifier Prism_Depth, 5 unless the POV command line
// declares another (`Declare=Prism_Depth=8`); the image size is POV's own
// (+W, +H), as --size is Prism's.
void writePov(std::ostream& out, const Scene& scene, const std::string& header = "");

// Writes the file completely or not at all. Throws std::runtime_error on failure.
void savePov(const std::filesystem::path& path, const Scene& scene, const std::string& header = "");

} // namespace prism

// Writes a Scene as .sc text that loadScene reads back to the same scene:
// every number is printed in its shortest form that reads back exactly, and
// the push/pop groups are kept. `prism convert` uses it to turn NFF and OBJ
// files into .sc.
#pragma once

#include "core/scene/scene.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace prism {

// `header` (may hold several lines) is written first as `#` comments.
void writeScene(std::ostream& out, const Scene& scene, const std::string& header = "");

// Writes the file completely or not at all (a temporary name beside it, then
// renamed). Throws std::runtime_error on failure.
void saveScene(const std::filesystem::path& path, const Scene& scene,
               const std::string& header = "");

} // namespace prism

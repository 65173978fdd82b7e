// One entry point for every scene format Prism reads, chosen by the file's
// extension (case-insensitive): .nff (NFF), .obj (Wavefront OBJ with MTL),
// anything else the .sc language.
#pragma once

#include "core/io/scene_parser.h"

#include <filesystem>
#include <vector>

namespace prism {

enum class SceneFormat { Sc, Nff, Obj };

SceneFormat sceneFormatOf(const std::filesystem::path& path);

// Reads the scene at `path` in the format its extension names. Throws
// SceneError; problems that do not stop the reading go to `warnings`.
Scene loadAnyScene(const std::filesystem::path& path, std::vector<Diagnostic>* warnings = nullptr);

// "FILE:LINE:COLUMN: warning: MESSAGE"
std::string formatWarning(const Diagnostic& d);

} // namespace prism

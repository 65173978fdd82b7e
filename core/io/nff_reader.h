// Reads NFF, the Neutral File Format of Eric Haines' Standard Procedural
// Databases, into a Scene. The mapping onto Prism's model (how lights without
// falloff become 1/r^2 lights, how `angle` becomes `fov`, how polygon patches
// become smooth triangles) is documented in docs/importing.md, "Importing NFF and
// OBJ". Errors are Diagnostics with file, line and column, thrown together as
// a SceneError, exactly as for .sc files.
#pragma once

#include "core/io/diagnostic.h"
#include "core/scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// Reads the file at `path`. Problems that do not stop the scene from being
// read (a zero-area polygon, dropped) are appended to `warnings` when given.
Scene loadNff(const std::filesystem::path& path, std::vector<Diagnostic>* warnings = nullptr);

// Reads `text` as if it were the contents of the file `name`.
Scene parseNff(std::string_view text, const std::string& name,
               std::vector<Diagnostic>* warnings = nullptr);

} // namespace prism

// Reads the .sc scene language (docs/scene-language.md) into a Scene. Every problem found is
// reported as a Diagnostic with file, line and column; the parser collects all
// of them it can and then throws SceneError, never exits, so a previewer can show
// the messages and keep its last good scene.
#pragma once

#include "core/io/diagnostic.h"
#include "core/scene/scene.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// Parses the file at `path`; includes are resolved relative to the including file.
Scene loadScene(const std::filesystem::path& path);

// Parses `text` as if it were the contents of a file named `name` (includes are
// resolved relative to the directory of `name`). For tests and fuzzing.
Scene parseScene(std::string_view text, const std::string& name);

} // namespace prism

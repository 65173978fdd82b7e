// A checking pass over OBJ and MTL text before tinyobjloader reads it.
// tinyobjloader accepts almost anything (a word where a number belongs reads
// as 0, an out-of-range index is noticed only at the end, without its line),
// so this pass finds every problem Prism cares about with its file, line and
// column, and records what tinyobjloader does not keep: the line of each face
// (for the --pixel ray tree) and whether a material gave `illum`.
#pragma once

#include "core/scene_parser.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

struct ObjScan {
  std::vector<Diagnostic> errors;
  std::vector<std::uint32_t> faceLines;       // line of every `f`, in file order
  std::uint64_t triangles = 0;                // sum over faces of (vertices - 2)
  std::vector<std::string> materialLibraries; // readable `mtllib` files, resolved
  std::map<std::string, bool> materials;      // every `newmtl` name: was `illum` given?
};

// Checks the OBJ `text` of file `name`; `directory` resolves `mtllib` paths,
// whose files are read and checked too. Stops after 50 errors.
ObjScan scanObj(std::string_view text, const std::string& name,
                const std::filesystem::path& directory);

// Checks MTL `text` of file `name`, adding its materials to `scan`.
void scanMtl(std::string_view text, const std::string& name, ObjScan& scan);

} // namespace prism

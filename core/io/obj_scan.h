// A checking pass over OBJ and MTL text before tinyobjloader reads it.
// tinyobjloader accepts almost anything (a word where a number belongs reads
// as 0, an out-of-range index is noticed only at the end, without its line),
// so this pass finds every problem Prism cares about with its file, line and
// column, and records what tinyobjloader does not keep: the line and the true
// size of each face, the material each face uses and whether a material gave
// `illum`.
//
// Two parsers of one text disagree wherever their rules differ (white space,
// line ends, a byte-order mark, comments, statements recognised by prefix,
// NUL bytes, number syntax), and each disagreement was a memory error or a
// silently wrong scene. So tinyobjloader never reads the file itself: it reads
// a copy written from what this pass checked (normaliseObjForTinyObj), one
// statement per line on the same line numbers, in a form its rules read the
// same way. What it would decide by rules of its own (materials: when a name
// is looked up, which libraries are read) comes from this pass instead.
#pragma once

#include "core/io/diagnostic.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

inline constexpr std::uint32_t kNoMaterial = std::numeric_limits<std::uint32_t>::max();

struct ObjFace {
  std::uint32_t line = 0;               // for the --pixel ray tree
  std::uint32_t corners = 0;            // tinyobjloader keeps only the low 8 bits of this
  std::uint32_t material = kNoMaterial; // into ObjScan::usedMaterials
};

// An MTL `map_Kd`: the image multiplying a material's Kd, with the options
// Prism maps (docs/importing.md): -s and -o scale and offset the texture
// coordinates, -clamp on clamps them.
struct DiffuseMap {
  std::string path;    // resolved against the MTL file's directory
  std::string library; // the MTL file, for messages
  int line = 0;        // of the FILE argument, for messages
  int column = 0;
  Vec2 scale{1.0};
  Vec2 offset{0.0};
  bool clamp = false;
};

struct MaterialLibrary {
  std::string path; // resolved against the OBJ's directory
  std::string text; // normalised for tinyobj::LoadMtl
};

struct ObjScan {
  std::vector<Diagnostic> errors;
  std::vector<ObjFace> faces;                    // every `f`, in file order
  std::uint64_t triangles = 0;                   // sum over faces of (corners - 2)
  std::vector<MaterialLibrary> libraries;        // every readable `mtllib` file, once
  std::vector<std::string> usedMaterials;        // every `usemtl` name, once
  std::map<std::string, bool> materials;         // every `newmtl` name: was `illum` given?
  std::map<std::string, DiffuseMap> diffuseMaps; // by material name: its map_Kd, if any
  // Every `vt`'s U and V (0 when absent), read exactly: tinyobjloader's
  // parser is off by a few ulps, and only its indices are used.
  std::vector<Vec2> texcoords;
};

// Checks the OBJ `text` of file `name`; `directory` resolves `mtllib` paths,
// whose files are read, checked and normalised too. Stops after 50 errors.
ObjScan scanObj(std::string_view text, const std::string& name,
                const std::filesystem::path& directory);

// Checks MTL `text` of file `name`, adding its materials to `scan`.
void scanMtl(std::string_view text, const std::string& name, ObjScan& scan);

// Rewrites OBJ `text` that scanObj accepted, in place, into what tinyobjloader
// reads: each line's statement with single spaces between its words, or
// nothing for what Prism ignores or takes from the scan (comments,
// `usemtl`, `mtllib`, ...); `vt` as "vt U [V]"; faces' corners as "v", "v/t",
// "v//n" or "v/t/n". Line breaks are kept, so tinyobjloader's messages name
// the file's own lines.
void normaliseObjForTinyObj(std::string& text);

} // namespace prism

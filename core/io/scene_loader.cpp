#include "core/io/scene_loader.h"

#include "core/io/file_extension.h"
#include "core/io/nff_reader.h"
#include "core/io/obj_reader.h"

namespace prism {

SceneFormat sceneFormatOf(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".nff") return SceneFormat::Nff;
  if (ext == ".obj") return SceneFormat::Obj;
  return SceneFormat::Sc;
}

Scene loadAnyScene(const std::filesystem::path& path, std::vector<Diagnostic>* warnings) {
  switch (sceneFormatOf(path)) {
  case SceneFormat::Nff: return loadNff(path, warnings);
  case SceneFormat::Obj: return loadObj(path, warnings);
  case SceneFormat::Sc: break;
  }
  return loadScene(path);
}

std::string formatWarning(const Diagnostic& d) { return d.format("warning"); }

} // namespace prism

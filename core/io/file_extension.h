// A file name's extension in lower case ("Scene.NFF" -> ".nff"): how every
// reader and writer picks a format, so that case never matters.
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace prism {

inline std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

} // namespace prism

#include "scene_files.h"

#include "core/io/pending_file.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>

namespace prism {

namespace fs = std::filesystem;

bool isSceneFile(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".sc" || ext == ".nff" || ext == ".obj";
}

std::vector<FolderEntry> listSceneFolder(const fs::path& folder) {
  std::vector<FolderEntry> entries;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code ignored;
    const bool folderEntry = it->is_directory(ignored);
    if (folderEntry || (it->is_regular_file(ignored) && isSceneFile(it->path())))
      entries.push_back({name, folderEntry});
  }
  std::sort(entries.begin(), entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
  return entries;
}

RecentFiles::RecentFiles(std::optional<fs::path> store) : store_(std::move(store)) {
  if (!store_) return;
  std::ifstream in(*store_);
  for (std::string line; std::getline(in, line) && paths_.size() < kMaxRecent;)
    if (!line.empty()) paths_.push_back(line);
}

void RecentFiles::add(const fs::path& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error).lexically_normal();
  const std::string text = (error ? path : absolute).string();
  std::erase(paths_, text);
  paths_.insert(paths_.begin(), text);
  if (paths_.size() > kMaxRecent) paths_.resize(kMaxRecent);
  if (!store_) return;
  try { // the list is a convenience: failing to keep it must not stop anything
    fs::create_directories(store_->parent_path(), error);
    writeFileAtomically(*store_, [&](std::ostream& out) {
      for (const std::string& p : paths_)
        out << p << "\n";
    });
  } catch (const std::exception&) {
  }
}

std::optional<fs::path> RecentFiles::defaultStore() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
    return fs::path(config) / "prism" / "recent-scenes";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".config" / "prism" / "recent-scenes";
  return std::nullopt;
}

} // namespace prism

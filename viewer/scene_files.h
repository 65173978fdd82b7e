// Finding scenes to open in the previewer: the scene files and folders of a
// folder, for the Open dialog, and the list of recently opened scenes, kept
// between sessions. No ImGui here, so both can be tested.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace prism {

// Whether `path` names a scene Prism reads (.sc, .nff, .obj; any case).
bool isSceneFile(const std::filesystem::path& path);

struct FolderEntry {
  std::string name;
  bool folder = false;
};

// The folders and scene files in `folder`, folders first, each group sorted
// by name; hidden ones (a leading '.') left out. Empty when it cannot be read.
std::vector<FolderEntry> listSceneFolder(const std::filesystem::path& folder);

// Recently opened scenes, newest first, at most kMaxRecent, kept in a file
// (one absolute path a line) so they outlive the session.
class RecentFiles {
public:
  static constexpr std::size_t kMaxRecent = 10;

  // Reads the list from `store` (none: a list for this session only).
  explicit RecentFiles(std::optional<std::filesystem::path> store);

  const std::vector<std::string>& paths() const { return paths_; }
  // Puts `path` first (absolute, once) and writes the list back.
  void add(const std::filesystem::path& path);

  // Where the list is kept: $XDG_CONFIG_HOME/prism/recent-scenes, or
  // ~/.config/prism/recent-scenes; nothing when neither is set.
  static std::optional<std::filesystem::path> defaultStore();

private:
  std::optional<std::filesystem::path> store_;
  std::vector<std::string> paths_;
};

} // namespace prism

// Notices when a scene's files change on disk, so the previewer can reload it.
// Polling (the caller decides how often) keeps it portable and simple: a
// scene has a handful of files, and a stat each is cheap.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace prism {

class FileWatch {
public:
  // Starts watching `files`, remembering their current state.
  void watch(const std::vector<std::string>& files);

  // True when a watched file's modification time or size differs from what was
  // remembered (or it appeared or vanished); remembers the new state, so each
  // change is reported once.
  bool changed();

  const std::vector<std::string>& files() const { return files_; }

private:
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type mtime{};
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stampOf(const std::string& file);

  std::vector<std::string> files_;
  std::vector<Stamp> stamps_;
};

} // namespace prism

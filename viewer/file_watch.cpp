#include "file_watch.h"

namespace prism {

FileWatch::Stamp FileWatch::stampOf(const std::string& file) {
  std::error_code error;
  Stamp stamp;
  stamp.mtime = std::filesystem::last_write_time(file, error);
  if (error) return {};
  stamp.size = std::filesystem::file_size(file, error);
  if (error) return {};
  stamp.exists = true;
  return stamp;
}

void FileWatch::watch(const std::vector<std::string>& files) {
  files_ = files;
  stamps_.clear();
  for (const std::string& file : files_)
    stamps_.push_back(stampOf(file));
}

bool FileWatch::changed() {
  bool any = false;
  for (std::size_t i = 0; i < files_.size(); ++i) {
    const Stamp now = stampOf(files_[i]);
    if (now == stamps_[i]) continue;
    stamps_[i] = now;
    any = true;
  }
  return any;
}

} // namespace prism

// Files written completely or not at all. A PendingFile is written under a
// temporary name beside its target (same folder, so the final rename is
// atomic; same extension, so image libraries pick the format by it) and
// renamed into place by commit(). Until then nothing is at the target, and the
// temporary file is removed on every way out: by the destructor (an error, an
// exception, std::bad_alloc) and, once removePendingFilesOnSignals() has been
// called, when the process is stopped by SIGINT, SIGTERM, SIGHUP or SIGQUIT.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace prism {

class PendingFile {
public:
  // Chooses the temporary name `.STEM.prism-PID-N.EXT` beside `target`.
  explicit PendingFile(const std::filesystem::path& target);
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  const std::filesystem::path& tempPath() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }

  // Renames the temporary file to the target. Throws std::runtime_error
  // ("cannot write 'TARGET': ...") and removes the temporary on failure.
  void commit();

private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  int slot_ = -1; // in the signal handler's list, or -1 when not listed
  bool committed_ = false;
};

// Writes a file completely or not at all: `write` fills a stream on a
// PendingFile, which is committed when the stream is good. Throws
// std::runtime_error ("cannot write 'PATH'") otherwise.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write);

// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT that remove every
// pending temporary file and then let the signal take its default course (the
// process ends with the signal's status). For programs, not libraries: call
// once from main.
void removePendingFilesOnSignals();

} // namespace prism

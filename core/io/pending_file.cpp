#include "core/io/pending_file.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace prism {

namespace fs = std::filesystem;

namespace {

// The temporary files a signal handler must remove. A handler may only call
// async-signal-safe functions (unlink, raise) and read lock-free atomics, so
// the list is a fixed array of fixed buffers: a slot is claimed, its path
// written, then published; the handler reads published slots only.
constexpr std::size_t kPendingSlots = 64;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<bool> claimed{false};
  std::atomic<bool> published{false};
  char path[kMaxPath];
};
std::array<Slot, kPendingSlots> gSlots;
static_assert(std::atomic<bool>::is_always_lock_free);

// A file that does not fit (a very long path, or more than kPendingSlots at once) is
// still removed on every error path; only a signal would leave it.
int publish(const fs::path& path) {
  const std::string& text = path.native();
  if (text.size() >= kMaxPath) return -1;
  for (std::size_t i = 0; i < kPendingSlots; ++i) {
    bool expected = false;
    if (!gSlots[i].claimed.compare_exchange_strong(expected, true)) continue;
    std::memcpy(gSlots[i].path, text.c_str(), text.size() + 1);
    gSlots[i].published.store(true);
    return int(i);
  }
  return -1;
}

void withdraw(int slot) {
  if (slot < 0) return;
  gSlots[std::size_t(slot)].published.store(false);
  gSlots[std::size_t(slot)].claimed.store(false);
}

extern "C" void removeAndReraise(int signal) {
  for (Slot& slot : gSlots)
    if (slot.published.load()) unlink(slot.path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

std::atomic<unsigned> gCounter{0};

} // namespace

PendingFile::PendingFile(const fs::path& target) : target_(target) {
  // The counter tells apart two pending files for one target in one process
  // (the previewer saving while a render command writes, say).
  temp_ =
      target.parent_path() / ("." + target.stem().string() + ".prism-" + std::to_string(getpid()) +
                              "-" + std::to_string(gCounter++) + target.extension().string());
  slot_ = publish(temp_);
}

PendingFile::~PendingFile() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove(temp_, ignored);
  }
  withdraw(slot_);
}

void PendingFile::commit() {
  std::error_code error;
  fs::rename(temp_, target_, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temp_, ignored);
    throw std::runtime_error("cannot write '" + target_.string() + "': " + error.message());
  }
  committed_ = true;
  withdraw(slot_);
  slot_ = -1;
}

void writeFileAtomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  PendingFile file(path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    if (out) write(out);
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  }
  file.commit();
}

void removePendingFilesOnSignals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    struct sigaction action {};
    action.sa_handler = removeAndReraise;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
  }
}

} // namespace prism

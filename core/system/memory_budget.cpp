#include "core/system/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace prism {

namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

// The first number in a file, or nothing (also for "max", cgroup v2's "no limit").
std::optional<std::uint64_t> numberIn(const char* path) {
  std::ifstream in(path);
  std::uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

// A "Key: N kB" line of /proc/meminfo, in bytes.
std::optional<std::uint64_t> memInfo(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(key.size() + 1));
    std::uint64_t kib = 0;
    if (fields >> kib) return kib * 1024;
  }
  return std::nullopt;
}

// Field `index` of /proc/self/statm (0: whole address space, 5: data and
// stack), in bytes.
std::optional<std::uint64_t> statm(int index) {
  std::ifstream in("/proc/self/statm");
  std::uint64_t pages = 0;
  for (int i = 0; i <= index; ++i)
    if (!(in >> pages)) return std::nullopt;
  return pages * std::uint64_t(sysconf(_SC_PAGESIZE));
}

// Room left under a resource limit, given what is in use.
std::optional<std::uint64_t> roomUnderLimit(int resource, std::optional<std::uint64_t> used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || !used) {
    return std::nullopt;
  }
  const auto cap = std::uint64_t(limit.rlim_cur);
  return cap > *used ? cap - *used : 0;
}

std::optional<std::uint64_t> roomInCgroup() {
  // cgroup v2, then v1 (whose "no limit" is a huge number).
  if (const auto max = numberIn("/sys/fs/cgroup/memory.max")) {
    const std::uint64_t used = numberIn("/sys/fs/cgroup/memory.current").value_or(0);
    return *max > used ? *max - used : 0;
  }
  if (const auto max = numberIn("/sys/fs/cgroup/memory/memory.limit_in_bytes");
      max && *max < (std::uint64_t(1) << 60)) {
    const std::uint64_t used = numberIn("/sys/fs/cgroup/memory/memory.usage_in_bytes").value_or(0);
    return *max > used ? *max - used : 0;
  }
  return std::nullopt;
}

} // namespace

std::uint64_t imageBytes(int width, int height, std::uint64_t bytesPerPixel) {
  return std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0)) * bytesPerPixel;
}

std::optional<std::uint64_t> parseByteCount(std::string_view text) {
  std::uint64_t value = 0;
  std::size_t i = 0;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
    if (value > (kUnlimited - 9) / 10) return std::nullopt;
    value = value * 10 + std::uint64_t(text[i] - '0');
  }
  if (i == 0) return std::nullopt;
  int shift = 0;
  if (i + 1 == text.size()) {
    const std::string_view units = "KMGTP";
    const std::size_t unit = units.find(char(std::toupper(static_cast<unsigned char>(text[i]))));
    if (unit == std::string_view::npos) return std::nullopt;
    shift = 10 * int(unit + 1);
  } else if (i != text.size()) {
    return std::nullopt;
  }
  if (shift > 0 && value > (kUnlimited >> shift)) return std::nullopt;
  return value << shift;
}

std::optional<MemoryAvailable> availableMemory() {
  MemoryAvailable best{kUnlimited, ""};
  const auto consider = [&](std::optional<std::uint64_t> room, const char* source) {
    if (room && *room < best.bytes) best = {*room, source};
  };
  if (const char* limit = std::getenv("PRISM_MEMORY_LIMIT"))
    consider(parseByteCount(limit), "PRISM_MEMORY_LIMIT");
  consider(memInfo("MemAvailable"), "MemAvailable in /proc/meminfo");
  consider(roomInCgroup(), "the cgroup's memory limit");
  consider(roomUnderLimit(RLIMIT_AS, statm(0)), "ulimit -v");
  consider(roomUnderLimit(RLIMIT_DATA, statm(5)), "ulimit -d");
  if (best.bytes == kUnlimited) return std::nullopt;
  return best;
}

std::string formatBytes(std::uint64_t bytes) {
  static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 6) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, kUnits[unit]);
  return text;
}

std::optional<std::string> memoryProblem(std::uint64_t bytes, const std::string& what) {
  const std::optional<MemoryAvailable> available = availableMemory();
  if (!available || bytes <= available->bytes) return std::nullopt;
  return what + " needs about " + formatBytes(bytes) + " of memory, but only " +
         formatBytes(available->bytes) + " is available (limited by " + available->source + ")";
}

} // namespace prism

#include "core/system/system_info.h"

#include <sys/resource.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace prism {

std::string hostName() {
  char name[256] = "";
  if (gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "unknown";
  return name;
}

namespace {

std::string_view trimmed(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && blank(s.back()))
    s.remove_suffix(1);
  return s;
}

// The "KEY : VALUE" lines of a cpuinfo text, in order, both trimmed; lines
// without a colon (the blank ones between processors) are skipped.
std::vector<std::pair<std::string_view, std::string_view>> fields(std::string_view text) {
  std::vector<std::pair<std::string_view, std::string_view>> all;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    all.emplace_back(trimmed(line.substr(0, colon)), trimmed(line.substr(colon + 1)));
  }
  return all;
}

// The first non-empty value of `key`.
std::optional<std::string> firstValue(const auto& all, std::string_view key) {
  for (const auto& [k, v] : all)
    if (k == key && !v.empty()) return std::string(v);
  return std::nullopt;
}

// The designers Arm assigns implementer codes to ("CPU implementer").
std::optional<std::string_view> implementerName(std::string_view code) {
  static constexpr std::pair<std::string_view, std::string_view> kNames[] = {
      {"0x41", "ARM"},       {"0x42", "Broadcom"}, {"0x43", "Cavium"}, {"0x46", "Fujitsu"},
      {"0x48", "HiSilicon"}, {"0x4e", "NVIDIA"},   {"0x50", "APM"},    {"0x51", "Qualcomm"},
      {"0x61", "Apple"},     {"0xc0", "Ampere"}};
  for (const auto& [c, name] : kNames)
    if (c == code) return name;
  return std::nullopt;
}

// Arm's own cores ("CPU part" of implementer 0x41), the common ones.
std::optional<std::string_view> armPartName(std::string_view code) {
  static constexpr std::pair<std::string_view, std::string_view> kNames[] = {
      {"0xd03", "Cortex-A53"},  {"0xd04", "Cortex-A35"},  {"0xd05", "Cortex-A55"},
      {"0xd07", "Cortex-A57"},  {"0xd08", "Cortex-A72"},  {"0xd09", "Cortex-A73"},
      {"0xd0a", "Cortex-A75"},  {"0xd0b", "Cortex-A76"},  {"0xd0c", "Neoverse-N1"},
      {"0xd0d", "Cortex-A77"},  {"0xd40", "Neoverse-V1"}, {"0xd41", "Cortex-A78"},
      {"0xd49", "Neoverse-N2"}, {"0xd4f", "Neoverse-V2"}};
  for (const auto& [c, name] : kNames)
    if (c == code) return name;
  return std::nullopt;
}

// One arm64 core: "ARM Neoverse-N1", "ARM implementer 0x41 part 0xd99",
// "implementer 0x99 part 0x001".
std::string armCore(std::string_view implementer, std::string_view part) {
  const std::optional<std::string_view> designer = implementerName(implementer);
  if (implementer == "0x41")
    if (const std::optional<std::string_view> name = armPartName(part))
      return "ARM " + std::string(*name);
  std::string text = designer ? std::string(*designer) + " " : "";
  return text + "implementer " + std::string(implementer) + " part " + std::string(part);
}

// Every distinct core of an arm64 cpuinfo in order of appearance, joined by
// " + "; "" if there is no "CPU part".
std::string armCores(const auto& all) {
  std::vector<std::string> cores;
  std::string_view implementer = "?";
  for (const auto& [k, v] : all) {
    if (k == "CPU implementer") implementer = v;
    if (k != "CPU part" || v.empty()) continue;
    std::string core = armCore(implementer, v);
    bool seen = false;
    for (const std::string& c : cores)
      seen = seen || c == core;
    if (!seen) cores.push_back(std::move(core));
  }
  std::string text;
  for (const std::string& c : cores)
    text += (text.empty() ? "" : " + ") + c;
  return text;
}

} // namespace

std::string describeCpu(std::string_view cpuinfo, std::string_view arch) {
  const auto all = fields(cpuinfo);
  std::optional<std::string> cpu = firstValue(all, "model name");
  if (!cpu) {
    std::string cores = armCores(all);
    if (!cores.empty()) cpu = std::move(cores);
  }
  for (const char* key : {"Processor", "cpu model", "cpu", "uarch", "vendor_id"})
    if (!cpu) cpu = firstValue(all, key);
  std::optional<std::string> board = firstValue(all, "Model");
  if (!board) board = firstValue(all, "Hardware");
  std::string text;
  if (cpu && board)
    text = *cpu + ", " + *board;
  else if (cpu || board)
    text = cpu ? *cpu : *board;
  else
    text = "unknown CPU";
  return text + " (" + std::string(arch.empty() ? "unknown architecture" : arch) + ")";
}

std::string machineDescription() {
  std::ifstream file("/proc/cpuinfo");
  std::stringstream cpuinfo;
  cpuinfo << file.rdbuf();
  utsname names{};
  const std::string arch = uname(&names) == 0 ? names.machine : "";
  return describeCpu(cpuinfo.str(), arch);
}

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace prism

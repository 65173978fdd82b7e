#include "bench_startup.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace prism {

namespace {

namespace fs = std::filesystem;

struct ChildCost {
  double cpuMs = 0.0;  // user + system
  double peakMb = 0.0; // maximum resident set
};

double millis(const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) / 1e3; }

// Runs `exe args...` with its output discarded and returns what it cost;
// throws when it cannot be started or does not exit with status 0.
ChildCost runChild(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(exe.c_str())};
  for (const std::string& a : args)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) throw std::runtime_error("cannot run " + exe);
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("prism " + args.front() + " failed in the start-up benchmark");
  return {millis(usage.ru_utime) + millis(usage.ru_stime), double(usage.ru_maxrss) / 1024.0};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

void benchStartup(int runs) {
  const std::string exe = fs::read_symlink("/proc/self/exe").string();
  const fs::path dir = fs::temp_directory_path() / ("prism-startup-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path scene = dir / "one-sphere.sc";
  std::ofstream(scene) << "resolution 8 8\neye 0 0 5\nlookat 0 0 0\nfov 40\n"
                          "light 3 3 5 20 20 20\nsurface 1 0.2 0.2 0.8 0.2 0 20 1\n"
                          "sphere 0 0 0 1\n";
  const std::string picture = (dir / "one-sphere.tif").string();
  struct Case {
    const char* name;
    std::vector<std::string> args;
  };
  const std::vector<Case> cases = {
      {"prism --version", {"--version"}},
      {"prism --help", {"--help"}},
      {"prism render (one sphere, 8 x 8, TIFF)",
       {"render", scene.string(), "-o", picture, "--threads", "1", "-q"}},
  };
  std::cout << "prism bench --startup: " << runs
            << " runs of each, whole-process CPU (user + system) and peak memory\n";
  std::printf("  %-42s %12s %12s %12s\n", "", "median ms", "min ms", "max MB");
  for (const Case& c : cases) {
    std::vector<double> cpu;
    double peak = 0.0;
    for (int i = 0; i < runs; ++i) {
      const ChildCost cost = runChild(exe, c.args);
      cpu.push_back(cost.cpuMs);
      peak = std::max(peak, cost.peakMb);
    }
    std::printf("  %-42s %12.1f %12.1f %12.1f\n", c.name, median(cpu),
                *std::min_element(cpu.begin(), cpu.end()), peak);
  }
  fs::remove_all(dir);
}

} // namespace prism

// Running `prism` as an MPI job in the tests (docs/distributed.md): where
// mpirun is, and the command line that starts N processes.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace prism::test {

// mpirun as found on PATH, or empty. The MPI tests fail without it rather
// than skip (CI installs openmpi-bin): a missing launcher must not pass
// unnoticed as tests that did not run.
inline std::filesystem::path mpirunOnPath() {
  const char* path = std::getenv("PATH");
  std::string_view rest = path ? path : "";
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const std::string_view dir = rest.substr(0, colon);
    const std::filesystem::path candidate =
        std::filesystem::path(dir.empty() ? "." : std::string(dir)) / "mpirun";
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  return {};
}

// The prefix of a command run as an MPI job of `processes` processes (Open
// MPI's mpirun): allowed as root (CI containers), with more processes than
// cores (this 2-core machine runs -np 3), and without single-copy transfers
// between processes (containers often forbid the ptrace they need); a job
// that hangs is ended after 2 minutes (status 124). Under AddressSanitizer
// the ranks look for memory errors but not for leaks: LeakSanitizer stops
// the world to scan it, and with Open MPI's progress threads running its
// tracer crashed at random (1 job in about 15 in CI); after MPI_Finalize
// Open MPI has unloaded its components and their allocations cannot be told
// from Prism's. Leaks of the code the ranks share with one process are
// checked by the single-process tests (docs/testing.md). E.g.
//   mpirunPrefix(2) + quoted(PRISM_BINARY) + " sweep ..."
inline std::string mpirunPrefix(int processes) {
  return "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" "
         "timeout 120 mpirun --allow-run-as-root --oversubscribe --mca "
         "btl_vader_single_copy_mechanism none -np " +
         std::to_string(processes) + " ";
}

} // namespace prism::test

// Files and memory, whatever goes wrong: a file is written completely or not
// at all (its temporary is removed on errors, exceptions and SIGINT/SIGTERM),
// a worker's exception reaches the caller instead of ending the process, and
// the memory a render may take is known before it starts.
#include "core/io/pending_file.h"
#include "core/render/parallel.h"
#include "core/system/memory_budget.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <stdexcept>
#include <thread>

namespace prism {
namespace {

namespace fs = std::filesystem;

// The names in `dir`, to see that nothing was left behind.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(PendingFile, CommitRenamesTheTemporaryIntoPlace) {
  test::ScratchDir dir;
  const fs::path target = dir / "out.txt";
  {
    PendingFile file(target);
    EXPECT_EQ(file.tempPath().parent_path(), dir.path());
    EXPECT_EQ(file.tempPath().extension(), ".txt"); // image libraries choose by it
    test::writeFile(file.tempPath(), "complete");
    EXPECT_FALSE(fs::exists(target));
    file.commit();
  }
  EXPECT_EQ(test::slurp(target), "complete");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.txt"});
}

TEST(PendingFile, AnErrorOrExceptionLeavesNothing) {
  test::ScratchDir dir;
  const fs::path target = dir / "out.txt";
  test::writeFile(target, "old");
  EXPECT_THROW(writeFileAtomically(target,
                                   [](std::ostream& out) {
                                     out << "half";
                                     throw std::runtime_error("disk on fire");
                                   }),
               std::runtime_error);
  EXPECT_EQ(test::slurp(target), "old"); // the previous file is untouched
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.txt"});
  // A failed stream is an error too.
  EXPECT_THROW(
      writeFileAtomically(target, [](std::ostream& out) { out.setstate(std::ios::badbit); }),
      std::runtime_error);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.txt"});
  // Committing onto a directory fails and removes the temporary.
  fs::create_directory(dir / "taken");
  {
    PendingFile file(dir / "taken");
    test::writeFile(file.tempPath(), "x");
    EXPECT_THROW(file.commit(), std::runtime_error);
  }
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"out.txt", "taken"}));
}

// A child process starts writing, then is stopped by a signal: its temporary
// file is gone and it ended by that signal (the shell's status 128 + N).
TEST(PendingFile, ASignalRemovesPendingTemporaries) {
  for (const int signal : {SIGINT, SIGTERM}) {
    test::ScratchDir dir;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      removePendingFilesOnSignals();
      PendingFile first(dir / "a.tiff"), second(dir / "b.sc");
      test::writeFile(first.tempPath(), "partial");
      test::writeFile(second.tempPath(), "partial");
      std::raise(signal);
      _exit(0); // not reached: the default action ends the process
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_TRUE(entries(dir.path()).empty()) << entries(dir.path()).front();
  }
}

// Threads 0 is the cores this thread may run on: bound to one core (as
// mpirun binds a rank, or taskset a process) it is 1, and an explicit count
// is kept whatever the binding.
TEST(ParallelFor, ThreadsZeroFollowsTheCpuAffinity) {
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
  EXPECT_EQ(resolveThreadCount(0), CPU_COUNT(&saved));
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &saved)) {
      CPU_SET(cpu, &one);
      break;
    }
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  const int bound = resolveThreadCount(0), explicitCount = resolveThreadCount(3);
  ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
  EXPECT_EQ(bound, 1);
  EXPECT_EQ(explicitCount, 3);
}

// An exception thrown by a worker (std::bad_alloc in a tile, say) ended the
// process through std::terminate; it now stops the other workers and is
// rethrown to the caller once every thread has finished.
TEST(ParallelFor, AWorkersExceptionReachesTheCaller) {
  // Thrown on a thread of the pool (worker 1), while the calling thread
  // (worker 0) waits inside an item for it: rethrown to the caller.
  std::atomic<bool> thrown{false};
  EXPECT_THROW(parallelFor(10000, 2,
                           [&](int, int worker) {
                             if (worker == 1) {
                               thrown = true;
                               throw std::bad_alloc();
                             }
                             while (!thrown)
                               std::this_thread::yield();
                           }),
               std::bad_alloc);
  // On one thread, nothing after the failing item runs.
  std::atomic<int> started{0};
  EXPECT_THROW(parallelFor(10000, 1,
                           [&](int item, int) {
                             ++started;
                             if (item == 3) throw std::runtime_error("item 3");
                           }),
               std::runtime_error);
  EXPECT_EQ(started.load(), 4);
  // Without exceptions every item runs once.
  std::atomic<int> ran{0};
  parallelFor(1000, 2, [&](int, int) { ++ran; });
  EXPECT_EQ(ran.load(), 1000);
}

TEST(MemoryBudget, ByteCountsAndSizes) {
  EXPECT_EQ(parseByteCount("4096"), 4096u);
  EXPECT_EQ(parseByteCount("512K"), 512u << 10);
  EXPECT_EQ(parseByteCount("8g"), std::uint64_t(8) << 30);
  EXPECT_EQ(parseByteCount("2T"), std::uint64_t(2) << 40);
  EXPECT_FALSE(parseByteCount(""));
  EXPECT_FALSE(parseByteCount("G"));
  EXPECT_FALSE(parseByteCount("1.5G"));
  EXPECT_FALSE(parseByteCount("1GB"));
  EXPECT_FALSE(parseByteCount("99999999999999999999"));
  EXPECT_FALSE(parseByteCount("99999999999P"));
  EXPECT_EQ(formatBytes(512), "512 bytes");
  EXPECT_EQ(formatBytes(std::uint64_t(3) << 29), "1.5 GiB");
  // 32768 x 32768 pixels of a headless render: 28 bytes each.
  EXPECT_EQ(imageBytes(32768, 32768, kRenderBytesPerPixel), std::uint64_t(28) << 30);
}

// Under `ulimit -v` the room left is the limit minus what the process already
// maps, and a render that needs more is refused with the limit named. In a
// child, so the limit binds nothing else.
TEST(MemoryBudget, TheAddressSpaceLimitIsHonoured) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages = 0;
    statm >> pages;
    const std::uint64_t mapped = pages * std::uint64_t(sysconf(_SC_PAGESIZE));
    const std::uint64_t room = std::uint64_t(1) << 30;
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = rlim_t(mapped + room);
    if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(10);
    const std::optional<MemoryAvailable> available = availableMemory();
    if (!available) _exit(11);
    if (available->source != "ulimit -v") _exit(12);
    // What was mapped between reading statm here and in availableMemory.
    if (available->bytes > room || available->bytes < room - (std::uint64_t(64) << 20)) _exit(13);
    const std::optional<std::string> problem = memoryProblem(std::uint64_t(2) << 30, "it");
    if (!problem || problem->find("it needs about 2.0 GiB of memory, but only") != 0) _exit(14);
    if (memoryProblem(std::uint64_t(1) << 20, "it")) _exit(15);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "failed check " << WEXITSTATUS(status);
}

} // namespace
} // namespace prism

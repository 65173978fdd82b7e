// `prism sweep` as an MPI job (docs/choosing-settings.md#sweeps-over-mpi):
// under `mpirun -np 2` and `-np 3` it writes the table, the summary and the
// reference of a sweep on one process, but for the columns that time the
// renders; a scene error ends every process with status 2, reported once.
// Needs Open MPI's mpirun on PATH: without it these tests fail.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/sweep/sweep_table.h"

#include "mpi_run.h"
#include "test_files.h"

#include <cmath>
#include <filesystem>
#include <numeric>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace prism {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::RunResult;
using test::slurp;

// A mirror-like sphere over a floor: pass 2 on some pixels, reflected rays,
// a bailout that has something to skip.
const char* kScene = R"(eye 0 0 4
lookat 0 0 0
light 2 3 4 30 30 30
ambient 0.1 0.1 0.1
surface 1 0.5 0.2 0.6 0.4 0 20 1
sphere 0 0 0 1
surface 0.4 0.6 0.9 0.8 0 0 1 1
polygon 4  -5 -1 -5  5 -1 -5  5 -1 5  -5 -1 5
)";

// The same picture as NFF, without a view: every process that reads it
// gets a warning ("no view ('v')"), which only rank 0 may print.
const char* kSceneWithWarning = "b 0.1 0.1 0.2\nl 2 3 4\nf 1 0.5 0.2 0.6 0.4 20 0 1\n"
                                "s 0 0 0 1\nf 0.4 0.6 0.9 0.8 0 1 0 1\n"
                                "p 4\n-5 -1 -5\n5 -1 -5\n5 -1 5\n-5 -1 5\n";

const char* kBadScene = "eye 0 0 4\nsphere 0 0 0 -1\n";
const char* kBadSceneError = "bad.sc:2:14: error:";

// The columns that depend on the machine and the moment: the measured times,
// and the Pareto front, which is drawn from cpu_s.
const std::set<std::string> kTimingColumns{"cpu_s", "wall_s", "pareto"};

// 8 depths x 3 bailouts: the groups of settings a distributed sweep hands out.
constexpr int kGroups = 24;

std::size_t countOf(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size()))
    ++count;
  return count;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at = text.find(separator); at != std::string::npos;
       at = text.find(separator, start)) {
    parts.push_back(text.substr(start, at - start));
    start = at + 1;
  }
  parts.push_back(text.substr(start));
  return parts;
}

// sweep.csv as its header and its rows of fields (no field holds a comma).
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

Table readTable(const std::string& csv) {
  Table table;
  std::vector<std::string> lines = split(csv, '\n');
  if (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty()) return table;
  table.header = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i)
    table.rows.push_back(split(lines[i], ','));
  return table;
}

// Every field of `got` equal to `expected`'s, timing columns aside.
void expectSameTableButTimes(const std::string& expectedCsv, const std::string& gotCsv) {
  const Table expected = readTable(expectedCsv), got = readTable(gotCsv);
  ASSERT_EQ(got.header, expected.header);
  for (const std::string& column : kTimingColumns)
    ASSERT_EQ(std::count(got.header.begin(), got.header.end(), column), 1) << column;
  ASSERT_EQ(expected.rows.size(), 408u);
  ASSERT_EQ(got.rows.size(), expected.rows.size());
  int compared = 0;
  std::vector<std::string> differences;
  for (std::size_t r = 0; r < got.rows.size(); ++r) {
    ASSERT_EQ(got.rows[r].size(), got.header.size()) << "row " << r;
    ASSERT_EQ(expected.rows[r].size(), got.header.size()) << "row " << r;
    for (std::size_t c = 0; c < got.header.size(); ++c) {
      if (kTimingColumns.count(got.header[c])) continue;
      ++compared;
      if (got.rows[r][c] != expected.rows[r][c])
        differences.push_back("row " + std::to_string(r + 1) + " (" + expected.rows[r][5] + "), " +
                              got.header[c] + ": " + got.rows[r][c] + " instead of " +
                              expected.rows[r][c]);
    }
  }
  EXPECT_EQ(compared, 408 * (int(got.header.size()) - int(kTimingColumns.size())));
  EXPECT_TRUE(differences.empty())
      << differences.size() << " fields differ, the first: " << differences.front();
}

// The pareto column is the front of the table's own cpu_s and psnr_db, over
// every row (not per process), and every row's time was measured.
void expectParetoOfItsOwnTimes(const std::string& csv) {
  const std::vector<SweepRow> written = parseSweepCsv(csv);
  std::vector<SweepRow> remarked = written;
  for (SweepRow& row : remarked)
    row.pareto = false;
  markParetoFront(remarked);
  int onFront = 0;
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_EQ(written[i].pareto, remarked[i].pareto) << settingOptions(written[i].setting);
    onFront += written[i].pareto ? 1 : 0;
    EXPECT_TRUE(written[i].cpuSeconds > 0.0 && std::isfinite(written[i].cpuSeconds))
        << settingOptions(written[i].setting);
  }
  EXPECT_GT(onFront, 0);
}

// sweep.json without what depends on the machine and the moment.
nlohmann::json summaryButTimes(const fs::path& file) {
  nlohmann::json json = nlohmann::json::parse(slurp(file));
  json.erase("cpu_s");
  json.erase("wall_s");
  json.at("reference").erase("cpu_s");
  json.at("reference").erase("wall_s");
  return json;
}

class MpiSweep : public ::testing::Test {
protected:
  void SetUp() override {
    ASSERT_FALSE(test::mpirunOnPath().empty())
        << "mpirun is not on PATH: the MPI tests need Open MPI's launcher (openmpi-bin)";
  }

  fs::path write(const std::string& name, const std::string& text) {
    test::writeFile(dir_ / name, text);
    return dir_ / name;
  }

  // `prism sweep` at 8 x 6 on one thread a process (the processes of a job
  // share this machine's two cores), under `launcher`, each setting rendered
  // once (--min-seconds 0: the times are not compared). At 16 x 12, each
  // setting timed over 16 runs, the two job tests took 40 s and 48 s under
  // the sanitizers. At 8 x 6 the sweep still has supersampled pixels and
  // reflected rays in nearly every row.
  // `scene` as a shell word.
  static std::string sweepCommand(const std::string& launcher, const std::string& scene,
                                  const fs::path& out, const std::string& more = "") {
    return launcher + quoted(PRISM_BINARY) + " sweep " + scene + " -o " + quoted(out) +
           " --size 8 6 --threads 1 --min-seconds 0" + more;
  }

  RunResult run(const std::string& command) { return test::runCaptured(command, dir_); }

  // The sweep of `scene` by one process and by `processes`, compared.
  // Returns the job's run.
  RunResult expectSameSweep(int processes, const fs::path& scene, const std::string& more) {
    const fs::path single = dir_ / "single", job = dir_ / "job";
    const RunResult alone = run(sweepCommand("", quoted(scene), single, " -q"));
    EXPECT_EQ(alone.exitCode, 0) << alone.err;
    const RunResult distributed =
        run(sweepCommand(test::mpirunPrefix(processes), quoted(scene), job, more));
    EXPECT_EQ(distributed.exitCode, 0) << distributed.err;
    if (alone.exitCode != 0 || distributed.exitCode != 0) return distributed;

    const std::string jobCsv = slurp(job / "sweep.csv");
    expectSameTableButTimes(slurp(single / "sweep.csv"), jobCsv);
    expectParetoOfItsOwnTimes(jobCsv);
    EXPECT_EQ(summaryButTimes(job / "sweep.json"), summaryButTimes(single / "sweep.json"));
    const std::string reference = slurp(job / "reference.png");
    EXPECT_FALSE(reference.empty());
    EXPECT_TRUE(reference == slurp(single / "reference.png"));
    for (const char* plot : {"time-vs-error.png", "error-vs-depth.png", "error-vs-threshold.png"})
      EXPECT_GT(fs::file_size(job / plot), 0u) << plot;
    return distributed;
  }

  test::ScratchDir scratch_;
  const fs::path dir_ = scratch_.path();
};

TEST_F(MpiSweep, TwoProcessesWriteTheSingleProcessSweepButItsTimes) {
  const fs::path scene = write("small.sc", kScene);
  const RunResult job = expectSameSweep(2, scene, " -q");
  // -q: nothing from any process, and nothing from mpirun.
  EXPECT_EQ(job.err, "");
  EXPECT_EQ(job.out, "");
}

TEST_F(MpiSweep, ThreeProcessesWriteTheSingleProcessSweepAndRank0AloneSpeaks) {
  const fs::path scene = write("small.nff", kSceneWithWarning);
  const RunResult job = expectSameSweep(3, scene, "");
  // Every process read the scene; its warning is printed once, as is the
  // summary.
  EXPECT_EQ(countOf(job.err, "small.nff:1:1: warning: no view"), 1u) << job.err;
  EXPECT_EQ(countOf(job.err, "written "), 1u) << job.err;
  EXPECT_EQ(countOf(job.err, "Pareto front"), 1u) << job.err;
  // The groups of settings each process rendered: three processes, every
  // group once.
  const std::regex line(
      "processes +3, groups of settings rendered by each: (\\d+), (\\d+), (\\d+)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(job.err, match, line)) << job.err;
  EXPECT_EQ(std::stoi(match[1]) + std::stoi(match[2]) + std::stoi(match[3]), kGroups);
}

TEST_F(MpiSweep, SceneErrorExitsWith2AndIsReportedOnce) {
  const fs::path bad = write("bad.sc", kBadScene);
  const fs::path out = dir_ / "results";
  const RunResult job = run(sweepCommand(test::mpirunPrefix(2), quoted(bad), out, " -q"));
  EXPECT_EQ(job.exitCode, 2) << job.err;
  EXPECT_EQ(countOf(job.err, kBadSceneError), 1u) << job.err;
  EXPECT_EQ(countOf(job.err, "prism: error"), 0u) << job.err; // the scene's error is all
  EXPECT_FALSE(fs::exists(out));                              // a scene error leaves no folder
}

// Rank 1 alone reads a bad scene (as a host whose copy of the file is
// broken would): rank 0 reports it once, and every process ends with 2,
// rank 0 included, although its scene was good. Each process's status is
// written by a wrapper that itself exits 0, so that mpirun ends no process
// early.
TEST_F(MpiSweep, SceneErrorOnOneRankEndsEveryRankWith2ReportedOnceByRank0) {
  const fs::path good = write("small.sc", kScene), bad = write("bad.sc", kBadScene);
  const fs::path out = dir_ / "results";
  const fs::path script =
      write("rank.sh", "if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then scene=" + quoted(bad) +
                           "; else scene=" + quoted(good) + "; fi\n" +
                           sweepCommand("", "\"$scene\"", out, " -q") + "\necho $? > " +
                           quoted(dir_) + "/status.$OMPI_COMM_WORLD_RANK\n");

  const RunResult job = run(test::mpirunPrefix(2) + "sh " + quoted(script));
  EXPECT_EQ(job.exitCode, 0) << job.err; // the wrappers'
  EXPECT_EQ(slurp(dir_ / "status.0"), "2\n");
  EXPECT_EQ(slurp(dir_ / "status.1"), "2\n");
  EXPECT_EQ(countOf(job.err, "prism: error: on rank 1:\n" + bad.string() + ":2:14: error:"), 1u)
      << job.err;
  EXPECT_EQ(countOf(job.err, kBadSceneError), 1u) << job.err;
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
}

TEST_F(MpiSweep, OutputThatIsAFileExitsWith1AndIsReportedOnce) {
  const fs::path scene = write("small.sc", kScene);
  const fs::path file = write("taken", "not a folder\n");
  const RunResult job = run(sweepCommand(test::mpirunPrefix(2), quoted(scene), file, " -q"));
  EXPECT_EQ(job.exitCode, 1) << job.err;
  EXPECT_EQ(countOf(job.err, "prism: error:"), 1u) << job.err;
  EXPECT_NE(job.err.find(file.string()), std::string::npos) << job.err;
  EXPECT_EQ(slurp(file), "not a folder\n");
}

} // namespace
} // namespace prism

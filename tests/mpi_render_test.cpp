// `mpirun -np N prism render`: the picture (float radiance, bit for bit) and
// the statistics are those of one process for any number of ranks and
// threads; tiles go to whichever rank asks, so a slowed rank does fewer; a
// killed rank ends the job with a message and no picture; a scene error is
// reported once with the usage status (docs/distributed.md).
#include "tests/mpi_run.h"
#include "tests/test_files.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace prism::test {
namespace {

std::optional<std::vector<float>> readRadiance(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return std::nullopt;
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) *
                            std::size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    return std::nullopt;
  return pixels;
}

class MpiRender : public ::testing::Test {
protected:
  void SetUp() override {
    ASSERT_FALSE(mpirunOnPath().empty())
        << "mpirun is not on PATH: the MPI tests need Open MPI's launcher (openmpi-bin)";
  }
  ScratchDir dir_;
  std::string scene(const std::string& name) const {
    return quoted(fs::path(PRISM_SOURCE_DIR) / "scenes" / name);
  }
  // `prism render SCENE ARGS` on `ranks` processes (0: no mpirun), writing
  // OUT.tiff (float radiance) and OUT.json.
  RunResult render(int ranks, const std::string& out, const std::string& args,
                   const std::string& env = "") {
    const std::string launcher = ranks > 0 ? mpirunPrefix(ranks) : "";
    return run(dir_.path(), env + launcher + quoted(PRISM_BINARY) + " render " + args + " -o " +
                                quoted(dir_ / (out + ".tiff")) + " --float --stats-json " +
                                quoted(dir_ / (out + ".json")));
  }
  nlohmann::json stats(const std::string& out) const {
    return nlohmann::json::parse(slurp(dir_ / (out + ".json")));
  }
};

// What must not depend on the number of processes.
void expectSameRender(const nlohmann::json& one, const nlohmann::json& many) {
  EXPECT_EQ(one["rays"], many["rays"]);
  EXPECT_EQ(one["tir_events"], many["tir_events"]);
  EXPECT_EQ(one["bailout_skipped"], many["bailout_skipped"]);
  EXPECT_EQ(one["avgmax"], many["avgmax"]); // a double, compared exactly
  EXPECT_EQ(one["supersampled_pixels"], many["supersampled_pixels"]);
}

TEST_F(MpiRender, EveryRankAndThreadCountGivesTheOneProcessPictureBitForBit) {
  // 100 x 76 in 32-pixel tiles: 4 x 3 tiles, the last column and row narrow.
  const std::string args = scene("glass.sc") + " --size 100 76 -q";
  const RunResult one = render(0, "one", args + " --threads 2");
  ASSERT_EQ(one.exitCode, 0) << one.err;
  const auto reference = readRadiance(dir_ / "one.tiff");
  ASSERT_TRUE(reference);
  for (const auto& [ranks, threads] : {std::pair{2, 1}, {3, 2}, {4, 1}}) {
    const std::string name = "np" + std::to_string(ranks);
    const RunResult many = render(ranks, name, args + " --threads " + std::to_string(threads));
    ASSERT_EQ(many.exitCode, 0) << many.err;
    EXPECT_EQ(readRadiance(dir_ / (name + ".tiff")), reference) << ranks << " ranks";
    const nlohmann::json s = stats(name);
    expectSameRender(stats("one"), s);
    // One entry per rank; every tile of both passes ran exactly once.
    ASSERT_EQ(s["ranks"].size(), std::size_t(ranks));
    int tiles = 0;
    for (const auto& r : s["ranks"]) {
      tiles += r["tiles"].get<int>();
      EXPECT_EQ(r["threads"], threads);
      EXPECT_GT(r["cpu_seconds"].get<double>(), 0.0);
    }
    EXPECT_EQ(tiles, 2 * 12);
    EXPECT_GT(s["load_balance"].get<double>(), 0.0);
    EXPECT_LE(s["load_balance"].get<double>(), 1.0);
  }
}

// Without antialiasing, and with the bailout (whose pilot pass is a third
// hand-out of tiles and a second exact sum), the same holds.
TEST_F(MpiRender, NoAntialiasingAndTheBailoutAreTheOneProcessPictureToo) {
  for (const std::string& option : {std::string("--no-aa"), std::string("--bailout 1")}) {
    const std::string args = scene("chex.sc") + " --size 90 64 -q --threads 1 " + option;
    ASSERT_EQ(render(0, "one", args).exitCode, 0);
    const RunResult many = render(3, "np3", args);
    ASSERT_EQ(many.exitCode, 0) << many.err;
    EXPECT_EQ(readRadiance(dir_ / "np3.tiff"), readRadiance(dir_ / "one.tiff")) << option;
    expectSameRender(stats("one"), stats("np3"));
  }
}

// Rank 1 waits 40 ms after each tile: the tiles are handed out on request,
// so rank 0 does most of them, and the picture is unchanged.
TEST_F(MpiRender, ASlowRankIsGivenFewerTiles) {
  const std::string args = scene("chex.sc") + " --size 128 128 --no-aa -q --threads 1";
  ASSERT_EQ(render(0, "one", args).exitCode, 0);
  const RunResult many = render(2, "slow", args, "PRISM_MPI_SIMULATE=rank=1,tile_delay_ms=40 ");
  ASSERT_EQ(many.exitCode, 0) << many.err;
  EXPECT_EQ(readRadiance(dir_ / "slow.tiff"), readRadiance(dir_ / "one.tiff"));
  const nlohmann::json s = stats("slow");
  ASSERT_EQ(s["ranks"].size(), 2u);
  const int fast = s["ranks"][0]["tiles"], slow = s["ranks"][1]["tiles"];
  EXPECT_EQ(fast + slow, 16);
  EXPECT_GT(fast, slow) << "rank 0 did " << fast << " tiles, the slowed rank 1 " << slow;
}

// Rank 0 takes 2.5 seconds over each tile: the first, which it always gives
// itself, and the one it queues behind it; rank 1 does the rest meanwhile
// (62 tiles, which once took more than 2 seconds under the sanitizers beside
// other tests: with 1 second a tile, rank 0 then took a third). Rank 0's main
// thread, answering rank 1's requests, sleeps between polls: its CPU time is
// a small part of that time, not all of it (as a spinning wait would make it).
TEST_F(MpiRender, WaitingForWorkOrRequestsSleepsInsteadOfSpinning) {
  const std::string args = scene("chex.sc") + " --size 256 256 --no-aa -q --threads 1";
  const RunResult slow = render(2, "slow", args, "PRISM_MPI_SIMULATE=rank=0,tile_delay_ms=2500 ");
  ASSERT_EQ(slow.exitCode, 0) << slow.err;
  const nlohmann::json s = stats("slow");
  ASSERT_EQ(s["ranks"].size(), 2u);
  const int slowTiles = s["ranks"][0]["tiles"];
  EXPECT_GE(slowTiles, 1);
  EXPECT_LE(slowTiles, 2);
  EXPECT_EQ(s["ranks"][1]["tiles"].get<int>(), 64 - slowTiles);
  EXPECT_GE(s["wall_seconds"].get<double>(), 2.5);
  EXPECT_LT(s["ranks"][0]["cpu_seconds"].get<double>(), 0.25 * s["wall_seconds"].get<double>());
}

// Rank 1 dies (SIGKILL) after its second tile: the job ends, not hangs, with
// a non-zero status and mpirun's message naming the rank, and leaves no
// picture and no statistics.
TEST_F(MpiRender, AKilledRankEndsTheJobWithAMessageAndNoFiles) {
  const std::string args = scene("glass.sc") + " --size 160 120 -q --threads 1";
  const RunResult killed =
      render(2, "killed", args, "PRISM_MPI_SIMULATE=rank=1,die_after_tiles=2 ");
  EXPECT_NE(killed.exitCode, 0);
  EXPECT_NE(killed.exitCode, 124) << "the job hung until the timeout";
  EXPECT_NE((killed.out + killed.err).find("rank 1"), std::string::npos) << killed.err;
  EXPECT_FALSE(fs::exists(dir_ / "killed.tiff"));
  EXPECT_FALSE(fs::exists(dir_ / "killed.json"));
  for (const auto& entry : fs::directory_iterator(dir_.path()))
    EXPECT_EQ(entry.path().filename().string().find("killed"), std::string::npos)
        << "a leftover: " << entry.path();
}

// Ctrl-C on mpirun once both ranks run (rank 0 is slowed to five seconds a
// tile, so the render is far from done): every rank ends within seconds, the
// status is not success, and nothing is written.
TEST_F(MpiRender, CtrlCOnMpirunStopsEveryRankAndWritesNothing) {
  const fs::path out = dir_ / "interrupted.tiff";
  const std::string ranks = std::string("^") + PRISM_BINARY + " render .*" + out.string();
  const std::string script = "PRISM_MPI_SIMULATE=rank=0,tile_delay_ms=5000 " + mpirunPrefix(2) +
                             quoted(PRISM_BINARY) + " render " + scene("glass.sc") +
                             " --size 320 240 --threads 1 -q -o " + quoted(out) +
                             " & job=$!\n"
                             // Until both ranks exist (at most 60 s).
                             "i=0; while [ \"$(pgrep -c -f '" +
                             ranks +
                             "')\" -lt 2 ] && [ $i -lt 1200 ]; do\n"
                             "  sleep 0.05; i=$((i+1)); done\n"
                             "echo \"ranks seen: $(pgrep -c -f '" +
                             ranks +
                             "')\"\n"
                             "kill -INT $job\n"
                             "wait $job; echo \"status $?\"\n"
                             // mpirun may return while its ranks are still being ended: until
                             // none is left (at most 10 s).
                             "i=0; while [ \"$(pgrep -c -f '" +
                             ranks +
                             "')\" -gt 0 ] && [ $i -lt 200 ]; do\n"
                             "  sleep 0.05; i=$((i+1)); done\n"
                             "echo \"ranks left: $(pgrep -c -f '" +
                             ranks + "')\"\n";
  writeFile(dir_ / "interrupt.sh", script);
  const RunResult run = test::run(dir_.path(), "sh " + quoted(dir_ / "interrupt.sh"));
  EXPECT_NE(run.out.find("ranks seen: 2"), std::string::npos) << run.out << run.err;
  const std::size_t at = run.out.find("status ");
  ASSERT_NE(at, std::string::npos) << run.out;
  const int status = std::stoi(run.out.substr(at + 7));
  EXPECT_NE(status, 0);
  EXPECT_NE(status, 124) << "the job hung until the timeout";
  EXPECT_NE(run.out.find("ranks left: 0"), std::string::npos) << run.out;
  for (const auto& entry : fs::directory_iterator(dir_.path()))
    EXPECT_EQ(entry.path().filename().string().find("interrupted"), std::string::npos)
        << "a leftover: " << entry.path();
}

// Every rank reads the scene and fails the same way; only rank 0 says so,
// and the job's status is the usage status of a single process.
TEST_F(MpiRender, ASceneErrorIsReportedOnceWithStatusTwo) {
  writeFile(dir_ / "bad.sc", "eye 0 0 5\nsphere 0 0 0 oops\n");
  const RunResult bad = render(3, "bad", quoted(dir_ / "bad.sc") + " -q");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  const std::string where = "bad.sc:2:";
  const std::size_t first = bad.err.find(where);
  ASSERT_NE(first, std::string::npos) << bad.err;
  EXPECT_EQ(bad.err.find(where, first + 1), std::string::npos) << "reported twice:\n" << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.tiff"));
}

// An output rank 0 cannot write stops every rank before any work, once.
TEST_F(MpiRender, AnUnwritableOutputStopsEveryRankBeforeTheRender) {
  const RunResult unwritable =
      run(dir_.path(), mpirunPrefix(2) + quoted(PRISM_BINARY) + " render " + scene("glass.sc") +
                           " -o " + quoted(dir_ / "no" / "such" / "dir" / "x.tiff") + " -q");
  EXPECT_EQ(unwritable.exitCode, 1) << unwritable.err;
  const std::size_t first = unwritable.err.find("prism: error:");
  ASSERT_NE(first, std::string::npos) << unwritable.err;
  EXPECT_EQ(unwritable.err.find("prism: error:", first + 1), std::string::npos) << unwritable.err;
}

// srun starting several tasks with no MPI process manager would make each
// render the whole picture into the same file: refused, saying what to run.
TEST_F(MpiRender, SrunWithoutAnMpiProcessManagerIsRefused) {
  const RunResult refused =
      render(0, "srun", scene("table.sc") + " --size 16 12 -q", "SLURM_STEP_NUM_TASKS=4 ");
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("srun --mpi=pmix"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir_ / "srun.tiff"));
  // One task is a plain run.
  EXPECT_EQ(
      render(0, "one", scene("table.sc") + " --size 16 12 -q", "SLURM_STEP_NUM_TASKS=1 ").exitCode,
      0);
}

// MPI costs nothing where it is not used: a render started without a
// launcher loads neither the MPI module nor libmpi (the dynamic loader's
// own log says what it loads); under mpirun, even of one rank, it loads both.
TEST_F(MpiRender, OnlyARenderStartedByALauncherLoadsMpi) {
  const std::string args = scene("table.sc") + " --size 16 12 -q";
  const RunResult plain = render(0, "plain", args, "LD_DEBUG=files ");
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_NE(plain.err.find("file=libtiff"), std::string::npos) << "no loader log:\n" << plain.err;
  EXPECT_EQ(plain.err.find("libprism_mpi"), std::string::npos);
  EXPECT_EQ(plain.err.find("libmpi"), std::string::npos);
  const RunResult launched = render(1, "launched", args, "LD_DEBUG=files ");
  ASSERT_EQ(launched.exitCode, 0) << launched.err;
  EXPECT_NE(launched.err.find("libprism_mpi.so"), std::string::npos);
  EXPECT_NE(launched.err.find("libmpi.so"), std::string::npos);
}

} // namespace
} // namespace prism::test

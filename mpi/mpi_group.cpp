// The ProcessGroup of an MPI job, and the module's entry (mpi/mpi_module.h).
#include "mpi/mpi_executor.h"
#include "mpi/mpi_module.h"
#include "mpi/work_dispenser.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>

namespace prism::mpi {

namespace {

class MpiGroup final : public ProcessGroup {
public:
  MpiGroup() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiGroup() override { MPI_Finalize(); }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::unique_ptr<DistributedExecutor> makeExecutor(Executor& local) override {
    return std::make_unique<MpiExecutor>(local, rank_, size_, calls_);
  }

  std::optional<Failure> firstFailure(bool ok, const std::string& message) override {
    int first = ok ? size_ : rank_;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == size_) return std::nullopt;
    Failure failure{first, rank_ == first ? message : std::string()};
    int length = int(failure.message.size());
    MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
    failure.message.resize(std::size_t(length));
    MPI_Bcast(failure.message.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
    return failure;
  }

  std::vector<RankStats> gatherStats(const RankStats& mine) override {
    struct Packed {
      char host[256];
      int threads, tiles;
      std::uint64_t rays;
      double cpuSeconds;
    } packed{};
    std::snprintf(packed.host, sizeof packed.host, "%s", mine.host.c_str());
    packed.threads = mine.threads;
    packed.tiles = mine.tiles;
    packed.rays = mine.rays;
    packed.cpuSeconds = mine.cpuSeconds;
    std::vector<Packed> all(rank_ == 0 ? std::size_t(size_) : 0);
    MPI_Gather(&packed, int(sizeof packed), MPI_BYTE, all.data(), int(sizeof packed), MPI_BYTE, 0,
               MPI_COMM_WORLD);
    std::vector<RankStats> stats;
    for (std::size_t r = 0; r < all.size(); ++r)
      stats.push_back(
          {int(r), all[r].host, all[r].threads, all[r].tiles, all[r].rays, all[r].cpuSeconds});
    return stats;
  }

  std::vector<std::string> distribute(int count, const std::function<std::string(int)>& work,
                                      const DistributeProgress& progress) override {
    // Each process runs one item at a time (an item uses all its threads).
    std::map<int, std::string> results;
    WorkDispenser dispenser(rank_, size_, calls_++);
    try {
      dispenser.run(
          count, 1,
          [&](ItemQueue& queue) {
            for (int item = queue.take(); item >= 0; item = queue.take()) {
              results[item] = work(item);
              queue.finished();
            }
          },
          progress);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "prism: error: rank %d: %s\n", rank_, error.what());
      abort(1);
    }
    // Gathered as (item, length, text) records.
    std::string packed;
    for (const auto& [item, text] : results) {
      const int header[2] = {item, int(text.size())};
      packed.append(reinterpret_cast<const char*>(header), sizeof header);
      packed += text;
    }
    int length = int(packed.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(lengths.size());
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
      for (std::size_t r = 0, at = 0; r < lengths.size(); at += std::size_t(lengths[r]), ++r)
        offsets[r] = int(at);
      all.resize(std::size_t(offsets.back() + lengths.back()));
    }
    MPI_Gatherv(packed.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
    std::vector<std::string> ordered(rank_ == 0 ? std::size_t(count) : 0);
    for (std::size_t at = 0; at < all.size();) {
      int header[2];
      std::memcpy(header, all.data() + at, sizeof header);
      at += sizeof header;
      ordered[std::size_t(header[0])] = all.substr(at, std::size_t(header[1]));
      at += std::size_t(header[1]);
    }
    return ordered;
  }

  [[noreturn]] void abort(int status) override {
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status); // MPI_Abort does not return; if it did, neither do we
  }

private:
  int rank_ = 0, size_ = 1;
  int calls_ = 0; // collective hand-outs so far (their messages' tags)
};

} // namespace

} // namespace prism::mpi

extern "C" __attribute__((visibility("default"))) prism::ProcessGroup*
prism_mpi_start(char* error, std::size_t errorSize) {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::snprintf(error, errorSize, "MPI_Init_thread failed");
    return nullptr;
  }
  if (provided < MPI_THREAD_FUNNELED) {
    std::snprintf(error, errorSize, "this MPI library gives no thread support (FUNNELED needed)");
    MPI_Finalize();
    return nullptr;
  }
  try {
    return new prism::mpi::MpiGroup();
  } catch (const std::exception& e) {
    std::snprintf(error, errorSize, "%s", e.what());
    return nullptr;
  }
}

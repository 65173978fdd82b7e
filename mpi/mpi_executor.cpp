#include "mpi/mpi_executor.h"

#include "mpi/work_dispenser.h"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

namespace prism::mpi {

namespace {

// MPI counts are ints: large buffers go in parts.
constexpr std::size_t kMaxPart = std::size_t(1) << 26;

void allreduceInPlace(void* data, std::size_t count, MPI_Datatype type, std::size_t typeSize,
                      MPI_Op op) {
  auto* bytes = static_cast<unsigned char*>(data);
  for (std::size_t done = 0; done < count; done += kMaxPart) {
    const int part = int(std::min(kMaxPart, count - done));
    MPI_Allreduce(MPI_IN_PLACE, bytes + done * typeSize, part, type, op, MPI_COMM_WORLD);
  }
}

void reduceToRoot(void* data, std::size_t count, MPI_Datatype type, std::size_t typeSize, MPI_Op op,
                  int rank) {
  auto* bytes = static_cast<unsigned char*>(data);
  for (std::size_t done = 0; done < count; done += kMaxPart) {
    const int part = int(std::min(kMaxPart, count - done));
    void* at = bytes + done * typeSize;
    MPI_Reduce(rank == 0 ? MPI_IN_PLACE : at, rank == 0 ? at : nullptr, part, type, op, 0,
               MPI_COMM_WORLD);
  }
}

// The tiles as the grid makeTiles lays out: row-major, equal sizes but for
// the last column and row.
class TileGrid {
public:
  explicit TileGrid(std::span<const Tile> tiles) : tiles_(tiles) {
    while (columns_ < int(tiles.size()) && tiles[std::size_t(columns_)].y0 == tiles[0].y0)
      ++columns_;
  }

  enum Side { Left, Right, Up, Down };

  // The tile across `side` of tile t, or -1 at the picture's edge.
  int neighbour(int t, Side side) const {
    const int column = t % columns_, count = int(tiles_.size());
    int u = -1;
    switch (side) {
    case Left: u = column > 0 ? t - 1 : -1; break;
    case Right: u = column + 1 < columns_ && t + 1 < count ? t + 1 : -1; break;
    case Up: u = t - columns_; break;
    case Down: u = t + columns_ < count ? t + columns_ : -1; break;
    }
    if (u < 0) return -1;
    const Tile &a = tiles_[std::size_t(t)], &b = tiles_[std::size_t(u)];
    const bool adjacent = side == Left    ? b.x1 == a.x0 && b.y0 == a.y0
                          : side == Right ? b.x0 == a.x1 && b.y0 == a.y0
                          : side == Up    ? b.y1 == a.y0 && b.x0 == a.x0
                                          : b.y0 == a.y1 && b.x0 == a.x0;
    if (!adjacent) throw std::logic_error("the tiles are not a row-major grid");
    return u;
  }

  // Calls visit(x, y) for the pixels of tile t along `side`: those its
  // neighbour there reads.
  template <class Visit> void forEdge(int t, Side side, Visit visit) const {
    const Tile& a = tiles_[std::size_t(t)];
    if (side == Left || side == Right) {
      const int x = side == Left ? a.x0 : a.x1 - 1;
      for (int y = a.y0; y < a.y1; ++y)
        visit(x, y);
    } else {
      const int y = side == Up ? a.y0 : a.y1 - 1;
      for (int x = a.x0; x < a.x1; ++x)
        visit(x, y);
    }
  }

  int size() const { return int(tiles_.size()); }

private:
  std::span<const Tile> tiles_;
  int columns_ = 0;
};

constexpr TileGrid::Side kSides[] = {TileGrid::Left, TileGrid::Right, TileGrid::Up, TileGrid::Down};

} // namespace

SimulatedFault SimulatedFault::fromEnvironment() {
  SimulatedFault fault;
  const char* text = std::getenv("PRISM_MPI_SIMULATE");
  if (!text) return fault;
  std::istringstream in(text);
  std::string field;
  while (std::getline(in, field, ',')) {
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = field.substr(0, eq);
    const int value = std::atoi(field.c_str() + eq + 1);
    if (key == "rank") fault.rank = value;
    if (key == "tile_delay_ms") fault.tileDelayMs = value;
    if (key == "die_after_tiles") fault.dieAfterTiles = value;
  }
  return fault;
}

void MpiExecutor::forEach(int itemCount, const ItemWork& work, const StopCheck& stop) {
  WorkDispenser dispenser(rank_, size_, calls_++);
  std::atomic<int> ran{0};
  const int workers = local_.workers();
  try {
    dispenser.run(
        itemCount, workers,
        [&](ItemQueue& queue) {
          // Each of the local workers takes items until the queue is
          // exhausted: at most itemCount of them and one -1 each.
          local_.forEach(
              itemCount + workers,
              [&](int, int worker) {
                const int item = queue.take();
                if (item < 0) return;
                work(item, worker);
                const int ranHere = itemsRun_ + ++ran;
                if (fault_.rank == rank_) {
                  if (fault_.tileDelayMs > 0)
                    std::this_thread::sleep_for(std::chrono::milliseconds(fault_.tileDelayMs));
                  if (fault_.dieAfterTiles > 0 && ranHere >= fault_.dieAfterTiles)
                    std::raise(SIGKILL);
                }
                queue.finished();
              },
              [&] { return (stop && stop()) || queue.exhausted(); });
        },
        [&](int done, int total) {
          if (progress_) progress_(pass_, total > 0 ? double(done) / double(total) : 1.0);
        });
  } catch (const std::exception& error) {
    // The other processes wait for this one's items: only ending the whole
    // job stops them.
    std::fprintf(stderr, "prism: error: rank %d: %s\n", rank_, error.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  itemsRun_ += ran;
}

void MpiExecutor::sumOverProcesses(ExactSum& sum) {
  MPI_Allreduce(MPI_IN_PLACE, sum.data(), ExactSum::kBins, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
}

void MpiExecutor::completePass1(Film& film, std::span<const Tile> tiles,
                                const std::vector<std::uint8_t>& traced) {
  pass_ = 2;
  const TileGrid grid(tiles);
  std::vector<int> owner(tiles.size());
  for (std::size_t t = 0; t < tiles.size(); ++t)
    owner[t] = traced[t] != 0 ? rank_ : -1;
  MPI_Allreduce(MPI_IN_PLACE, owner.data(), int(owner.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);

  // What goes to each process: for each tile traced here, in tile order, the
  // edges facing tiles another process traced. The receiver enumerates the
  // same (tile, side) pairs in the same order, so no positions travel.
  const auto ranks = static_cast<std::size_t>(size_);
  std::vector<std::vector<float>> out(ranks), in(ranks);
  for (int t = 0; t < grid.size(); ++t) {
    const int from = owner[std::size_t(t)];
    for (const TileGrid::Side side : kSides) {
      const int u = grid.neighbour(t, side);
      if (u < 0) continue;
      const int to = owner[std::size_t(u)];
      if (from == to || from < 0 || to < 0) continue;
      if (from == rank_) {
        grid.forEdge(t, side, [&](int x, int y) {
          const Rgb& c = film.centre[film.index(x, y)];
          out[std::size_t(to)].insert(out[std::size_t(to)].end(), {c.r, c.g, c.b});
        });
      } else if (to == rank_) {
        grid.forEdge(t, side, [&](int, int) {
          in[std::size_t(from)].resize(in[std::size_t(from)].size() + 3);
        });
      }
    }
  }
  std::vector<int> sendCounts(ranks), sendOffsets(ranks), receiveCounts(ranks),
      receiveOffsets(ranks);
  std::vector<float> sendBuffer, receiveBuffer;
  for (std::size_t r = 0; r < ranks; ++r) {
    sendOffsets[r] = int(sendBuffer.size());
    sendCounts[r] = int(out[r].size());
    sendBuffer.insert(sendBuffer.end(), out[r].begin(), out[r].end());
    receiveOffsets[r] = int(receiveBuffer.size());
    receiveCounts[r] = int(in[r].size());
    receiveBuffer.resize(receiveBuffer.size() + in[r].size());
  }
  MPI_Alltoallv(sendBuffer.data(), sendCounts.data(), sendOffsets.data(), MPI_FLOAT,
                receiveBuffer.data(), receiveCounts.data(), receiveOffsets.data(), MPI_FLOAT,
                MPI_COMM_WORLD);

  std::vector<std::size_t> at(receiveOffsets.begin(), receiveOffsets.end());
  for (int t = 0; t < grid.size(); ++t) {
    const int from = owner[std::size_t(t)];
    if (from == rank_ || from < 0) continue;
    for (const TileGrid::Side side : kSides) {
      const int u = grid.neighbour(t, side);
      if (u < 0 || owner[std::size_t(u)] != rank_) continue;
      grid.forEdge(t, side, [&](int x, int y) {
        std::size_t& i = at[std::size_t(from)];
        film.centre[film.index(x, y)] =
            Rgb(receiveBuffer[i], receiveBuffer[i + 1], receiveBuffer[i + 2]);
        i += 3;
      });
    }
  }
}

void MpiExecutor::shareMarks(std::vector<std::uint8_t>& marks) {
  std::vector<std::uint64_t> bits((marks.size() + 63) / 64, 0);
  for (std::size_t i = 0; i < marks.size(); ++i)
    if (marks[i] != 0) bits[i / 64] |= std::uint64_t(1) << (i % 64);
  allreduceInPlace(bits.data(), bits.size(), MPI_UINT64_T, sizeof(std::uint64_t), MPI_BOR);
  for (std::size_t i = 0; i < marks.size(); ++i)
    marks[i] = std::uint8_t((bits[i / 64] >> (i % 64)) & 1);
  marks_ = marks;
}

void MpiExecutor::completeRender(Film& film, RayCounts& counts) {
  // A pixel's value lives on one process: where its centre was traced, or,
  // if marked, where pass 2 supersampled it. Zero it everywhere else, and
  // the sum over processes is that value exactly.
  for (std::size_t i = 0; i < marks_.size(); ++i)
    if (marks_[i] != 0 && film.supersampled[i] == 0) film.radiance[i] = Rgb(0.0f);
  static_assert(sizeof(Rgb) == 3 * sizeof(float));
  reduceToRoot(film.radiance.data(), 3 * film.radiance.size(), MPI_FLOAT, sizeof(float), MPI_SUM,
               rank_);
  if (rank_ == 0) {
    if (marks_.empty())
      std::fill(film.supersampled.begin(), film.supersampled.end(), std::uint8_t(0));
    else
      film.supersampled = marks_;
  }

  raysHere_ = counts.total();
  static_assert(sizeof(RayCounts) == 9 * sizeof(std::uint64_t));
  reduceToRoot(&counts, 9, MPI_UINT64_T, sizeof(std::uint64_t), MPI_SUM, rank_);
}

} // namespace prism::mpi

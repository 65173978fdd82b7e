#include "core/render/pass_schedule.h"

#include "core/render/bailout.h"
#include "core/render/tracer.h"

#include <algorithm>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>

namespace prism {

PassSchedule::PassSchedule(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                           int coarsestLevel)
    : scene_(scene), accel_(accel), settings_(settings), coarsestLevel_(coarsestLevel),
      camera_(scene.camera, settings.width, settings.height),
      tiles_(makeTiles(settings.width, settings.height, settings.tileSize)) {
  if (coarsestLevel < 1 || (coarsestLevel & (coarsestLevel - 1)) != 0)
    throw std::invalid_argument("the first level of a pass schedule must be a power of two, not " +
                                std::to_string(coarsestLevel));
}

class PassSchedule::Run {
public:
  Run(const PassSchedule& schedule, Film& film, Executor& executor, ScheduleSink& sink,
      const StopCheck& stop)
      : s_(schedule), film_(film), executor_(executor), sink_(sink), stop_(stop),
        counts_(std::size_t(executor.workers())), traced_(std::size_t(schedule.tileCount()), 0) {
    if (s_.settings_.bailout > 0.0) {
      bound_.beyond = radianceBounds(s_.scene_, s_.settings_.maxDepth);
      // Where no ray could be skipped the exact trace is the same picture,
      // without the pilot's cost.
      if (!bailoutCanSkip(s_.scene_, bound_.beyond, s_.settings_.bailout)) bound_.beyond.clear();
    }
  }

  bool bailingOut() const { return bound_.active(); }
  // Sets the radiance the bailout may skip per sample from a lower bound on
  // the avgmax the picture will be exposed by.
  void allowFor(double avgmax) {
    bound_.allowance = bailoutAllowance(s_.settings_.bailout, avgmax);
  }

  // The bailout's lower bound on pass 1's avgmax, before pass 1: the avgmax
  // of a depth-1 trace of every pixel centre. Each pass-1 sample holds its
  // depth-1 terms computed the same way, plus non-negative deeper ones, so
  // it is at least that sample channel by channel, and so is the mean of the
  // largest channels (the floats and the sums round monotonically). Its rays
  // are counted as bailoutPilot; its samples go nowhere.
  double pilotAvgmax() {
    std::vector<Rgb> local(film_.pixelCount(), Rgb(0.0f));
    executor_.forEach(
        s_.tileCount(),
        [&](int item, int worker) {
          Tracer tracer(s_.scene_, s_.accel_, 1);
          RayCounts counts;
          std::vector<Sample> samples;
          for (const Tile& block : splitTile(s_.tiles_[std::size_t(item)], kBundleSide)) {
            if (stopped()) return;
            Pixel pixels[Accel::kMaxBundle];
            std::size_t n = 0;
            for (int y = block.y0; y < block.y1; ++y)
              for (int x = block.x0; x < block.x1; ++x)
                pixels[n++] = {x, y};
            tracePixelCentres(tracer, s_.camera_, std::span(pixels, n), samples, counts);
          }
          for (const Sample& sample : samples)
            local[film_.index(sample.x, sample.y)] = sample.radiance;
          counts_[std::size_t(worker)].bailoutPilot += counts.total();
        },
        stop_);
    ExactSum sum = sumOfMaxima(local); // 0 where another process traced
    executor_.sumOverProcesses(sum);
    return averageMax(sum, local.size());
  }

  bool stopped() const { return stop_ && stop_(); }

  // Pass 1's coarse `level`: the centres new at this level. Any
  // kBundleSide * level consecutive pixels hold kBundleSide multiples of
  // `level`, so a block of that side has at most a full bundle of new
  // pixels; at level 1 of a one-level schedule they are render()'s 8x8
  // bundles.
  void traceLevel(int level) {
    sink_.levelStarted(level);
    forEachTile(
        1, level, kBundleSide * level, [&](Tracer& tracer, const Tile& block, TileSamples& out) {
          Pixel pixels[Accel::kMaxBundle];
          std::size_t n = 0;
          for (int y = block.y0; y < block.y1; ++y)
            for (int x = block.x0; x < block.x1; ++x)
              if (isNewAtLevel(x, y, level, s_.coarsestLevel_)) pixels[n++] = {x, y};
          tracePixelCentres(tracer, s_.camera_, std::span(pixels, n), out.samples, out.counts);
        });
  }

  // The previewer's Pass1::Keep: the film holds every centre already.
  void keepPass1() {
    std::fill(traced_.begin(), traced_.end(), std::uint8_t(1));
    film_.radiance = film_.centre;
    std::fill(film_.supersampled.begin(), film_.supersampled.end(), std::uint8_t(0));
  }

  // Reduction point 1, then avgmax: the exact sum of the maxima of the
  // centres this process traced, plus the other processes' parts.
  double completePass1() {
    ExactSum sum;
    for (std::size_t t = 0; t < traced_.size(); ++t) {
      if (traced_[t] == 0) continue;
      const Tile& tile = s_.tiles_[t];
      for (int y = tile.y0; y < tile.y1; ++y)
        sum += sumOfMaxima(std::span(film_.centre)
                               .subspan(film_.index(tile.x0, y), std::size_t(tile.x1 - tile.x0)));
    }
    executor_.sumOverProcesses(sum);
    // The ring of neighbours is for pass 2's decisions only.
    if (!s_.settings_.noAa) executor_.completePass1(film_, s_.tiles_, traced_);
    return averageMax(sum, film_.pixelCount());
  }

  // Pass 2's decisions for the tiles traced here (they read the centres
  // around them), then shared: pass 2 may run any tile anywhere.
  void decide(double avgmax) {
    marks_.assign(film_.pixelCount(), 0);
    std::vector<int> here;
    for (std::size_t t = 0; t < traced_.size(); ++t)
      if (traced_[t] != 0) here.push_back(int(t));
    executor_.forEachHere(
        int(here.size()),
        [&](int item, int) {
          markForSupersampling(s_.tiles_[std::size_t(here[std::size_t(item)])], film_, avgmax,
                               s_.settings_.thresh, marks_);
        },
        stop_);
    if (!stopped()) executor_.shareMarks(marks_);
    keepMarksInCrop();
  }

  // With a crop, pass 2 outside it is left out: its marks are cleared, on
  // every process alike, after the decisions (which read the whole frame).
  void keepMarksInCrop() {
    const RenderSettings& c = s_.settings_;
    if (c.cropX1 == 0) return;
    for (int y = 0; y < film_.height; ++y)
      for (int x = 0; x < film_.width; ++x)
        if (x < c.cropX0 || x >= c.cropX1 || y < c.cropY0 || y >= c.cropY1)
          marks_[film_.index(x, y)] = 0;
  }

  // Pass 2 in small blocks: a supersampled pixel costs 16 eye rays and their
  // trees, and a cancelling edit should not wait for many of them.
  void antialias() {
    forEachTile(2, 1, 4, [&](Tracer& tracer, const Tile& block, TileSamples& out) {
      antialiasBlock(tracer, s_.camera_, block, film_, marks_, s_.settings_.jitter, out.samples,
                     out.counts);
    });
  }

  // Every ray traced so far, over all workers.
  RayCounts counts() const {
    RayCounts total;
    for (const RayCounts& c : counts_)
      total += c;
    return total;
  }

private:
  using BlockSampler = std::function<void(Tracer&, const Tile& block, TileSamples& out)>;

  // Every tile on the executor, block by block (cancellation is checked
  // between blocks), with a Tracer of the tile's own: it belongs to one
  // thread (core/render/tracer.h). A tile's rays are counted in counts of its
  // own, added to its worker's once: the workers' counts sit side by side in
  // memory, and adding to them ray by ray from two cores would bounce their
  // cache line between the cores.
  void forEachTile(int pass, int level, int blockSide, const BlockSampler& sampleBlock) {
    executor_.forEach(
        s_.tileCount(),
        [&](int item, int worker) {
          const Tile& tile = s_.tiles_[std::size_t(item)];
          Tracer tracer(s_.scene_, s_.accel_, s_.settings_.maxDepth);
          tracer.setBailout(bound_);
          TileSamples out{pass, level, item, {}, {}};
          if (pass == 1)
            out.samples.reserve(std::size_t((tile.x1 - tile.x0 + level - 1) / level) *
                                std::size_t((tile.y1 - tile.y0 + level - 1) / level));
          for (const Tile& block : splitTile(tile, blockSide)) {
            if (stopped()) return;
            sampleBlock(tracer, block, out);
          }
          // All at once: the film never holds a part of a tile, and a
          // tile stopped halfway is dropped whole.
          (pass == 1 ? storeCentres : storeSupersampled)(out.samples, film_);
          if (pass == 1) traced_[std::size_t(item)] = 1;
          counts_[std::size_t(worker)] += out.counts;
          sink_.tileDone(out);
        },
        stop_);
  }

  const PassSchedule& s_;
  Film& film_;
  Executor& executor_;
  ScheduleSink& sink_;
  const StopCheck& stop_;
  std::vector<RayCounts> counts_;    // per worker
  std::vector<std::uint8_t> traced_; // per tile: 1 once its centres are in the film
  std::vector<std::uint8_t> marks_;  // per pixel: 1 where pass 2 supersamples
  BailoutBound bound_;               // inactive unless settings.bailout > 0
};

bool PassSchedule::run(Film& film, Executor& executor, ScheduleSink& sink, const StopCheck& stop,
                       Pass1 pass1) const {
  Run run(*this, film, executor, sink, stop);
  if (pass1 == Pass1::Trace) {
    if (run.bailingOut()) {
      run.allowFor(run.pilotAvgmax());
      if (run.stopped()) return false;
      sink.pilotDone(run.counts());
    }
    for (int level = coarsestLevel_; level >= 1; level /= 2) {
      run.traceLevel(level);
      if (run.stopped()) return false;
    }
  } else {
    run.keepPass1();
  }

  // The same avgmax, bit for bit, for any executor (an exact sum).
  const double avgmax = run.completePass1();
  sink.pass1Complete(avgmax);

  // Pass 2's samples are exposed by this avgmax: their allowance is its W levels.
  run.allowFor(avgmax);
  if (!settings_.noAa) {
    run.decide(avgmax);
    if (run.stopped()) return false;
    run.antialias();
  }
  if (run.stopped()) return false;

  RayCounts counts = run.counts();
  executor.completeRender(film, counts);
  sink.done(counts);
  return true;
}

} // namespace prism

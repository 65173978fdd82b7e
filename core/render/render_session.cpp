#include "core/render/render_session.h"

#include "core/render/image_formation.h"
#include "core/render/parallel.h"
#include "core/render/tracer.h"

#include <condition_variable>
#include <optional>
#include <stdexcept>
#include <string>

namespace prism {

namespace {

constexpr int kCoarsestLevel = 8; // block side of the first preview level
constexpr std::uint8_t kNoSample = 255;

using Clock = std::chrono::steady_clock;

// One pixel-centre sample waiting to be published.
struct Sample {
  std::size_t index;
  Rgb radiance;
};

} // namespace

bool isNewAtLevel(int x, int y, int level) {
  if (x % level != 0 || y % level != 0) return false;
  return level == kCoarsestLevel || x % (2 * level) != 0 || y % (2 * level) != 0;
}

struct RenderSession::Work {
  Work(int w, int h)
      : film(w, h), display(film.pixelCount(), Rgb(0.0f)),
        displayLevel(film.pixelCount(), kNoSample) {}

  Film film;                              // the samples of the final picture
  std::vector<Rgb> display;               // each pixel shows its nearest sample so far
  std::vector<std::uint8_t> displayLevel; // block size of the sample shown; kNoSample: stale
  SessionPhase phase = SessionPhase::Coarse;
  int level = kCoarsestLevel;
  double sumMax = 0.0;       // of max(r,g,b) over traced pixel centres
  double levelsAvgmax = 0.0; // sumMax / pass1Pixels when the last level completed
  long long pass1Pixels = 0;
  double avgmax = 0.0;
  long long supersampled = 0;
  long long pass2TilesDone = 0;
  long long tileCount = 1;
  RayCounts counts;
  RayCounts pass1Counts; // the counts when pass 1 completed, kept by a pass-2-only restart
  Clock::time_point start = Clock::now();
  Clock::time_point end;      // when the render finished: elapsed time stops there
  Clock::time_point pass1End; // when pass 1 was complete (or kept from before)
  bool done = false;
  std::condition_variable doneChanged;
  std::string failure; // why the render stopped early, if it failed
};

RenderSession::RenderSession(Scene scene, const RenderSettings& settings, AccelKind accel)
    : scene_(std::make_unique<Scene>(std::move(scene))), accelKind_(accel), settings_(settings) {
  accel_ = makeAccel(*scene_, accelKind_);
  startWorkers(false);
}

RenderSession::~RenderSession() { stopWorkers(); }

void RenderSession::stopWorkers() {
  cancel_.store(true, std::memory_order_relaxed);
  if (driver_.joinable()) driver_.join();
  cancel_.store(false, std::memory_order_relaxed);
}

void RenderSession::startWorkers(bool keepPass1) {
  auto work = std::make_unique<Work>(settings_.width, settings_.height);
  {
    std::lock_guard lock(mutex_);
    if (work_ && work_->film.width == settings_.width && work_->film.height == settings_.height) {
      // Until the new samples arrive the window keeps showing the old picture
      // (marked stale), rather than flashing black on every drag of a light.
      work->display = work_->display;
      if (keepPass1) {
        work->film.centre = work_->film.centre;
        work->film.radiance = work_->film.centre;
        work->display = work_->film.centre;
        std::fill(work->displayLevel.begin(), work->displayLevel.end(), std::uint8_t(1));
        work->sumMax = work_->sumMax;
        work->levelsAvgmax = work_->levelsAvgmax;
        work->pass1Pixels = work_->pass1Pixels;
        work->counts = work_->pass1Counts;
        work->pass1Counts = work_->pass1Counts;
        work->level = 1;
      }
    }
    work_ = std::move(work);
    version_.fetch_add(1, std::memory_order_release);
  }
  Work* current = work_.get(); // replaced only after this thread is joined
  driver_ = std::jthread([this, current, keepPass1] {
    // A failure (memory exhausted in a tile, say) ends this render with its
    // reason instead of the whole program, and whoever waits is woken.
    std::string failure;
    try {
      run(*current, keepPass1);
      return;
    } catch (const std::bad_alloc&) {
      failure = "out of memory";
    } catch (const std::exception& error) {
      failure = error.what();
    }
    {
      std::lock_guard lock(mutex_);
      current->failure = failure;
      current->done = true;
    }
    current->doneChanged.notify_all();
    version_.fetch_add(1, std::memory_order_release);
  });
}

void RenderSession::apply(const SessionEdit& edit) {
  if (edit.empty()) return;
  for (const auto& [index, light] : edit.lights)
    if (index >= scene_->lights.size())
      throw std::out_of_range("light " + std::to_string(index + 1) +
                              " does not exist: the scene has " +
                              std::to_string(scene_->lights.size()));
  // thresh and jitter only steer pass 2: a finished pass 1 stays valid when
  // nothing else changes.
  const RenderSettings& old = settings_;
  const bool onlyPass2 =
      !edit.camera && !edit.ambient && edit.lights.empty() &&
      (!edit.settings ||
       (old.width == edit.settings->width && old.height == edit.settings->height &&
        old.maxDepth == edit.settings->maxDepth && old.tileSize == edit.settings->tileSize));
  bool pass1Complete;
  {
    std::lock_guard lock(mutex_);
    pass1Complete = work_->phase != SessionPhase::Coarse;
  }
  stopWorkers(); // the workers read all of these: change them only while none runs
  if (edit.settings) settings_ = *edit.settings;
  if (edit.camera) scene_->camera = *edit.camera;
  if (edit.ambient) scene_->ambient = *edit.ambient;
  for (const auto& [index, light] : edit.lights)
    scene_->lights[index] = light;
  ++restarts_;
  startWorkers(onlyPass2 && pass1Complete);
}

void RenderSession::setScene(std::unique_ptr<Scene> scene, std::unique_ptr<Accel> accel) {
  stopWorkers();
  accel_ = std::move(accel); // refers to *scene, so both change together
  scene_ = std::move(scene);
  ++restarts_;
  startWorkers(false);
}

RenderSettings RenderSession::settings() const { return settings_; }

std::string RenderSession::failure() const {
  std::lock_guard lock(mutex_);
  return work_->failure;
}

Scene RenderSession::sceneCopy() const { return *scene_; }

void RenderSession::run(Work& work, bool keepPass1) {
  const RenderSettings s = settings_;
  const Camera camera(scene_->camera, s.width, s.height);
  const std::vector<Tile> tiles = makeTiles(s.width, s.height, s.tileSize);
  const int threads = resolveThreadCount(s.threads);
  auto cancelled = [this] { return cancel_.load(std::memory_order_relaxed); };
  {
    std::lock_guard lock(mutex_);
    work.tileCount = (long long)tiles.size();
  }

  auto publish = [&](auto&& apply) {
    std::lock_guard lock(mutex_);
    apply();
    version_.fetch_add(1, std::memory_order_release);
  };
  // Every tile on the worker threads, in blocks of blockSide x blockSide
  // pixels: sample(tracer, block, counts, samples) adds the block's samples
  // (none where the pass has nothing to do), with a Tracer of the tile's own
  // (it belongs to one thread); then the tile's samples and counts are handed
  // to store() at once under the lock, so a cancelled tile is dropped whole,
  // never half-published. Cancellation is checked block by block.
  auto sampleTiles = [&](int blockSide, auto&& sample, auto&& store) {
    parallelFor(
        int(tiles.size()), threads,
        [&](int item, int) {
          lowerCurrentThreadPriority();
          Tracer tracer(*scene_, *accel_, s.maxDepth);
          RayCounts counts;
          std::vector<Sample> samples;
          for (const Tile& block : splitTile(tiles[std::size_t(item)], blockSide)) {
            if (cancelled()) return;
            sample(tracer, block, counts, samples);
          }
          publish([&] { store(samples, counts); });
        },
        cancelled);
  };

  if (!keepPass1) {
    for (int level = kCoarsestLevel; level >= 1; level /= 2) {
      publish([&] {
        work.level = level;
        // Levels run one after another: every centre traced so far belongs
        // to a completed level.
        if (work.pass1Pixels > 0) work.levelsAvgmax = work.sumMax / double(work.pass1Pixels);
      });
      // Any kBundleSide * level consecutive pixels hold kBundleSide multiples of
      // `level`: a block of that side has at most a full bundle of new pixels.
      sampleTiles(
          kBundleSide * level,
          [&](Tracer& tracer, const Tile& block, RayCounts& counts, std::vector<Sample>& samples) {
            Pixel pixels[Accel::kMaxBundle];
            std::size_t n = 0;
            for (int y = block.y0; y < block.y1; ++y)
              for (int x = block.x0; x < block.x1; ++x)
                if (isNewAtLevel(x, y, level)) pixels[n++] = {x, y};
            Color colors[Accel::kMaxBundle];
            tracePixelCentres(tracer, camera, std::span(pixels, n), colors, counts);
            for (std::size_t i = 0; i < n; ++i)
              samples.push_back({work.film.index(pixels[i].x, pixels[i].y), toRgb(colors[i])});
          },
          [&](const std::vector<Sample>& samples, const RayCounts& counts) {
            for (const Sample& sample : samples) {
              work.film.centre[sample.index] = sample.radiance;
              work.film.radiance[sample.index] = sample.radiance;
              work.sumMax +=
                  double(std::max({sample.radiance.r, sample.radiance.g, sample.radiance.b}));
              const int x = int(sample.index % std::size_t(s.width));
              const int y = int(sample.index / std::size_t(s.width));
              for (int by = y; by < std::min(y + level, s.height); ++by) {
                for (int bx = x; bx < std::min(x + level, s.width); ++bx) {
                  const std::size_t j = work.film.index(bx, by);
                  if (work.displayLevel[j] <= level) continue; // a finer sample is shown
                  work.display[j] = sample.radiance;
                  work.displayLevel[j] = std::uint8_t(level);
                }
              }
            }
            work.pass1Pixels += (long long)samples.size();
            work.counts += counts;
          });
      if (cancelled()) return;
    }
  }

  // The same function over the same samples as render(): the same avgmax.
  const double avgmax = averageMax(work.film.centre);
  publish([&] {
    work.avgmax = avgmax;
    work.levelsAvgmax = avgmax;
    work.pass1End = Clock::now();
    work.phase = SessionPhase::Antialias;
    work.pass1Counts = work.counts;
  });

  // Small blocks: a supersampled pixel costs 16 eye rays and their trees, and
  // an edit should not wait for many of them.
  sampleTiles(
      4,
      [&](Tracer& tracer, const Tile& block, RayCounts& counts, std::vector<Sample>& samples) {
        for (int y = block.y0; y < block.y1; ++y)
          for (int x = block.x0; x < block.x1; ++x)
            if (needsSupersampling(work.film, x, y, avgmax, s.thresh))
              samples.push_back({work.film.index(x, y),
                                 supersamplePixel(tracer, camera, x, y, s.jitter, counts)});
      },
      [&](const std::vector<Sample>& samples, const RayCounts& counts) {
        for (const Sample& sample : samples) {
          work.film.radiance[sample.index] = sample.radiance;
          work.film.supersampled[sample.index] = 1;
          work.display[sample.index] = sample.radiance;
        }
        work.supersampled += (long long)samples.size();
        work.counts += counts;
        ++work.pass2TilesDone;
      });
  if (cancelled()) return;

  publish([&] {
    work.phase = SessionPhase::Done;
    work.done = true;
    work.end = Clock::now();
  });
  work.doneChanged.notify_all();
}

bool RenderSession::copyImage(SessionImage& image) const {
  std::lock_guard lock(mutex_);
  const std::uint64_t now = version_.load(std::memory_order_acquire);
  if (image.version == now && image.width == work_->film.width &&
      image.height == work_->film.height)
    return false;
  image.width = work_->film.width;
  image.height = work_->film.height;
  image.radiance = work_->display;
  image.supersampled = work_->film.supersampled;
  image.version = now;
  return true;
}

SessionProgress RenderSession::progress() const {
  std::lock_guard lock(mutex_);
  const Work& w = *work_;
  SessionProgress p;
  p.phase = w.phase;
  p.level = w.level;
  const double pixels = double(w.film.pixelCount());
  const double pass1 = pixels > 0 ? double(w.pass1Pixels) / pixels : 1.0;
  const double pass2 = double(w.pass2TilesDone) / double(std::max(1LL, w.tileCount));
  p.fraction = w.done ? 1.0 : 0.5 * pass1 + 0.5 * pass2;
  p.pass1Fraction = pass1;
  p.pass2Fraction = w.done ? 1.0 : pass2;
  if (w.phase != SessionPhase::Coarse)
    p.pass1Seconds = std::chrono::duration<double>(w.pass1End - w.start).count();
  p.pass1Pixels = w.pass1Pixels;
  p.supersampledPixels = w.supersampled;
  p.liveAvgmax = w.pass1Pixels > 0 ? w.sumMax / double(w.pass1Pixels) : 0.0;
  p.levelsAvgmax = w.levelsAvgmax;
  p.avgmax = w.phase == SessionPhase::Coarse ? p.liveAvgmax : w.avgmax;
  p.counts = w.counts;
  p.elapsedSeconds =
      std::chrono::duration<double>((w.done ? w.end : Clock::now()) - w.start).count();
  p.restarts = restarts_.load(std::memory_order_relaxed);
  return p;
}

bool RenderSession::finished() const {
  std::lock_guard lock(mutex_);
  return work_->done;
}

RenderResult RenderSession::waitForResult() {
  std::unique_lock lock(mutex_);
  work_->doneChanged.wait(lock, [this] { return work_->done; });
  if (!work_->failure.empty()) throw std::runtime_error("the render failed: " + work_->failure);
  RenderResult result;
  result.film = work_->film;
  result.avgmax = work_->avgmax;
  result.counts = work_->counts;
  result.supersampledPixels = work_->supersampled;
  return result;
}

} // namespace prism

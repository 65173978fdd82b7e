#include "save_job.h"

#include "core/exposure.h"
#include "core/image_io.h"

#include <chrono>

namespace prism {

void writeRenderResult(const std::filesystem::path& path, const RenderResult& result) {
  const Film& film = result.film;
  // The same calls as `prism render` (viewer/render_command.cpp), so the files agree.
  if (isFloatFormat(path)) {
    writeImageFloat(path, film.width, film.height, film.radiance);
  } else {
    writeImage8(path, film.width, film.height,
                exposeImage(film.radiance, exposureScale(result.avgmax)));
  }
}

SaveJob::~SaveJob() {
  if (writing_.valid()) writing_.wait();
}

void SaveJob::start(const std::filesystem::path& path) {
  if (state_ == State::Writing) writing_.wait(); // one file at a time
  path_ = path;
  try {
    checkWritable(path);
  } catch (const std::exception& error) {
    state_ = State::Failed;
    message_ = error.what();
    return;
  }
  state_ = State::WaitingForRender;
  message_ = "finishing the render";
}

void SaveJob::poll(RenderSession& session) {
  if (state_ == State::WaitingForRender && session.finished()) {
    // finished() is true, so this returns at once; only this thread edits the
    // session, so nothing can restart it in between.
    std::shared_ptr<RenderResult> result;
    try {
      result = std::make_shared<RenderResult>(session.waitForResult());
    } catch (const std::exception& error) { // the render failed: nothing to write
      state_ = State::Failed;
      message_ = error.what();
      return;
    }
    message_ = "writing " + path_.string();
    state_ = State::Writing;
    writing_ = std::async(std::launch::async, [result, path = path_]() -> std::string {
      try {
        writeRenderResult(path, *result);
        return {};
      } catch (const std::exception& error) {
        return error.what();
      }
    });
  }
  if (state_ == State::Writing &&
      writing_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    const std::string error = writing_.get();
    state_ = error.empty() ? State::Saved : State::Failed;
    message_ = error.empty() ? "saved " + path_.string() : error;
  }
}

} // namespace prism

#include "save_job.h"

#include "core/io/image_io.h"

#include <chrono>
#include <iostream>

namespace prism {

// Shown in the panel, and printed for whoever started the previewer from a
// terminal (as scene errors are).
void SaveJob::fail(const std::string& message) {
  state_ = State::Failed;
  message_ = message;
  std::cerr << "prism: error: " << message << "\n";
}

SaveJob::~SaveJob() {
  if (writing_.valid()) writing_.wait();
}

void SaveJob::start(const std::filesystem::path& path, const PictureExposure& exposure) {
  if (state_ == State::Writing) writing_.wait(); // one file at a time
  path_ = path;
  exposure_ = exposure;
  try {
    checkWritable(path);
  } catch (const std::exception& error) {
    fail(error.what());
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
      fail(error.what());
      return;
    }
    message_ = "writing " + path_.string();
    state_ = State::Writing;
    writing_ = std::async(std::launch::async,
                          [result, path = path_, exposure = exposure_]() -> std::string {
                            try {
                              // The same routine as `prism render`, so the files agree.
                              writePicture(path, *result, isFloatFormat(path), exposure);
                              return {};
                            } catch (const std::exception& error) {
                              return error.what();
                            }
                          });
  }
  if (state_ == State::Writing &&
      writing_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    const std::string error = writing_.get();
    if (error.empty()) {
      state_ = State::Saved;
      message_ = "saved " + path_.string();
    } else {
      fail(error);
    }
  }
}

} // namespace prism

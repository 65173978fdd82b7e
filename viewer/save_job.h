// The previewer's Save: the final antialiased picture at full resolution,
// exactly the file `prism render` writes with the same settings (same samples,
// same avgmax, same writer). It never blocks the window: it waits for the
// render by polling, then writes on a helper thread.
#pragma once

#include "core/io/picture_writer.h"
#include "core/render/render_session.h"

#include <filesystem>
#include <future>
#include <string>

namespace prism {

class SaveJob {
public:
  enum class State { Idle, WaitingForRender, Writing, Saved, Failed };

  ~SaveJob(); // waits for a write in progress

  // Starts saving to `path`, as `prism render` writes it: with the automatic
  // automatic exposure unless `exposure` says otherwise (the file's metadata
  // says which). Fails at once (state Failed) when the path cannot be
  // written; a save already in progress is replaced only once it is written.
  void start(const std::filesystem::path& path, const PictureExposure& exposure = {});

  // Once a frame: takes the picture when the session has finished, and notices
  // when the write is done.
  void poll(RenderSession& session);

  State state() const { return state_; }
  bool busy() const { return state_ == State::WaitingForRender || state_ == State::Writing; }
  // What happened, for the panel: "saved x.tiff (640 x 480)", or why not.
  const std::string& message() const { return message_; }
  const std::filesystem::path& path() const { return path_; }

private:
  void fail(const std::string& message);

  State state_ = State::Idle;
  std::filesystem::path path_;
  PictureExposure exposure_;
  std::string message_;
  std::future<std::string> writing_; // the error message, empty on success
};

} // namespace prism

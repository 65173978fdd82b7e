// Scripted previewer sessions (`prism view SCENE --script FILE`), for tests,
// screenshots and measurements. A script is a list of actions, one a line, `#`
// starts a comment:
//
//   wait coarse|pass1|done   until the window shows the first samples / all of
//                            pass 1 / the finished picture (event-driven: it
//                            checks once a frame, never sleeps)
//   wait reload|error        until the scene file was re-read successfully /
//                            with errors (counted from the script's start)
//   frames N                 let N frames pass
//   timeout SECONDS          how long any later action may block [60]
//   depth D | thresh T | jitter on|off | no-aa on|off | ambient R G B
//   fog R G B DENSITY        the fog's colour and density (0: no fog)
//   light N X Y Z            move light N (from 1)
//   intensity N R G B        set light N's intensity
//   texture N SCALE R G B [R0 G0 B0]
//                            texture N's (from 1) scale and value-1 colour, as
//                            its `texture` line gives them; R0 G0 B0 the
//                            value-0 colour, its `surface` line's. For an
//                            image alone, texture N SCALE R G B: its size
//                            (1 / SU) and the `surface` colour tinting it
//   orbit YAW PITCH          degrees;  pan DX DY (pixels);  zoom FACTOR;  reset
//   overlay on|off | markers on|off
//   exposure auto|lock       unlock / lock the exposure;  ev STOPS  its offset
//   picture fit|PERCENT      the picture's zoom (the camera stays)
//   inspect X Y              show pixel (X, Y)'s ray tree, as a click does
//   pin                      pin the render for comparison
//   compare off|flip|split [FRACTION]  how the pinned render is shown
//   reload                   re-read the scene files now
//   save PATH                the final picture, as the Save button (waits for it)
//   screenshot PATH          the window's own pixels after the next frame is drawn
//   echo TEXT                print TEXT on stdout (a test can wait for it)
//   print sweep              print the Sweep section's text on stdout, each line
//                            as "sweep: LINE" ("sweep: none" without a sweep)
//   quit
//
// The parser is pure; running goes through a ScriptHost so it can be tested
// without a window.
#pragma once

#include "scene_edit.h"

#include "core/io/scene_parser.h"

#include <chrono>
#include <string>
#include <vector>

namespace prism {

enum class ScriptOp {
  Wait,
  Frames,
  Timeout,
  Depth,
  Thresh,
  Jitter,
  NoAa,
  Ambient,
  Fog,
  Light,
  Intensity,
  Texture,
  Orbit,
  Pan,
  Zoom,
  Reset,
  Overlay,
  Markers,
  Exposure,
  Ev,
  Picture,
  Inspect,
  Pin,
  Compare,
  Reload,
  Save,
  Screenshot,
  Echo,
  Print,
  Quit,
};

// What `wait` waits for.
enum class WaitFor { Coarse, Pass1, Done, Reload, Error };

struct ScriptAction {
  ScriptOp op = ScriptOp::Quit;
  int line = 0;     // 1-based, for messages
  std::string text; // the line as written, for messages
  WaitFor waitFor = WaitFor::Done;
  int index = 0;              // light or texture number (from 1), frame count, depth
  std::vector<double> values; // numbers in order; on/off as 1/0
  std::string path;           // save, screenshot; echo's text; what print prints
};

// Parses a script; throws SceneError (FILE:LINE:COLUMN diagnostics, like a scene)
// listing every bad line.
std::vector<ScriptAction> parseScript(const std::string& text, const std::string& name);
std::vector<ScriptAction> loadScript(const std::string& path);

// What a `texture` action (texture N SCALE R G B [R0 G0 B0]) changes: texture
// N's values as shown (`edits` over `file`) with the action's put in. For an
// image alone, which has no value-1 colour, the form is texture N SCALE R G
// B: its size and the surface colour that tints it. Throws
// std::runtime_error for a texture the scene does not have, and for the form
// with R0 G0 B0 on an image alone.
TextureEdit textureEditOf(const ScriptAction& action, const FileValues& file,
                          const UserEdits& edits);

// What a script drives. `start` performs an action once; `finished` is asked
// once a frame until it says the action is complete (a wait is reached, a save
// is written, a screenshot taken). Throwing std::runtime_error from either
// fails the script.
class ScriptHost {
public:
  virtual ~ScriptHost() = default;
  virtual void start(const ScriptAction& action) = 0;
  virtual bool finished(const ScriptAction& action) = 0;
};

// Steps a script once a frame.
class ScriptRunner {
public:
  using Clock = std::chrono::steady_clock;

  explicit ScriptRunner(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}

  // Starts and completes as many actions as possible this frame; returns false
  // when the script has ended. Throws std::runtime_error ("script line N: ...")
  // when an action fails or blocks longer than the timeout.
  bool step(ScriptHost& host, Clock::time_point now = Clock::now());
  bool done() const { return next_ >= actions_.size(); }

private:
  std::vector<ScriptAction> actions_;
  std::size_t next_ = 0;
  bool started_ = false;
  Clock::time_point startedAt_{};
  double timeoutSeconds_ = 60.0;
};

} // namespace prism

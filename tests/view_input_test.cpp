// The previewer driven as a user drives it: real mouse clicks, drags, wheel
// turns and key taps (xdotool) on a real window, in an X server the test
// starts itself (Xvfb). `prism view --dump-widgets` lists every widget with
// its place and value each frame; the test aims at those places and waits for
// the values to change (each wait is for an event, with a deadline, never a
// fixed sleep). Scripted sessions (view_e2e_test) bypass ImGui's input
// handling, which is how a dead Save button and lost key taps went unseen.
#include "test_files.h"
#include "xdnd_source.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

namespace prism::test {
namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

// Starts `argv` with `env` added; its stdout comes back through `out`.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env, int* out,
            int stderrFd = -1) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(pipeFds[1], 1);
    if (stderrFd >= 0) dup2(stderrFd, 2);
    close(pipeFds[0]);
    close(pipeFds[1]);
    for (const std::string& e : env)
      putenv(const_cast<char*>(e.c_str()));
    std::vector<char*> args;
    for (const std::string& a : argv)
      args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(pipeFds[1]);
  *out = pipeFds[0];
  return pid;
}

// One line from `fd`, or nothing when none comes within `seconds`.
std::optional<std::string> readLine(int fd, double seconds) {
  std::string line;
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, int(left.count())) <= 0) return std::nullopt;
    char c;
    if (read(fd, &c, 1) != 1) return std::nullopt;
    if (c == '\n') return line;
    line += c;
  }
}

// An X server of the test's own: Xvfb picks a free display and says which
// on a pipe once it accepts clients (-displayfd), so nothing waits blindly.
class XServer {
public:
  XServer() {
    pid_ = spawn(
        {"Xvfb", "-displayfd", "1", "-screen", "0", "1280x800x24", "-noreset", "-nolisten", "tcp"},
        {}, &out_);
    if (const std::optional<std::string> number = readLine(out_, 20.0)) display_ = ":" + *number;
  }
  ~XServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    close(out_);
  }
  const std::string& display() const { return display_; }

private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::string display_;
};

// xdotool on the test's display; false if it failed.
bool xdotool(const std::string& display, const std::string& args) {
  // Bounded, so that a `search --sync` that never matches fails the test
  // instead of hanging it.
  return std::system(("DISPLAY=" + display + " timeout 30 xdotool " + args).c_str()) == 0;
}

// The ImageDescription a picture file holds.
std::string imageDescription(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return "";
  return in->spec().get_string_attribute("ImageDescription");
}

// The scene: two lights, a sphere on a checker floor (so that the Textures
// section shows), small enough to render in a fraction of a second.
std::string sceneText(int lights) {
  std::string text = "eye 0 1.5 6\nlookat 0 0.3 0\nfov 40\nresolution 320 240\n";
  for (int i = 0; i < lights; ++i)
    text += "light " + std::to_string(3 - 3 * i) + " 4 4  30 28 26\n";
  return text + "surface 0.9 0.3 0.2 0.8 0.3 0 40 1\nsphere -0.8 0.3 0 0.8\n"
                "surface 0.4 0.6 0.8 0.9 0.1 0 10 1\n"
                "texture checker 1  0.2 0.3 0.4  0.9 0.1 0  10\n"
                "polygon 4 -6 -0.5 -6 -6 -0.5 6 6 -0.5 6 6 -0.5 -6\n";
}

// A previewer in the test's X server, its widgets read from the dump file.
class Previewer {
public:
  Previewer(const XServer& x, const ScratchDir& dir) : display_(x.display()), dir_(dir.path()) {
    writeFile(dir_ / "a.sc", sceneText(2));
    writeFile(dir_ / "ready.txt", "wait done\necho ready\n");
    errFile_ = dir_ / "stderr.txt";
    const int err = open(errFile_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_ =
        spawn({PRISM_BINARY, "view", (dir_ / "a.sc").string(), "-o", (dir_ / "saved.tiff").string(),
               "--dump-widgets", (dir_ / "widgets.json").string(), "--script",
               (dir_ / "ready.txt").string()},
              {"DISPLAY=" + display_, "XDG_CONFIG_HOME=" + (dir_ / "config").string()}, &out_, err);
    close(err);
    // The script says "ready" within a frame, before that frame's widgets
    // are dumped: the first dump may still be on its way (a test that read
    // the widgets at once saw none).
    ready_ = readLine(out_, 60.0) == std::optional<std::string>("ready") &&
             waitFor([&] { return !widgets().empty(); });
  }
  ~Previewer() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    close(out_);
  }

  bool ready() const { return ready_; }
  const fs::path& dir() const { return dir_; }
  std::string stderrText() const { return slurp(errFile_); }

  // The widgets of the latest frame (the file is replaced whole each frame).
  json widgets() const {
    const std::string text = slurp(dir_ / "widgets.json");
    return text.empty() ? json::array() : json::parse(text, nullptr, false);
  }
  std::optional<json> widget(const std::string& name) const {
    for (const json& w : widgets())
      if (w.value("name", "") == name) return w;
    return std::nullopt;
  }
  bool active(const std::string& name) const {
    const std::optional<json> w = widget(name);
    return w && (*w)["active"].get<bool>();
  }
  bool anyActive() const {
    for (const json& w : widgets())
      if (w.value("active", false)) return true;
    return false;
  }
  std::string value(const std::string& name) const {
    const std::optional<json> w = widget(name);
    return w ? (*w)["value"].get<std::string>() : "(no such widget)";
  }

  // Waits until `done()` holds, checking each time the window has drawn
  // (the dump changes); false after `seconds`.
  bool waitFor(const std::function<bool()>& done, double seconds = 20.0) const {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < deadline) {
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10)); // a frame is ~16 ms
    }
    return done();
  }
  bool waitForValue(const std::string& name, const std::string& value) const {
    return waitFor([&] { return this->value(name) == value; });
  }

  // Scrolls the panel (the wheel over it) until the widget is wholly in view.
  bool reveal(const std::string& name) const {
    for (int turn = 0; turn < 40; ++turn) {
      const std::optional<json> w = widget(name);
      if (!w) return false;
      if ((*w)["visible"].get<bool>()) return true;
      const int x = int((*w)["x"].get<double>()) + 5;
      const bool below = (*w)["y"].get<double>() > 200.0;
      const std::string before = slurp(dir_ / "widgets.json");
      xdotool(display_, "mousemove " + std::to_string(x) + " 300 click " + (below ? "5" : "4"));
      waitFor([&] { return slurp(dir_ / "widgets.json") != before; }, 2.0);
    }
    return false;
  }

  // The centre of a widget (or a point a fraction `fx` across it), in the
  // window, which sits at the screen's origin (Xvfb has no window manager),
  // scrolled into view first.
  std::pair<int, int> at(const std::string& name, double fx = 0.5) const {
    if (!reveal(name)) return {-1, -1};
    const std::optional<json> w = widget(name);
    if (!w) return {-1, -1};
    return {int(std::lround((*w)["x"].get<double>() + fx * (*w)["w"].get<double>())),
            int(std::lround((*w)["y"].get<double>() + 0.5 * (*w)["h"].get<double>()))};
  }
  // Presses `button` on widget `name` (at `fx` of its width) and holds it
  // until the window shows the widget active: it saw the press there. A press
  // it did not see there is released and given again at the widget's new
  // place: in CI the first input after start-up was sometimes lost, and a
  // press read from the dump just before the panel's layout changed (a light
  // added by a reload) can land beside the widget. Returns where it pressed,
  // or nothing.
  std::optional<std::pair<int, int>> pressOn(const std::string& name, double fx,
                                             int button = 1) const {
    const std::string b = std::to_string(button);
    for (int attempt = 0; attempt < 5; ++attempt) {
      const auto [x, y] = at(name, fx);
      if (x < 0 || !xdotool(display_, "mousemove " + std::to_string(x) + " " + std::to_string(y) +
                                          " mousedown " + b))
        return std::nullopt;
      if (waitFor([&] { return active(name); }, 4.0)) return std::pair{x, y};
      if (!xdotool(display_, "mouseup " + b)) return std::nullopt;
    }
    return std::nullopt;
  }
  bool click(const std::string& name, double fx = 0.5) const {
    return pressOn(name, fx) && xdotool(display_, "mouseup 1");
  }
  // A key held for 10 ms, as a quick tap is.
  bool tap(const std::string& keys) const {
    return xdotool(display_, "keydown " + keys + " sleep 0.01 keyup " + keys);
  }
  // Presses `button` at (x, y), moves by (dx, dy), and releases it only once
  // `moved()` holds (or after 20 s): a loaded machine may render a frame
  // slower than the events arrive, and a release seen in the same frame as
  // the last move would lose the drag. Returns whether `moved()` held.
  bool drag(int x, int y, int dx, int dy, const std::function<bool()>& moved,
            int button = 1) const {
    return xdotool(display_, "mousemove " + std::to_string(x) + " " + std::to_string(y) +
                                 " mousedown " + std::to_string(button)) &&
           moveAndRelease(x, y, dx, dy, moved, button);
  }
  // Drags widget `name`, held at `fx` of its width, `dx` pixels sideways. The
  // motion starts only once the window has seen the press (pressOn):
  // otherwise the press and the whole motion can fall into one frame, which
  // then sees the button go down where the motion ended.
  bool dragWidget(const std::string& name, double fx, int dx,
                  const std::function<bool()>& moved) const {
    const std::optional<std::pair<int, int>> at = pressOn(name, fx);
    return at && moveAndRelease(at->first, at->second, dx, 0, moved, 1);
  }
  // With `button` held at (x, y): moves by (dx, dy) in five steps, waits for
  // `moved()`, releases, and waits until no widget is active (a dragged
  // widget is released in a later frame: its value is final then).
  bool moveAndRelease(int x, int y, int dx, int dy, const std::function<bool()>& moved,
                      int button) const {
    std::string steps = "sleep 0.05";
    for (int i = 1; i <= 5; ++i)
      steps += " mousemove " + std::to_string(x + dx * i / 5) + " " +
               std::to_string(y + dy * i / 5) + " sleep 0.03";
    const bool done = xdotool(display_, steps) && waitFor(moved);
    return xdotool(display_, "mouseup " + std::to_string(button)) && done &&
           waitFor([&] { return !anyActive(); });
  }
  // Waits for the program to end by itself.
  bool exits(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < deadline) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

private:
  std::string display_;
  fs::path dir_;
  fs::path errFile_;
  pid_t pid_ = -1;
  int out_ = -1;
  bool ready_ = false;
  bool exited_ = false;
};

class ViewInput : public ::testing::Test {
protected:
  void SetUp() override {
    ASSERT_FALSE(x_.display().empty()) << "Xvfb did not start";
    ASSERT_TRUE(app_.ready()) << app_.stderrText();
  }
  // What the window said and showed last, to tell why a test failed.
  void TearDown() override {
    if (HasFailure())
      std::cerr << "---- the previewer's stderr:\n"
                << app_.stderrText() << "---- its last widgets:\n"
                << slurp(app_.dir() / "widgets.json").substr(0, 6000) << "\n";
  }
  XServer x_;
  ScratchDir dir_;
  Previewer app_{x_, dir_};
};

// Every button and checkbox, clicked with the mouse, does what it says.
TEST_F(ViewInput, ButtonsAndCheckboxesWorkByMouse) {
  // Save: the picture is written (the button once shared its id with the
  // Save section's header and did nothing).
  ASSERT_TRUE(app_.click("Save/Save picture (Ctrl+S)"));
  EXPECT_TRUE(app_.waitFor([&] { return fs::exists(app_.dir() / "saved.tiff"); }));
  // A path that cannot be written: an error, said in the panel and on stderr.
  ASSERT_TRUE(app_.click("Save/path"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.active("Save/path"); }));
  ASSERT_TRUE(xdotool(x_.display(), "key ctrl+a BackSpace type --delay 20 '/no/such/dir/x.tiff'"));
  ASSERT_TRUE(app_.waitForValue("Save/path", "/no/such/dir/x.tiff"));
  ASSERT_TRUE(app_.click("Save/Save picture (Ctrl+S)"));
  EXPECT_TRUE(app_.waitFor([&] {
    return app_.stderrText().find("no such directory") != std::string::npos;
  })) << app_.stderrText();
  for (const char* box :
       {"Render/jitter sub-samples", "Render/no antialiasing", "Display/supersampled pixels (O)",
        "Display/lights (L)", "Display/lock exposure (E)"}) {
    const std::string before = app_.value(box);
    ASSERT_TRUE(before == "true" || before == "false") << box << ": " << before;
    ASSERT_TRUE(app_.click(box, 0.05));
    EXPECT_TRUE(app_.waitForValue(box, before == "true" ? "false" : "true")) << box;
  }
  // Reload: a third light written into the file appears.
  writeFile(app_.dir() / "a.sc", sceneText(3));
  ASSERT_TRUE(app_.click("Scene/Reload (R)"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Lights/light 3/light 3").has_value(); }));
  // Reset camera: an edited eye goes back to the file's.
  const std::string eye = app_.value("Camera/eye");
  ASSERT_TRUE(
      app_.dragWidget("Camera/eye", 0.16, 60, [&] { return app_.value("Camera/eye") != eye; }));
  ASSERT_TRUE(app_.click("Camera/Reset camera (Home)"));
  EXPECT_TRUE(app_.waitForValue("Camera/eye", eye));
}

// Every key tap of 10 ms counts, each exactly once (one in eight did before).
TEST_F(ViewInput, ShortKeyTapsAllCount) {
  const std::string overlay = "Display/supersampled pixels (O)";
  for (int i = 0; i < 8; ++i) {
    const std::string before = app_.value(overlay);
    ASSERT_TRUE(app_.tap("o"));
    ASSERT_TRUE(app_.waitForValue(overlay, before == "true" ? "false" : "true")) << "tap " << i;
  }
  ASSERT_TRUE(app_.tap("l"));
  EXPECT_TRUE(app_.waitForValue("Display/lights (L)", "false"));
  ASSERT_TRUE(app_.tap("e"));
  EXPECT_TRUE(app_.waitForValue("Display/lock exposure (E)", "true"));
  // F1 opens the key help (with its Close button); F1 closes it.
  ASSERT_TRUE(app_.tap("F1"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Help/Close (F1)").has_value(); }));
  ASSERT_TRUE(app_.tap("F1"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Help/Close (F1)").has_value(); }));
  // Tab hides the panel and shows it again.
  ASSERT_TRUE(app_.tap("Tab"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Scene/Reload (R)").has_value(); }));
  ASSERT_TRUE(app_.tap("Tab"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Scene/Reload (R)").has_value(); }));
  // R and F5 reload.
  writeFile(app_.dir() / "a.sc", sceneText(1));
  ASSERT_TRUE(app_.tap("r"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Lights/light 2/light 2").has_value(); }));
  writeFile(app_.dir() / "a.sc", sceneText(2));
  ASSERT_TRUE(app_.tap("F5"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Lights/light 2/light 2").has_value(); }));
  // With errors in the files, Ctrl+S saves the last good scene, and says so.
  writeFile(app_.dir() / "a.sc", "sphere 0 0 0 -1\n");
  ASSERT_TRUE(app_.tap("r"));
  ASSERT_TRUE(app_.waitFor(
      [&] { return app_.stderrText().find("a.sc:1:14: error") != std::string::npos; }));
  ASSERT_TRUE(app_.tap("ctrl+s"));
  EXPECT_TRUE(app_.waitFor([&] {
    return app_.stderrText().find("the scene files have errors: saving the last good scene") !=
           std::string::npos;
  })) << app_.stderrText();
  fs::remove(app_.dir() / "saved.tiff");
  // Ctrl+S saves, Ctrl+Q quits, both as quick taps.
  ASSERT_TRUE(app_.tap("ctrl+s"));
  EXPECT_TRUE(app_.waitFor([&] { return fs::exists(app_.dir() / "saved.tiff"); }));
  ASSERT_TRUE(app_.tap("ctrl+q"));
  EXPECT_TRUE(app_.exits(20.0));
}

// Sliders and number fields by dragging; the camera by dragging on the
// picture, the wheel, and Home.
TEST_F(ViewInput, DragsSlidersAndThePicture) {
  // A click on the slider's track sets the value there.
  ASSERT_TRUE(app_.click("Render/max depth", 0.95));
  EXPECT_TRUE(app_.waitFor([&] { return app_.value("Render/max depth") != "5"; }));
  const std::string light = app_.value("Lights/light 1/light 1");
  EXPECT_TRUE(app_.dragWidget("Lights/light 1/light 1", 0.16, 80,
                              [&] { return app_.value("Lights/light 1/light 1") != light; }));
  // Orbit: a drag on the picture moves the eye, not lookat.
  const std::string eye = app_.value("Camera/eye"), lookat = app_.value("Camera/lookat");
  EXPECT_TRUE(app_.drag(160, 120, 60, 20, [&] { return app_.value("Camera/eye") != eye; }));
  EXPECT_EQ(app_.value("Camera/lookat"), lookat);
  // Pan: a right drag moves both.
  const std::string orbited = app_.value("Camera/eye");
  EXPECT_TRUE(app_.drag(
      160, 120, 30, 30,
      [&] { return app_.value("Camera/eye") != orbited && app_.value("Camera/lookat") != lookat; },
      3));
  // Wheel: the eye moves toward lookat.
  const std::string panned = app_.value("Camera/eye");
  ASSERT_TRUE(xdotool(x_.display(), "mousemove 160 120 click 4"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.value("Camera/eye") != panned; }));
  // Home: back to the file's camera.
  ASSERT_TRUE(app_.tap("Home"));
  EXPECT_TRUE(app_.waitForValue("Camera/eye", eye));
  EXPECT_TRUE(app_.waitForValue("Camera/lookat", lookat));
}

// Undo and redo by key and by button; a drag is one step; resets and the
// file's values.
TEST_F(ViewInput, UndoRedoAndResets) {
  const std::string light = app_.value("Lights/light 1/light 1");
  ASSERT_TRUE(app_.dragWidget("Lights/light 1/light 1", 0.16, 80,
                              [&] { return app_.value("Lights/light 1/light 1") != light; }));
  const std::string moved = app_.value("Lights/light 1/light 1");
  ASSERT_TRUE(app_.tap("ctrl+z")); // the whole drag, in one step
  EXPECT_TRUE(app_.waitForValue("Lights/light 1/light 1", light));
  ASSERT_TRUE(app_.tap("ctrl+shift+z"));
  EXPECT_TRUE(app_.waitForValue("Lights/light 1/light 1", moved));
  ASSERT_TRUE(app_.click("Scene/Undo (Ctrl+Z)"));
  EXPECT_TRUE(app_.waitForValue("Lights/light 1/light 1", light));
  ASSERT_TRUE(app_.click("Scene/Redo"));
  EXPECT_TRUE(app_.waitForValue("Lights/light 1/light 1", moved));
  ASSERT_TRUE(app_.click("Lights/light 1/reset"));
  EXPECT_TRUE(app_.waitForValue("Lights/light 1/light 1", light));
  // The file's values: every edit of the scene goes (and can come back).
  const std::string eye = app_.value("Camera/eye");
  ASSERT_TRUE(app_.drag(160, 120, 60, 20, [&] { return app_.value("Camera/eye") != eye; }));
  ASSERT_TRUE(app_.click("Scene/Back to the file's values"));
  EXPECT_TRUE(app_.waitForValue("Camera/eye", eye));
}

// The picture's zoom (the camera stays): Ctrl + wheel, the slider, 1:1, fit.
TEST_F(ViewInput, ZoomThePictureNotTheCamera) {
  const std::string eye = app_.value("Camera/eye");
  const std::string fit = app_.value("View/zoom %");
  ASSERT_TRUE(xdotool(x_.display(), "mousemove 160 368 keydown ctrl click 4 click 4 keyup ctrl"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.value("View/zoom %") != fit; }));
  EXPECT_EQ(app_.value("Camera/eye"), eye);
  ASSERT_TRUE(app_.tap("1"));
  EXPECT_TRUE(app_.waitForValue("View/zoom %", "100"));
  ASSERT_TRUE(app_.click("View/zoom %", 0.9));
  EXPECT_TRUE(app_.waitFor([&] { return app_.value("View/zoom %") != "100"; }));
  ASSERT_TRUE(app_.click("View/Fit (F)"));
  EXPECT_TRUE(app_.waitForValue("View/zoom %", fit));
}

// A click on the picture shows that pixel's ray tree; Esc closes it. Pinning
// a render offers the comparison; B flips to it.
TEST_F(ViewInput, InspectAPixelAndCompareWithAPinnedRender) {
  ASSERT_FALSE(app_.widget("Pixel/Close").has_value());
  ASSERT_TRUE(xdotool(x_.display(), "mousemove 100 380 click 1")); // on the sphere
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Pixel/Close").has_value(); }));
  ASSERT_TRUE(app_.tap("Escape"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Pixel/Close").has_value(); }));
  ASSERT_FALSE(app_.widget("View/flip (B)").has_value());
  ASSERT_TRUE(app_.click("View/Pin this render (P)"));
  EXPECT_TRUE(app_.waitForValue("View/flip (B)", "true"));
  ASSERT_TRUE(app_.tap("b"));
  EXPECT_TRUE(app_.waitForValue("View/show the pinned render (B)", "true"));
  ASSERT_TRUE(app_.click("View/split"));
  EXPECT_TRUE(app_.waitForValue("View/split", "true"));
  EXPECT_TRUE(app_.widget("View/split at").has_value());
}

// Save with the window's exposure says so in the file; by default the file
// is what `prism render` writes, with the automatic exposure.
TEST_F(ViewInput, SaveSaysHowThePictureWasExposed) {
  ASSERT_TRUE(app_.click("Display/lock exposure (E)", 0.05));
  ASSERT_TRUE(app_.waitForValue("Display/lock exposure (E)", "true"));
  ASSERT_TRUE(app_.click("Save/with the window's exposure", 0.05));
  ASSERT_TRUE(app_.waitForValue("Save/with the window's exposure", "true"));
  ASSERT_TRUE(app_.click("Display/EV offset", 0.9));
  ASSERT_TRUE(app_.waitFor([&] { return app_.value("Display/EV offset") != "0"; }));
  ASSERT_TRUE(app_.tap("ctrl+s"));
  ASSERT_TRUE(app_.waitFor([&] { return fs::exists(app_.dir() / "saved.tiff"); }));
  EXPECT_NE(imageDescription(app_.dir() / "saved.tiff").find("the previewer's exposure"),
            std::string::npos);
  // Save scene as writes the scene shown as .sc.
  ASSERT_TRUE(app_.click("Save/Save scene as .sc"));
  EXPECT_TRUE(app_.waitFor([&] { return fs::exists(app_.dir() / "a-view.sc"); }))
      << "the scene field: " << app_.value("Save/scene path");
}

// Ctrl+O opens the dialog; a click on a scene opens it, and it is listed
// among the recent scenes (kept in the user's configuration folder).
TEST_F(ViewInput, OpenAnotherScene) {
  writeFile(app_.dir() / "other.sc", sceneText(3));
  ASSERT_TRUE(app_.tap("ctrl+o"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Open/folder/other.sc").has_value(); }));
  ASSERT_TRUE(app_.click("Open/folder/other.sc"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Lights/light 3/light 3").has_value(); }));
  EXPECT_FALSE(app_.widget("Open/folder/other.sc").has_value()); // the dialog closed
  ASSERT_TRUE(app_.click("Scene/Open... (Ctrl+O)"));
  const std::string other = (app_.dir() / "other.sc").string();
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Open/recent/" + other).has_value(); }));
  EXPECT_NE(slurp(app_.dir() / "config" / "prism" / "recent-scenes").find(other),
            std::string::npos);
  // Back to the first scene from the recent list.
  ASSERT_TRUE(app_.click("Open/recent/" + (app_.dir() / "a.sc").string()));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Lights/light 3/light 3").has_value(); }));
}

// A scene file dropped on the window (as from a file manager, by the XDND
// protocol) opens; of several files, the first scene file does.
TEST_F(ViewInput, DroppingASceneFileOpensIt) {
  writeFile(app_.dir() / "notes.txt", "not a scene");
  writeFile(app_.dir() / "dropped scene.sc", sceneText(3));
  ASSERT_TRUE(dropFiles(x_.display(), {app_.dir() / "notes.txt", app_.dir() / "dropped scene.sc"},
                        100, 380));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Lights/light 3/light 3").has_value(); }))
      << app_.stderrText();
  EXPECT_TRUE(
      xdotool(x_.display(), "search --sync --name 'Prism - .*dropped scene.sc' >/dev/null"));
}

// The remaining controls, each by mouse, each with its effect.
TEST_F(ViewInput, EveryOtherControlByMouse) {
  const auto changesOnClick = [&](const std::string& name, double fx) {
    const std::string before = app_.value(name);
    EXPECT_TRUE(app_.click(name, fx)) << name;
    EXPECT_TRUE(app_.waitFor([&] { return app_.value(name) != before; })) << name;
  };
  changesOnClick("Render/threshold", 0.9);
  changesOnClick("Camera/fov", 0.8);
  const auto changesOnDrag = [&](const std::string& name) {
    const std::string before = app_.value(name);
    EXPECT_TRUE(app_.dragWidget(name, 0.16, 70, [&] { return app_.value(name) != before; }))
        << name;
  };
  changesOnDrag("Lights/ambient");
  changesOnDrag("Lights/light 2/intensity");
  changesOnDrag("Fog/fog colour");
  changesOnDrag("Fog/fog density");
  // A texture: its scale, both colours, and back to the file's values.
  const std::string tiles = app_.value("Textures/texture 1/texture colour");
  changesOnClick("Textures/texture 1/scale", 0.9);
  changesOnDrag("Textures/texture 1/texture colour");
  changesOnDrag("Textures/texture 1/surface colour");
  ASSERT_TRUE(app_.click("Textures/texture 1/reset"));
  EXPECT_TRUE(app_.waitForValue("Textures/texture 1/texture colour", tiles));
  changesOnDrag("Camera/lookat");
  // The pixel's ray tree closes by its button, the key help by its own.
  ASSERT_TRUE(xdotool(x_.display(), "mousemove 100 380 click 1"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Pixel/Close").has_value(); }));
  ASSERT_TRUE(app_.click("Pixel/Close"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Pixel/Close").has_value(); }));
  ASSERT_TRUE(app_.tap("F1"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Help/Close (F1)").has_value(); }));
  ASSERT_TRUE(app_.click("Help/Close (F1)"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Help/Close (F1)").has_value(); }));
  // Split view's slider.
  ASSERT_TRUE(app_.click("View/Pin this render (P)"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("View/split").has_value(); }));
  ASSERT_TRUE(app_.click("View/split"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("View/split at").has_value(); }));
  changesOnClick("View/split at", 0.2);
  ASSERT_TRUE(app_.click("View/off"));
  EXPECT_TRUE(app_.waitForValue("View/off", "true"));
  // The Open dialog: Cancel closes it; a typed path and Open opens it.
  ASSERT_TRUE(app_.click("Scene/Open... (Ctrl+O)"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Open/Cancel").has_value(); }));
  ASSERT_TRUE(app_.click("Open/Cancel"));
  EXPECT_TRUE(app_.waitFor([&] { return !app_.widget("Open/Cancel").has_value(); }));
  // The third scene adds an image on a sphere (a 2 x 2 PNG): texture 2.
  const std::vector<std::uint8_t> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  auto png = OIIO::ImageOutput::create((app_.dir() / "grid.png").string());
  ASSERT_TRUE(png &&
              png->open((app_.dir() / "grid.png").string(),
                        OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)) &&
              png->write_image(OIIO::TypeDesc::UINT8, rgb.data()) && png->close());
  writeFile(app_.dir() / "third.sc", sceneText(3) + "surface 1 1 1  0.8 0.2 0  20 1\n"
                                                    "image grid.png\nsphere 1 0.3 -0.5 0.6\n");
  ASSERT_TRUE(app_.tap("ctrl+o"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Open/path").has_value(); }));
  ASSERT_TRUE(app_.click("Open/path"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.active("Open/path"); }));
  ASSERT_TRUE(
      xdotool(x_.display(), "type --delay 20 '" + (app_.dir() / "third.sc").string() + "'"));
  ASSERT_TRUE(app_.waitForValue("Open/path", (app_.dir() / "third.sc").string()));
  ASSERT_TRUE(app_.click("Open/Open"));
  EXPECT_TRUE(app_.waitFor([&] { return app_.widget("Lights/light 3/light 3").has_value(); }));
  // An image: its size and its tint, and no value-1 colour.
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Textures/texture 2/scale").has_value(); }));
  EXPECT_FALSE(app_.widget("Textures/texture 2/texture colour").has_value());
  const std::string size = app_.value("Textures/texture 2/scale");
  changesOnClick("Textures/texture 2/scale", 0.2);
  changesOnDrag("Textures/texture 2/surface colour");
  ASSERT_TRUE(app_.click("Textures/texture 2/reset"));
  EXPECT_TRUE(app_.waitForValue("Textures/texture 2/scale", size));
}

// The controls docs/previewer.md lists are the window's: every documented
// label is a widget, and every widget (but text fields, section headers and
// the Open dialog's list of files) is documented. With the key help, the
// Open dialog, a pinned render in split view and an inspected pixel on
// screen, every control is there at once.
TEST_F(ViewInput, TheDocumentedControlsAreTheWindows) {
  ASSERT_TRUE(xdotool(x_.display(), "mousemove 100 380 click 1"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("Pixel/Close").has_value(); }));
  ASSERT_TRUE(app_.click("View/Pin this render (P)"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("View/split").has_value(); }));
  ASSERT_TRUE(app_.click("View/split"));
  ASSERT_TRUE(app_.waitFor([&] { return app_.widget("View/split at").has_value(); }));
  ASSERT_TRUE(app_.click("View/flip (B)"));
  ASSERT_TRUE(
      app_.waitFor([&] { return app_.widget("View/show the pinned render (B)").has_value(); }));
  ASSERT_TRUE(app_.tap("F1"));
  ASSERT_TRUE(app_.tap("ctrl+o"));
  ASSERT_TRUE(app_.waitFor([&] {
    return app_.widget("Help/Close (F1)").has_value() && app_.widget("Open/Cancel").has_value();
  }));
  std::set<std::string> shown;
  const std::regex numberedLight("light [0-9]+");
  for (const json& w : app_.widgets()) {
    const std::string name = w["name"], kind = w["kind"];
    if (kind == "header" || kind == "input" || name.starts_with("Open/recent/") ||
        name.starts_with("Open/folder/"))
      continue;
    shown.insert(std::regex_replace(w["label"].get<std::string>(), numberedLight, "light N"));
  }
  // Split mode hides flip's checkbox; the help shows it under flip (both listed).
  shown.insert("split at");
  shown.insert("show the pinned render (B)");
  // The labels in the second column of the Controls table, each in backticks.
  const std::string doc = slurp(fs::path(PRISM_SOURCE_DIR) / "docs" / "previewer.md");
  const std::size_t start = doc.find("## Controls"), end = doc.find("\n## ", start + 1);
  ASSERT_NE(start, std::string::npos);
  std::set<std::string> documented;
  std::istringstream table(doc.substr(start, end - start));
  const std::regex label("`([^`]+)`");
  for (std::string row; std::getline(table, row);) {
    if (row.rfind("| ", 0) != 0) continue;
    const std::size_t first = row.find(" | "), second = row.find(" | ", first + 3);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string cell = row.substr(first + 3, second - first - 3);
    for (std::sregex_iterator it(cell.begin(), cell.end(), label), none; it != none; ++it)
      documented.insert((*it)[1]);
  }
  for (const std::string& l : shown)
    EXPECT_TRUE(documented.count(l)) << "not documented in docs/previewer.md: " << l;
  for (const std::string& l : documented)
    EXPECT_TRUE(shown.count(l)) << "documented but not in the window: " << l;
}

// No two widgets share an ImGui id (the dump refuses to be written then), and
// every widget has a place inside the window.
TEST_F(ViewInput, EveryWidgetHasAPlaceAndAUniqueName) {
  const json widgets = app_.widgets();
  ASSERT_GT(widgets.size(), 15u);
  std::set<std::string> names;
  for (const json& w : widgets) {
    EXPECT_TRUE(names.insert(w["name"].get<std::string>()).second) << w["name"];
    EXPECT_GE(w["x"].get<double>(), 0.0);
    // Never cut off at the side: the window is the 320-pixel image and the
    // 360-pixel panel wide.
    EXPECT_LE(w["x"].get<double>() + w["w"].get<double>(), 680.0) << w["name"];
    EXPECT_GT(w["w"].get<double>(), 0.0);
    EXPECT_GT(w["h"].get<double>(), 0.0);
  }
}

// On a screen set up for twice the usual pixels per inch (Xft.dpi 192, which
// GLFW reports as a content scale of 2) the panel's widgets are twice as
// large: text stays readable and the mouse still finds them.
TEST(ViewScale, HighDpiScreensGetAScaledPanel) {
  XServer x;
  ASSERT_FALSE(x.display().empty());
  ASSERT_EQ(std::system(("echo 'Xft.dpi: 192' | DISPLAY=" + x.display() + " xrdb -merge").c_str()),
            0);
  ScratchDir dir;
  Previewer app(x, dir);
  ASSERT_TRUE(app.ready()) << app.stderrText();
  const std::optional<json> reload = app.widget("Scene/Reload (R)");
  ASSERT_TRUE(reload.has_value());
  EXPECT_GE((*reload)["h"].get<double>(), 34.0); // 19 at the usual scale
  ASSERT_TRUE(app.click("Render/jitter sub-samples", 0.05));
  EXPECT_TRUE(app.waitForValue("Render/jitter sub-samples", "true"));
}

// The window opens before the scene is read: here the scene file is a pipe
// that the test fills only once the window is there and stderr has said
// what the previewer is waiting for (forest.sc, 10^6 primitives, left its
// user without a window or a word for seconds).
TEST(ViewLoading, TheWindowOpensAtOnceAndSaysWhatItIsReading) {
  XServer x;
  ASSERT_FALSE(x.display().empty());
  ScratchDir dir;
  const fs::path scene = dir / "slow.sc";
  ASSERT_EQ(mkfifo(scene.c_str(), 0644), 0);
  writeFile(dir / "ready.txt", "wait done\necho ready\nquit\n");
  const fs::path errors = dir / "stderr.txt";
  const int err = open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  int out = -1;
  const pid_t pid =
      spawn({PRISM_BINARY, "view", scene.string(), "--script", (dir / "ready.txt").string()},
            {"DISPLAY=" + x.display(), "XDG_CONFIG_HOME=" + (dir / "config").string()}, &out, err);
  close(err);
  // The window exists while the scene cannot have been read.
  EXPECT_TRUE(xdotool(x.display(), "search --sync --name 'Prism - .*slow.sc'"));
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (slurp(errors).find("prism: reading") == std::string::npos && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_NE(slurp(errors).find("prism: reading " + scene.string() + "..."), std::string::npos)
      << slurp(errors);
  writeFile(scene, sceneText(1)); // opens the pipe: the reading ends
  EXPECT_EQ(readLine(out, 60.0), std::optional<std::string>("ready")) << slurp(errors);
  int status = 0;
  EXPECT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_NE(slurp(errors).find("prism: ready in "), std::string::npos) << slurp(errors);
  close(out);
}

} // namespace
} // namespace prism::test

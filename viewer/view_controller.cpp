#include "view_controller.h"

#include "core/io/image_io.h"
#include "core/io/scene_loader.h"
#include "core/io/scene_writer.h"
#include "core/render/exposure.h"
#include "core/render/pixel_tree.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

namespace prism {

namespace {

// How often the scene's files are checked for changes.
constexpr auto kPollInterval = std::chrono::milliseconds(500);

} // namespace

namespace {
// What a reload reads: the scene's files and its images (an image edited in
// a paint program reloads the scene like an edited include).
std::vector<std::string> watchedFiles(const Scene& scene) {
  std::vector<std::string> files = scene.files;
  if (scene.images)
    for (std::size_t i = 0; i < scene.images->size(); ++i)
      files.push_back(scene.images->info(std::uint32_t(i)).path);
  return files;
}
} // namespace

ViewController::ViewController(Scene scene, const ViewOptions& options,
                               std::vector<std::string> warnings)
    : options_(options), file_(FileValues::of(scene)), sceneWarnings_(std::move(warnings)),
      namedSweepScene_(options.scenePath) {
  const auto [sweepPath, named] = sweepPathFor(options_.scenePath);
  sweep_ = loadSweep(sweepPath, named);
  if (!sweep_.error.empty()) std::cerr << sweep_.error << "\n";
  for (const std::string& line : sceneWarnings_)
    std::cerr << line << "\n"; // also for whoever runs it from a terminal
  watch_.watch(watchedFiles(scene));
  UserEdits start;
  start.settings = options.settings;
  start.camera = options.camera;
  states_.push_back(start);
  current().applyTo(scene);
  session_ = std::make_unique<RenderSession>(std::move(scene), options.settings, options.accel);
}

ViewController::~ViewController() {
  if (loading_.valid()) loading_.wait(); // the loader thread must not outlive what it reads
  if (sceneSave_.writing.valid()) sceneSave_.writing.wait();
}

void ViewController::apply(const SceneEdit& edit) { record(withEdit(current(), edit, file_)); }

void ViewController::record(UserEdits next) {
  if (next == current()) return; // nothing changed: no step, no restart
  keptEdits_ = {};               // the user has seen what the reload did
  if (gesture_ && gestureStep_) {
    current() = std::move(next);
  } else {
    states_.erase(states_.begin() + std::ptrdiff_t(at_) + 1, states_.end()); // no more redo
    states_.push_back(std::move(next));
    ++at_;
    if (states_.size() > kMaxUndoSteps + 1) {
      states_.pop_front();
      --at_;
    }
    gestureStep_ = gesture_;
  }
  show();
}

void ViewController::show() {
  const SessionEdit change =
      changeToShow(current(), file_, session_->scene(), session_->settings());
  if (change.empty()) return;
  session_->apply(change);
  stale_ = true;
}

bool ViewController::undo() {
  if (!canUndo()) return false;
  --at_;
  keptEdits_ = {};
  gestureStep_ = false; // a gesture still going on makes a new step
  show();
  return true;
}

bool ViewController::redo() {
  if (!canRedo()) return false;
  ++at_;
  keptEdits_ = {};
  gestureStep_ = false;
  show();
  return true;
}

void ViewController::beginGesture() {
  gesture_ = true;
  gestureStep_ = false;
}

void ViewController::endGesture() {
  // A drag that came back to where it started leaves no step to undo.
  if (gestureStep_ && states_[at_] == states_[at_ - 1]) {
    states_.erase(states_.begin() + std::ptrdiff_t(at_));
    --at_;
  }
  gesture_ = false;
  gestureStep_ = false;
}

std::pair<std::string, bool> ViewController::sweepPathFor(const std::string& path) const {
  if (!options_.sweepPath.empty() && path == namedSweepScene_) return {options_.sweepPath, true};
  return {sweepPathBeside(path), false};
}

ViewController::LoadedScene ViewController::load(const std::string& path, AccelKind accel,
                                                 const std::string& sweepPath, bool sweepNamed) {
  LoadedScene loaded;
  loaded.sweep = loadSweep(sweepPath, sweepNamed); // never throws
  try {
    std::vector<Diagnostic> warnings;
    loaded.scene = std::make_unique<Scene>(loadAnyScene(path, &warnings));
    for (const Diagnostic& d : warnings)
      loaded.warnings.push_back(formatWarning(d));
    loaded.accel = makeAccel(*loaded.scene, accel);
  } catch (const SceneError& error) {
    loaded.scene.reset();
    for (const Diagnostic& d : error.diagnostics())
      loaded.errors.push_back(d.format());
  } catch (const std::exception& error) { // out of memory, too many primitives
    loaded.scene.reset();
    loaded.errors.push_back(path + ": error: " + error.what());
  }
  return loaded;
}

void ViewController::reload() {
  if (loading_.valid()) {
    reloadAgain_ = true;
    return;
  }
  startLoading(options_.scenePath);
}

void ViewController::open(const std::string& path) {
  reloadAgain_ = false;
  if (loading_.valid()) { // after the reading in flight (it cannot be interrupted)
    openNext_ = path;
    return;
  }
  opening_ = path;
  startLoading(path);
}

void ViewController::startLoading(const std::string& path) {
  const auto [sweepPath, named] = sweepPathFor(path);
  loading_ = std::async(std::launch::async, &ViewController::load, path, session_->accelKind(),
                        sweepPath, named);
}

// The user's edits follow the scene into every state of the history: those of
// lights the file no longer has are dropped, those of textures go to their
// texture's new number (`textures`, from renumberTextures) or are dropped,
// and the size follows the file's `resolution` unless --size set it. Steps
// that no longer change anything go, so that every undo does something.
void ViewController::fitHistoryTo(const Scene& scene,
                                  const std::vector<std::optional<std::size_t>>& textures) {
  for (UserEdits& state : states_) {
    std::erase_if(state.lights,
                  [&](const auto& edit) { return edit.first >= scene.lights.size(); });
    std::map<std::size_t, TextureValues> moved;
    for (const auto& [index, values] : state.textures)
      if (index < textures.size() && textures[index]) moved[*textures[index]] = values;
    state.textures = std::move(moved);
    if (options_.sizeFromScene) {
      state.settings.width = scene.width;
      state.settings.height = scene.height;
    }
  }
  for (std::size_t k = 1; k < states_.size();) {
    if (!(states_[k] == states_[k - 1])) {
      ++k;
      continue;
    }
    states_.erase(states_.begin() + std::ptrdiff_t(k));
    if (at_ >= k) --at_;
  }
  gestureStep_ = false; // a gesture still going on makes a new step
}

void ViewController::install(LoadedScene loaded) {
  // Also for whoever runs the previewer from a terminal.
  for (const std::string& line : loaded.errors.empty() ? loaded.warnings : loaded.errors)
    std::cerr << line << "\n";
  const std::optional<std::string> opened = std::exchange(opening_, std::nullopt);
  if (!loaded.scene) {
    sceneErrors_ = std::move(loaded.errors);
    ++failedReloads_;
    return;
  }
  sceneErrors_.clear();
  if (opened) { // another scene: a fresh start, only the render settings stay
    options_.scenePath = *opened;
    UserEdits fresh;
    fresh.settings = current().settings;
    states_.assign(1, fresh);
    at_ = 0;
    keptEdits_ = {};
  }
  sceneWarnings_ = std::move(loaded.warnings);
  if (!loaded.sweep.error.empty()) std::cerr << loaded.sweep.error << "\n";
  sweep_ = std::move(loaded.sweep);
  Scene& scene = *loaded.scene;
  watch_.watch(watchedFiles(scene)); // an edit may have added or dropped an include or image
  const FileValues before = std::exchange(file_, FileValues::of(scene));
  const std::vector<std::optional<std::size_t>> textures = renumberTextures(before, file_);

  // The user's edits go over the re-read file where their value still exists.
  // (Dropped edits stay listed until the user's next edit: the file watch
  // often reloads twice for one save, and the second drops nothing.)
  for (const auto& [index, light] : current().lights)
    if (index >= scene.lights.size())
      keptEdits_.dropped.push_back("light " + std::to_string(index + 1));
  for (const auto& [index, values] : current().textures)
    if (index >= textures.size() || !textures[index])
      keptEdits_.dropped.push_back("texture " + std::to_string(index + 1));
  fitHistoryTo(scene, textures);
  keptEdits_.kept = current().names();
  current().applyTo(scene); // the hierarchy does not depend on the camera or the lights

  const RenderSettings& s = current().settings;
  if (s.width != session_->settings().width || s.height != session_->settings().height)
    session_->apply({.settings = s});
  session_->setScene(std::move(loaded.scene), std::move(loaded.accel));
  show(); // the edited textures: the session grouped the file's
  stale_ = true;
  ++successfulReloads_;
}

void ViewController::saveSceneAs(const std::string& path) {
  if (sceneSave_.writing.valid()) { // one file at a time
    sceneSave_.writing.wait();
    pollSceneSave();
  }
  sceneSave_.path = path;
  try {
    if (std::filesystem::path(path).extension() != ".sc")
      throw std::runtime_error("cannot save the scene as '" + path + "': scene files end in .sc");
    checkWritableFile(path);
  } catch (const std::exception& error) {
    sceneSave_.state = SceneSaveState::Failed;
    sceneSave_.message = error.what();
    return;
  }
  // A copy: the session's scene may be replaced by a reload while this writes.
  auto scene = std::make_shared<const Scene>(session_->sceneCopy());
  const std::vector<std::string> edited = current().names();
  std::string header = "Saved by prism view from " + options_.scenePath + ", ";
  if (edited.empty()) {
    header += "without edits.";
  } else {
    header += "with edits of:";
    for (const std::string& name : edited)
      header += (name == edited.front() ? " " : ", ") + name;
    header += ".";
  }
  header += "\nIncluded files are written out in full: the .sc language cannot override a\n"
            "camera or light set by an included file.";
  sceneSave_.state = SceneSaveState::Writing;
  sceneSave_.message = "writing " + path;
  sceneSave_.writing = std::async(std::launch::async, [scene, path, header]() -> std::string {
    try {
      saveScene(path, *scene, header);
      return {};
    } catch (const std::exception& error) { // std::bad_alloc too
      return error.what();
    }
  });
}

void ViewController::pollSceneSave() {
  if (!sceneSave_.writing.valid() ||
      sceneSave_.writing.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  const std::string error = sceneSave_.writing.get();
  sceneSave_.state = error.empty() ? SceneSaveState::Saved : SceneSaveState::Failed;
  sceneSave_.message = error.empty() ? "saved scene " + sceneSave_.path : error;
}

bool ViewController::update(Clock::time_point now) {
  if (now >= nextPoll_) {
    nextPoll_ = now + kPollInterval;
    // The watch keeps the last good scene's files (the main file among them),
    // so fixing a broken scene is noticed too.
    if (watch_.changed()) reload();
  }
  if (loading_.valid() && loading_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    install(loading_.get());
    if (openNext_) {
      opening_ = std::exchange(openNext_, std::nullopt);
      startLoading(*opening_);
    } else if (reloadAgain_) {
      reloadAgain_ = false;
      reload();
    }
  }
  save_.poll(*session_);
  pollSceneSave();
  progress_ = session_->progress(); // before the copy: the image has at least this much
  stale_ = false;
  return session_->copyImage(image_);
}

std::string ViewController::pixelRayTree(int x, int y) const {
  return pixelRayTreeText(session_->scene(), session_->accel(), session_->settings(), x, y);
}

float ViewController::exposure() const { return exposureScale(progress_.avgmax); }

} // namespace prism

#include "view_controller.h"

#include "core/exposure.h"
#include "core/scene_loader.h"

#include <iostream>

namespace prism {

namespace {

// How often the scene's files are checked for changes.
constexpr auto kPollInterval = std::chrono::milliseconds(500);

} // namespace

ViewController::ViewController(Scene scene, const ViewOptions& options,
                               std::vector<std::string> warnings)
    : options_(options), fileCamera_(scene.camera), sceneWarnings_(std::move(warnings)) {
  for (const std::string& line : sceneWarnings_)
    std::cerr << line << "\n"; // also for whoever runs it from a terminal
  watch_.watch(scene.files);
  session_ = std::make_unique<RenderSession>(std::move(scene), options.settings, options.accel);
}

ViewController::~ViewController() {
  if (loading_.valid()) loading_.wait(); // the loader thread must not outlive what it reads
}

void ViewController::setSettings(const RenderSettings& settings) {
  session_->setSettings(settings);
  stale_ = true;
}

void ViewController::setLight(std::size_t index, const Light& light) {
  session_->setLight(index, light);
  stale_ = true;
}

void ViewController::setAmbient(const Color& ambient) {
  session_->setAmbient(ambient);
  stale_ = true;
}

void ViewController::setCamera(const CameraSpec& camera) {
  session_->setCamera(camera);
  stale_ = true;
}

void ViewController::resetCamera() { setCamera(fileCamera_); }

ViewController::LoadedScene ViewController::load(const std::string& path, AccelKind accel) {
  LoadedScene loaded;
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
  loading_ = std::async(std::launch::async, &ViewController::load, options_.scenePath,
                        session_->accelKind());
}

void ViewController::apply(LoadedScene loaded) {
  // Also for whoever runs the previewer from a terminal.
  for (const std::string& line : loaded.errors.empty() ? loaded.warnings : loaded.errors)
    std::cerr << line << "\n";
  if (!loaded.scene) {
    sceneErrors_ = std::move(loaded.errors);
    ++failedReloads_;
    return;
  }
  sceneErrors_.clear();
  sceneWarnings_ = std::move(loaded.warnings);
  watch_.watch(loaded.scene->files); // an edit may have added or dropped an include
  fileCamera_ = loaded.scene->camera;
  if (options_.sizeFromScene) {
    RenderSettings s = session_->settings();
    if (s.width != loaded.scene->width || s.height != loaded.scene->height) {
      s.width = loaded.scene->width;
      s.height = loaded.scene->height;
      session_->setSettings(s);
    }
  }
  session_->setScene(std::move(loaded.scene), std::move(loaded.accel));
  stale_ = true;
  ++successfulReloads_;
}

bool ViewController::update(Clock::time_point now) {
  if (now >= nextPoll_) {
    nextPoll_ = now + kPollInterval;
    // The watch keeps the last good scene's files (the main file among them),
    // so fixing a broken scene is noticed too.
    if (watch_.changed()) reload();
  }
  if (loading_.valid() && loading_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    apply(loading_.get());
    if (reloadAgain_) {
      reloadAgain_ = false;
      reload();
    }
  }
  save_.poll(*session_);
  progress_ = session_->progress(); // before the copy: the image has at least this much
  stale_ = false;
  return session_->copyImage(image_);
}

float ViewController::exposure() const { return exposureScale(progress_.avgmax); }

} // namespace prism

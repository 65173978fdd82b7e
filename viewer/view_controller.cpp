#include "view_controller.h"

#include "core/exposure.h"
#include "core/scene_loader.h"

#include <iostream>

namespace prism {

namespace {

// How often the scene's files are checked for changes.
constexpr auto kPollInterval = std::chrono::milliseconds(500);

} // namespace

ViewController::ViewController(Scene scene, const ViewOptions& options)
    : options_(options), fileCamera_(scene.camera) {
  watch_.watch(scene.files);
  session_ = std::make_unique<RenderSession>(std::move(scene), options.settings, options.accel);
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

bool ViewController::reload() {
  Scene scene;
  try {
    scene = loadAnyScene(options_.scenePath);
  } catch (const SceneError& error) {
    sceneErrors_.clear();
    for (const Diagnostic& d : error.diagnostics()) {
      sceneErrors_.push_back(d.format());
      std::cerr << sceneErrors_.back() << "\n"; // also for whoever runs it from a terminal
    }
    ++failedReloads_;
    return false;
  }
  sceneErrors_.clear();
  watch_.watch(scene.files); // an edit may have added or dropped an include
  fileCamera_ = scene.camera;
  if (options_.sizeFromScene) {
    RenderSettings s = session_->settings();
    if (s.width != scene.width || s.height != scene.height) {
      s.width = scene.width;
      s.height = scene.height;
      session_->setSettings(s);
    }
  }
  session_->setScene(std::move(scene));
  stale_ = true;
  ++successfulReloads_;
  return true;
}

bool ViewController::update(Clock::time_point now) {
  if (now >= nextPoll_) {
    nextPoll_ = now + kPollInterval;
    // The watch keeps the last good scene's files (the main file among them),
    // so fixing a broken scene is noticed too.
    if (watch_.changed()) reload();
  }
  save_.poll(*session_);
  progress_ = session_->progress(); // before the copy: the image has at least this much
  stale_ = false;
  return session_->copyImage(image_);
}

float ViewController::exposure() const { return exposureScale(progress_.avgmax); }

} // namespace prism

#include "live_exposure.h"

#include "core/render/exposure.h"

#include <cmath>

namespace prism {

void LiveExposure::update(const SessionProgress& p) {
  holding_ = false;
  if (p.phase != SessionPhase::Coarse) {
    shown_ = p.avgmax;
  } else if (p.levelsAvgmax > 0.0) {
    shown_ = p.levelsAvgmax;
  } else if (shown_ > 0.0) {
    holding_ = true; // an edit's first level is under way: keep the last value
  } else {
    shown_ = p.liveAvgmax; // the first render: nothing to hold yet
  }
}

float LiveExposure::scale() const {
  return float(double(exposureScale(avgmax())) * std::exp2(ev_));
}

void LiveExposure::setLocked(bool locked) {
  if (locked && !locked_) lockedAvgmax_ = shown_;
  locked_ = locked;
}

} // namespace prism

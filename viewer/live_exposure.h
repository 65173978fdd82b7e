// The exposure the window applies while a render refines. The automatic
// exposure divides by avgmax, which is known only once pass 1 is complete;
// until then the window estimates it. Taken over the pixel centres traced so
// far, the estimate "pumped" by about 8% after every edit, as tiles finished in
// whatever order. Here it comes only from completed coarse levels (each a
// uniform subsample of the image), and right after an edit, before the first
// level is complete, the previous value is held. The user can also lock the
// exposure (to see how much brighter a moved light really makes the scene)
// and offset it by whole or fractional stops (EV).
#pragma once

#include "core/render/render_session.h"

namespace prism {

class LiveExposure {
public:
  // Once a frame, with the session's progress.
  void update(const SessionProgress& progress);

  // The avgmax the picture is exposed with now, and 128 / avgmax * 2^EV.
  double avgmax() const { return locked_ ? lockedAvgmax_ : shown_; }
  float scale() const;
  // True while an edit's first coarse level is incomplete and the previous
  // render's avgmax stands in for it.
  bool holding() const { return holding_; }

  // Locked: the avgmax stays what it is now, whatever the render does.
  void setLocked(bool locked);
  bool locked() const { return locked_; }
  void setEv(double ev) { ev_ = ev; }
  double ev() const { return ev_; }
  // The automatic exposure, unlocked and without offset.
  bool automatic() const { return !locked_ && ev_ == 0.0; }

private:
  double shown_ = 0.0;
  bool holding_ = false;
  bool locked_ = false;
  double lockedAvgmax_ = 0.0;
  double ev_ = 0.0;
};

} // namespace prism

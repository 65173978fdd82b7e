// How long the render still needs, honest about pass 2. Pass 1 traces one ray
// per pixel and its share done is its share of the time; pass 2 supersamples
// only where neighbours differ, and how many pixels that is (and so how long
// it takes) is not known until it runs. A progress bar that gave each pass
// half showed 66% at a quarter of the time. This estimate takes pass 2's cost
// from the last render that completed (as a multiple of its pass 1), from
// pass 2's own pace once enough of it is done, and says "then pass 2" rather
// than guess when it knows neither.
#pragma once

#include "core/render/render_session.h"

#include <optional>
#include <string>

namespace prism {

class ProgressEstimate {
public:
  // Once a frame, with the session's progress.
  void update(const SessionProgress& progress);

  // Seconds left, when known (pass 2 included).
  std::optional<double> remainingSeconds() const { return remaining_; }
  // Seconds left in pass 1 alone, while it runs and its pace is known.
  std::optional<double> pass1RemainingSeconds() const { return pass1Remaining_; }
  // Elapsed over elapsed plus remaining when known, else pass 1's share done
  // scaled to at most one half: for a progress bar that moves with time.
  double timeFraction() const { return timeFraction_; }
  // "elapsed 1.2 s, about 0.8 s left" and the like.
  std::string text() const;

private:
  double elapsed_ = 0.0;
  bool done_ = false;
  std::optional<double> remaining_, pass1Remaining_;
  double timeFraction_ = 0.0;
  std::optional<double> pass2PerPass1_; // pass 2's time over pass 1's, last completed render
  std::uint64_t restarts_ = 0;
  bool learned_ = false; // this render's ratio was recorded
};

} // namespace prism

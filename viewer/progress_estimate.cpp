#include "progress_estimate.h"

#include <algorithm>
#include <cstdio>

namespace prism {

namespace {

// Below these shares done, a pace measured over them says too little.
constexpr double kMinPass1Share = 0.02;
constexpr double kMinPass2Share = 0.05;
constexpr double kMinPass1Seconds = 1e-3;

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, s < 10.0 ? "%.1f s" : "%.0f s", s);
  return text;
}

} // namespace

void ProgressEstimate::update(const SessionProgress& p) {
  if (p.restarts != restarts_) {
    restarts_ = p.restarts;
    learned_ = false;
  }
  elapsed_ = p.elapsedSeconds;
  done_ = p.phase == SessionPhase::Done;
  remaining_.reset();
  pass1Remaining_.reset();
  if (done_) {
    // A render that ran both passes teaches the next one what pass 2 costs.
    // (A restart that kept pass 1 ran none: its pass 1 took no time.)
    if (!learned_ && p.pass1Seconds > kMinPass1Seconds) {
      pass2PerPass1_ = std::max(0.0, p.elapsedSeconds - p.pass1Seconds) / p.pass1Seconds;
      learned_ = true;
    }
    remaining_ = 0.0;
  } else if (p.phase == SessionPhase::Coarse) {
    if (p.pass1Fraction >= kMinPass1Share) {
      const double pass1Total = elapsed_ / p.pass1Fraction;
      pass1Remaining_ = pass1Total - elapsed_;
      if (pass2PerPass1_) remaining_ = *pass1Remaining_ + *pass2PerPass1_ * pass1Total;
    }
  } else {
    const double pass2Elapsed = std::max(0.0, elapsed_ - p.pass1Seconds);
    if (p.pass2Fraction >= kMinPass2Share) {
      remaining_ = pass2Elapsed * (1.0 - p.pass2Fraction) / p.pass2Fraction;
    } else if (pass2PerPass1_) {
      remaining_ = std::max(0.0, *pass2PerPass1_ * p.pass1Seconds - pass2Elapsed);
    }
  }
  if (remaining_) {
    const double total = elapsed_ + *remaining_;
    timeFraction_ = total > 0.0 ? elapsed_ / total : 1.0;
  } else {
    timeFraction_ = p.phase == SessionPhase::Coarse ? 0.5 * p.pass1Fraction : 0.5;
  }
}

std::string ProgressEstimate::text() const {
  if (done_) return ""; // the phase says "done in ..." already
  std::string out = "elapsed " + seconds(elapsed_);
  if (remaining_) return out + ", about " + seconds(*remaining_) + " left";
  if (pass1Remaining_)
    return out + ", about " + seconds(*pass1Remaining_) + " left in pass 1, then pass 2";
  return out;
}

} // namespace prism

// The charts `prism sweep` saves beside its table (docs/choosing-settings.md):
// where every setting sits in time against error, and how the error follows
// the ray depth and the supersampling threshold.
#pragma once

#include "core/sweep/sweep_table.h"

#include <string>
#include <vector>

namespace prism {

// Writes time-vs-error.png, error-vs-depth.png and error-vs-threshold.png
// into the existing folder `dir`, titled with `sceneName`. Settings the rows
// lack (a reduced grid) leave gaps. Throws std::runtime_error when a file
// cannot be written; returns the charts' warnings, one a line (empty when
// none), e.g. that their text could not be drawn.
std::string writeSweepPlots(const std::vector<SweepRow>& rows, const std::string& dir,
                            const std::string& sceneName);

} // namespace prism

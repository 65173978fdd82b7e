// `prism bench --startup`: what a run of prism costs before and around its
// work. Runs this same executable as a child process for `--version`,
// `--help` and a render of a one-sphere scene at 8 x 8, many times each, and
// reports the whole-process CPU time and peak memory (from wait4's rusage) of
// each. Start-up is what small renders, scripts and test suites pay per call.
#pragma once

namespace prism {

void benchStartup(int runs);

} // namespace prism

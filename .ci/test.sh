#!/usr/bin/env bash
# Installs the dependencies, builds Prism with its tests and runs the whole suite
# twice: an optimised build, then a build under AddressSanitizer and
# UndefinedBehaviorSanitizer; then fuzzes every reader for 30 s each. Each
# stage says when it starts (seconds since the script began): CI's budget is
# 25 minutes on 2 cores.
# Exits non-zero if anything fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/.ci/install-deps.sh"

echo "== Release build and tests (at ${SECONDS} s)"
# PRISM_BUILD_TESTS=ON: the quick start's command configures the same build
# directory without the tests, and a cached OFF would leave ctest nothing to
# run; --no-tests=error makes that a failure rather than a silent pass.
bash "$root/.ci/build.sh" "$root/build" -DPRISM_BUILD_TESTS=ON
ctest --test-dir "$root/build" --output-on-failure --no-tests=error -j"$(nproc)"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests (at ${SECONDS} s)"
# -g1: line tables only, enough for the sanitizers' stack traces; full debug
# information made the build a fifth slower (measured on tests/cli_test.cpp).
# -O1, the level the sanitizers' authors advise: instrumented code took 30% to
# 48% longer to compile at -O2, and this build was the longest stage of CI
# (docs/testing.md#cis-time). CMAKE_UNITY_BUILD: the core compiled in batches
# of files too, not only the program and the previewer (CMakeLists.txt,
# prism_unity_build), 509 -> 378 CPU seconds; this build's optimiser choices
# are not what users run, and the Release build above still compiles every
# core file alone.
bash "$root/.ci/build.sh" "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$root/build-sanitize" --output-on-failure --no-tests=error -j"$(nproc)"

echo "== Fuzzing the readers for a bounded time (30 s per target; docs/fuzzing.md) (at ${SECONDS} s)"
bash "$root/.ci/fuzz.sh" 30
echo "== Done (at ${SECONDS} s)"

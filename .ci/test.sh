#!/usr/bin/env bash
# Installs the dependencies, builds Prism with its tests and runs the whole suite
# twice: an optimised build, then a build under AddressSanitizer and
# UndefinedBehaviorSanitizer; then fuzzes every reader for 40 s each. Each
# stage says when it starts (seconds since the script began): CI's budget is
# 25 minutes on 2 cores.
# Exits non-zero if anything fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/.ci/install-deps.sh"

echo "== Release build and tests (at ${SECONDS} s)"
bash "$root/.ci/build.sh" "$root/build"
ctest --test-dir "$root/build" --output-on-failure -j"$(nproc)"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests (at ${SECONDS} s)"
# -g1: line tables only, enough for the sanitizers' stack traces; full debug
# information made the build a fifth slower (measured on tests/cli_test.cpp).
# -O1, the level the sanitizers' authors advise: instrumented code took 30% to
# 48% longer to compile at -O2, and this build was the longest stage of CI
# (docs/testing.md#cis-time).
bash "$root/.ci/build.sh" "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$root/build-sanitize" --output-on-failure -j"$(nproc)"

echo "== Fuzzing the readers for a bounded time (40 s per target; docs/fuzzing.md) (at ${SECONDS} s)"
bash "$root/.ci/fuzz.sh" 40
echo "== Done (at ${SECONDS} s)"

#!/usr/bin/env bash
# Configures and builds Prism into a build directory (default: build, Release).
# Usage: .ci/build.sh [BUILD_DIR] [cmake arguments...] [-- cmake --build arguments...]
#   e.g. .ci/build.sh build-fuzz -DPRISM_BUILD_FUZZERS=ON -- --target fuzzers
# A new build directory gets Ninja (it keeps both cores busier than make to
# the last link); one configured before keeps the generator it has, so that
# running this again over an existing make build still works.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-"$root/build"}
shift || true
configure=()
while [[ $# -gt 0 && $1 != -- ]]; do
  configure+=("$1")
  shift
done
shift || true # the "--", if any; what follows goes to cmake --build
if [[ ! -f $dir/CMakeCache.txt ]] && command -v ninja >/dev/null; then
  configure=(-G Ninja "${configure[@]}")
fi
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release "${configure[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)" "$@"

#!/usr/bin/env bash
# Installs the dependencies, builds Prism and runs it on a shipped scene:
# `prism scenes/table.sc` opens the previewer where a display exists; without
# one it says so and renders table.tiff headless (depth 5, threshold 0.1).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/.ci/install-deps.sh"
bash "$root/.ci/build.sh" "$root/build" -DPRISM_BUILD_TESTS=OFF
cd "$root"
exec "$root/build/prism" "$root/scenes/table.sc"

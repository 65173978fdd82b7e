#!/usr/bin/env bash
# Installs the dependencies, builds Prism and runs it on a shipped scene:
# renders scenes/table.sc to table.tiff at depth 5, threshold 0.1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/.ci/install-deps.sh"
bash "$root/.ci/build.sh" "$root/build" -DPRISM_BUILD_TESTS=OFF
"$root/build/viewer/prism" render "$root/scenes/table.sc" -o "$root/table.tiff" --depth 5 --thresh 0.1
echo "wrote $root/table.tiff"

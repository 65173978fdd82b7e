#!/usr/bin/env bash
# Runs the benchmark's scaling series and draws docs/scaling.png (docs/performance.md,
# "Performance"). Needs gnuplot (Debian: gnuplot-nox); the tests do not.
# Usage: bench/plot-scaling.sh [path/to/prism]   (default: build/prism)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prism=${1:-"$root/build/prism"}
mkdir -p "$root/out"
"$prism" bench --data "$root/out/scaling.dat" | tee "$root/out/scaling.md"
gnuplot -e "data='$root/out/scaling.dat'; out='$root/docs/scaling.png'" "$root/bench/scaling.gp"
echo "wrote $root/docs/scaling.png"

#!/usr/bin/env bash
# Regenerates docs/sweeps/: `prism sweep` of the four shipped scenes at a
# quarter of their resolution (160 x 120, tree.sc 128 x 128), the data and
# plots of docs/choosing-settings.md, and links each scene's sweep.csv beside
# it (scenes/NAME.sweep.csv), where the previewer finds it, and the tables of
# docs/sweeps/summary.md (tools/sweep_summary.py). About 3 minutes on
# 2 cores; run it on an otherwise idle machine, the times are measured.
# Usage: scenes/sweep-all.sh [path/to/prism]   (default: build/prism)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prism=${1:-"$root/build/prism"}

sweep() { # sweep NAME W H
  "$prism" sweep "$root/scenes/$1.sc" -o "$root/docs/sweeps/$1" --size "$2" "$3"
  ln -sfn "../docs/sweeps/$1/sweep.csv" "$root/scenes/$1.sweep.csv"
}

sweep table 160 120
sweep glass 160 120
sweep chex 160 120
sweep tree 128 128

python3 "$root/tools/sweep_summary.py" "$root/docs/sweeps" table glass chex tree
echo "written: $root/docs/sweeps/summary.md"

#!/usr/bin/env bash
# Renders the four shipped scenes and tree-solid.sc as docs/scenes.md shows them (512x512 unless the
# scene says otherwise, depth 5, threshold 0.1) into out/, writes 256-pixel PNG
# thumbnails to docs/, and prints the statistics table as Markdown.
# Usage: scenes/render-all.sh [path/to/prism]   (default: build/prism)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prism=${1:-"$root/build/prism"}
depth=5
thresh=0.1
mkdir -p "$root/out" "$root/docs"

field() { # field NAME FILE: a top-level number or string from prism's stats JSON
  sed -n "s/^  \"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$2"
}

echo "| scene | machine | depth | threshold | CPU seconds | wall seconds | pixels | rays/pixel | supersampled |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in table glass chex tree tree-solid; do
  "$prism" render "$root/scenes/$name.sc" -o "$root/out/$name.tiff" --depth "$depth" \
    --thresh "$thresh" --stats-json "$root/out/$name.json" -q
  oiiotool "$root/out/$name.tiff" --resize 256x0 -o "$root/docs/$name.png"
  j="$root/out/$name.json"
  awk -v n="$name.sc" -v m="$(field machine "$j")" -v d="$(field max_depth "$j")" \
    -v t="$(field thresh "$j")" -v cpu="$(field cpu_seconds "$j")" -v wall="$(field wall_seconds "$j")" \
    -v px="$(field pixels "$j")" -v rpp="$(field rays_per_pixel "$j")" \
    -v ss="$(field supersampled_share "$j")" \
    'BEGIN { printf "| %s | %s | %s | %s | %.2f | %.2f | %s | %.2f | %.1f%% |\n", n, m, d, t, cpu, wall, px, rpp, 100 * ss }'
done

#!/usr/bin/env bash
# Builds prism_vs_embree in a build directory of its own (build-embree, with
# -DPRISM_BENCH_EMBREE=ON; needs libembree-dev) and runs it over the shipped
# scenes and any others given, then prints one table of the median rates
# (docs/vs-embree.md). Each scene's full report goes to out/vs-embree/.
# Usage: bench/embree/run.sh [SCENE ...] [-- HARNESS OPTIONS]
#   e.g. bench/embree/run.sh scenes/gears.nff -- --isa avx2
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="$root/build-embree"

scenes=("$root/scenes/table.sc" "$root/scenes/glass.sc" "$root/scenes/chex.sc"
        "$root/scenes/tree.sc")
options=()
while (($#)); do
  if [[ $1 == -- ]]; then shift; options=("$@"); break; fi
  scenes+=("$1"); shift
done

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPRISM_BENCH_EMBREE=ON \
  -DPRISM_BUILD_TESTS=OFF -DPRISM_BUILD_VIEWER=OFF >/dev/null
cmake --build "$build" -j2 --target prism_vs_embree >/dev/null

mkdir -p "$root/out/vs-embree"
rows=()
header=""
for scene in "${scenes[@]}"; do
  name=$(basename "$scene")
  echo "prism_vs_embree: $name" >&2
  report="$root/out/vs-embree/$name.txt"
  "$build/prism_vs_embree" "$scene" --row "${options[@]}" >"$report"
  # The lines that name the ISA and quality are the same for every scene.
  [[ -n $header ]] || header=$(grep -E '^(machine|Embree [0-9])' "$report")
  rows+=("$(sed -n 's/^row: //p' "$report")")
done

echo "$header"
echo
echo "Mrays/s, one ray at a time on one thread (medians of alternating turns); ratio = Prism / Embree"
echo
echo "| scene | primitives | eye Prism | eye Embree | ratio | secondary Prism | secondary Embree | ratio | shadow (any hit) Prism | shadow Embree | ratio |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"

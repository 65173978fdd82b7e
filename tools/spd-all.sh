#!/usr/bin/env bash
# Writes the whole benchmark set of tools/spd_gen, every kind at one size, into
# OUTDIR as KIND-SIZE.sc (see docs/benchmark-scenes.md).
# Usage: tools/spd-all.sh OUTDIR [small|medium|large] [path/to/spd_gen]
#   small  about 10^3 primitives a scene (the default)
#   medium about 10^4
#   large  about 10^5
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -lt 1 ] || [ $# -gt 3 ]; then
  echo "usage: $0 OUTDIR [small|medium|large] [path/to/spd_gen]" >&2
  exit 2
fi
outdir=$1
size=${2:-small}
gen=${3:-"$root/build/tools/spd_gen"}
case "$size" in
  small) count=1000 ;;
  medium) count=10000 ;;
  large) count=100000 ;;
  *) echo "$0: the size must be small, medium or large, not '$size'" >&2; exit 2 ;;
esac
mkdir -p "$outdir"
for kind in balls gears mount rings teapot tetra tree lattice jacks shells hfield; do
  "$gen" "$kind" "$count" "$outdir/$kind-$size.sc"
done

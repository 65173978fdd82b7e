#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang-14 (a build directory of their
# own, build-fuzz) and runs each for a bounded time from its committed seed
# corpus, after replaying its reproducers in fuzz/regressions/TARGET/. A crash,
# timeout, leak or running out of memory fails the script (exit 1) and prints the
# reproducer (hex dump and base64) with libFuzzer's report. See docs/fuzzing.md.
#
# Usage: .ci/fuzz.sh [SECONDS_PER_TARGET]   (default: $PRISM_FUZZ_SECONDS, else 60)
#   PRISM_FUZZ_TARGETS="sc obj"  run only these targets (sc nff obj roundtrip sweep_csv)
#   PRISM_FUZZ_BUILD_DIR=DIR     build elsewhere than build-fuzz
#   PRISM_FUZZ_JOBS=N            targets run at once (default: the cores)
# Needs the Debian packages clang-14 and libclang-rt-14-dev (libFuzzer's runtime).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-${PRISM_FUZZ_SECONDS:-60}}
build=${PRISM_FUZZ_BUILD_DIR:-"$root/build-fuzz"}
read -r -a targets <<<"${PRISM_FUZZ_TARGETS:-sc nff obj roundtrip sweep_csv}"
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: SECONDS_PER_TARGET must be a positive integer, found '$seconds'" >&2
  exit 2
fi

# Corpora grow while fuzzing: they are copied here so that CI never modifies the
# repository. The targets' sandbox directories go here too (TMPDIR): in memory
# when possible, since the OBJ targets write their input to a file on every
# execution (six times faster than on an ext4 /tmp, measured).
shm=/dev/shm
[[ -d $shm && -w $shm ]] || shm=${TMPDIR:-/tmp}
scratch=$(mktemp -d "$shm/prism-fuzz.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/tmp"
export TMPDIR="$scratch/tmp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
started=$SECONDS

echo "== Configure and build the fuzz targets in $build (clang-14)"
# CMAKE_UNITY_BUILD: the instrumented core compiled in batches of files,
# as in CI's sanitizer build (.ci/test.sh).
bash "$root/.ci/build.sh" "$build" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Debug \
  -DPRISM_BUILD_FUZZERS=ON -DPRISM_BUILD_TESTS=OFF -DPRISM_BUILD_VIEWER=OFF -DCMAKE_UNITY_BUILD=ON \
  -- --target fuzzers
echo "build: $((SECONDS - started)) s"

# Prints what a failed run left: libFuzzer's report, then each reproducer.
report() { # LOG INPUT...
  local log=$1
  shift
  echo "---- libFuzzer output (last 150 of $(wc -l <"$log") lines)"
  tail -n 150 "$log"
  local found=0
  for input in "$@"; do
    [[ -f $input ]] || continue
    found=1
    echo "---- reproducer $input ($(stat -c %s "$input") bytes), hex:"
    od -A x -t x1z -v "$input" | head -n 256
    echo "---- the same, base64 (decode with: base64 -d > repro):"
    base64 -w 76 "$input"
  done
  ((found)) || echo "---- (libFuzzer saved no input)"
}

# One target: its regressions, then fuzzing. Its output goes to
# $scratch/TARGET.out, its summary line and any failure to files beside it,
# so that targets can run side by side; TARGET.done marks that it ran to its
# end (errexit ends a job at a failed command without a word).
fuzz_target() { # TARGET
  local target=$1 exe dict artifacts flags regressions crashed corpus log status
  local last runs rate cov ft corp line
  exe="$build/fuzz/fuzz_$target"
  dict="$scratch/$target.dict"
  if [[ $target == roundtrip ]]; then
    cat "$root/fuzz/roundtrip.dict" "$root/fuzz/sc.dict" "$root/fuzz/nff.dict" \
      "$root/fuzz/obj.dict" >"$dict"
  else
    cp "$root/fuzz/$target.dict" "$dict"
  fi
  artifacts="$scratch/artifacts-$target"
  mkdir -p "$artifacts"
  flags=(-rss_limit_mb=2048 -timeout=10 -artifact_prefix="$artifacts/")

  # Reproducers of fixed crashes, each run once: they must stay fixed.
  regressions=()
  if [[ -d $root/fuzz/regressions/$target ]]; then
    while IFS= read -r -d '' f; do regressions+=("$f"); done \
      < <(find "$root/fuzz/regressions/$target" -type f -print0 | sort -z)
  fi
  if ((${#regressions[@]})); then
    echo "== $target: ${#regressions[@]} regression input(s)"
    if ! "$exe" "${flags[@]}" "${regressions[@]}" >"$scratch/$target-regressions.log" 2>&1; then
      # libFuzzer names each file before running it: the last one named crashed.
      crashed=$(sed -n 's/^Running: //p' "$scratch/$target-regressions.log" | tail -n 1)
      echo "FAILED: $target crashes on a reproducer in fuzz/regressions/$target"
      report "$scratch/$target-regressions.log" "$crashed"
      echo "$target (regressions)" >"$scratch/$target.failed"
      : >"$scratch/$target.done"
      return
    fi
  fi

  echo "== $target: fuzzing for $seconds s"
  corpus="$scratch/corpus-$target"
  cp -r "$root/fuzz/corpus/$target" "$corpus"
  log="$scratch/$target.log"
  status=0
  "$exe" "$corpus" "${flags[@]}" -dict="$dict" -max_total_time="$seconds" \
    -print_final_stats=1 >"$log" 2>&1 || status=$?
  # The last status line: "#RUNS <event> cov: C ft: F corp: N/SIZE ... exec/s: E rss: R".
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || true)
  rate=$(grep -oE 'stat::average_exec_per_sec: *[0-9]+' "$log" | grep -oE '[0-9]+$' || true)
  cov=$(grep -oE 'cov: [0-9]+' <<<"$last" | tail -n 1 | cut -d' ' -f2 || true)
  ft=$(grep -oE 'ft: [0-9]+' <<<"$last" | tail -n 1 | cut -d' ' -f2 || true)
  corp=$(grep -oE 'corp: [0-9]+' <<<"$last" | tail -n 1 | cut -d' ' -f2 || true)
  line=$(printf '%-10s %10s execs %6s exec/s  cov %6s  ft %6s  corpus %5s' "$target" \
    "${runs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}")
  if ((status != 0)); then
    echo "FAILED: $target (libFuzzer exit status $status)"
    report "$log" "$artifacts"/*
    echo "$target" >"$scratch/$target.failed"
    line+="  FAILED"
  fi
  echo "$line"
  echo "$line" >"$scratch/$target.summary"
  : >"$scratch/$target.done"
}

# The targets side by side, one per core (each libFuzzer process is single
# threaded), their outputs printed in order once all have run.
jobs=${PRISM_FUZZ_JOBS:-$(nproc)}
running=0
for target in "${targets[@]}"; do
  fuzz_target "$target" >"$scratch/$target.out" 2>&1 &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=()
summary=()
for target in "${targets[@]}"; do
  cat "$scratch/$target.out"
  [[ -f $scratch/$target.summary ]] && summary+=("$(cat "$scratch/$target.summary")")
  if [[ -f $scratch/$target.failed ]]; then
    failed+=("$(cat "$scratch/$target.failed")")
  elif [[ ! -f $scratch/$target.done ]]; then
    # A command of fuzz_target failed (errexit ended its job early).
    failed+=("$target (the script stopped early: see its output above)")
  fi
done

echo "== Summary ($((SECONDS - started)) s in all, build included)"
((${#summary[@]} == 0)) || printf '%s\n' "${summary[@]}"
if ((${#failed[@]})); then
  echo "fuzzing failed: ${failed[*]}"
  exit 1
fi
echo "fuzzing clean"

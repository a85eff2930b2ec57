#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) in their own build directory and runs
# each for SECONDS seconds (default 60), starting from its seed corpus in fuzz/corpus/<target>/.
# New inputs go to <build>/corpus/<target>/ (the tree's seeds are never written); a crash, leak,
# sanitizer report or timeout is saved as <build>/artifacts/<target>/... and makes the script fail:
# turn it into a regression test. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
build=${PVATT_FUZZ_BUILD_DIR:-build-fuzz}
jobs=${PVATT_FUZZ_JOBS:-$(nproc)}  # targets built and run at once

cmake --preset fuzz -B "$build" \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} \
  ${CMAKE_C_COMPILER_LAUNCHER:+-DCMAKE_C_COMPILER_LAUNCHER=$CMAKE_C_COMPILER_LAUNCHER} >/dev/null
targets=("$@")
# Only the targets named (all of them when none is): a state fuzzer builds a whole block with ASan.
if [ ${#targets[@]} -eq 0 ]; then
  cmake --build "$build" --target fuzzers -j"$jobs"
else
  cmake --build "$build" --target "${targets[@]}" -j"$jobs"
fi

if [ ${#targets[@]} -eq 0 ]; then
  for f in "$build"/fuzzers/fuzz_*; do targets+=("$(basename "$f")"); done
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# One target: exit status 0 when it found nothing (its log in $build/$t.log).
fuzz_one() {
  local t=$1 seeds work artifacts
  seeds=fuzz/corpus/${t#fuzz_}
  work=$build/corpus/$t
  artifacts=$build/artifacts/$t
  mkdir -p "$work" "$artifacts"
  [ -d "$seeds" ] || seeds=
  [ "$t" = fuzz_ssd ] && seeds="$seeds harness/systems"  # the bundled systems are seeds too
  # -timeout: one input taking longer than 10 s is a hang; -rss_limit_mb: one using more than 2 GB is exhaustion.
  "$build/fuzzers/$t" "$work" $seeds -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -artifact_prefix="$artifacts/" -print_final_stats=1 2>"$build/$t.log"
}

# $jobs targets at a time (each fuzzer is one process on one core), each for the full SECONDS.
failed=()
declare -A running=()
finish() {  # waits for the target whose process is $1 and reports it
  local pid=$1 t=${running[$1]}
  unset "running[$pid]"
  if ! wait "$pid"; then
    failed+=("$t")
    tail -40 "$build/$t.log" >&2
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$build/$t.log" | sed "s/^/  $t /" || true
}
for t in "${targets[@]}"; do
  while [ ${#running[@]} -ge "$jobs" ]; do
    oldest=$(printf '%s\n' "${!running[@]}" | sort -n | head -1)
    finish "$oldest"
  done
  echo "fuzz.sh: $t for ${seconds} s"
  fuzz_one "$t" &
  running[$!]=$t
done
for pid in $(printf '%s\n' "${!running[@]}" | sort -n); do finish "$pid"; done
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz.sh: findings in ${failed[*]} (inputs in $build/artifacts/)" >&2
  exit 1
fi
echo "fuzz.sh: no findings in ${#targets[@]} targets"

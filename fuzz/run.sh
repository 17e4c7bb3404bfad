#!/bin/sh
# Builds the libFuzzer targets with clang (ASan + UBSan + libFuzzer) in build-fuzz and runs each one
# for a fixed number of inputs, starting from the committed seed corpus in fuzz/corpus/<reader>/
# (new inputs go to a temporary folder; the committed corpus is not changed).
#
#   fuzz/run.sh [RUNS]        RUNS per target, default 1000000 (FUZZ_BUILD_DIR overrides the build
#                             dir, FUZZ_TARGETS="csv dmis" runs only those readers)
#
# Prints one line per target: runs, seconds, result. Exit 0 when no target found a crash, leak,
# sanitizer report or timeout; crash inputs are kept in build-fuzz/artifacts/.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-1000000}
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
targets=${FUZZ_TARGETS:-"csv project setup_model thermal_log probe_points dmis hole_table cmm_text_report stl dfq calypso qif shdr"}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMETROFIT_FUZZ=ON -DMETROFIT_BUILD_GUI=OFF \
  -DMETROFIT_BUILD_TESTS=OFF -DMETROFIT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j2 --target $(for t in $targets; do printf 'fuzz_%s ' "$t"; done) >/dev/null

mkdir -p "$build/artifacts"
failed=0
for t in $targets; do
  work=$(mktemp -d)
  log="$build/fuzz_$t.log"
  start=$(date +%s)
  if "$build/bin/fuzz_$t" -runs="$runs" -max_len=65536 -timeout=10 -rss_limit_mb=4096 \
      -artifact_prefix="$build/artifacts/$t-" -print_final_stats=1 "$work" "$root/fuzz/corpus/$t" >"$log" 2>&1; then
    result="no crash"
  else
    result="FAILED (see $log and $build/artifacts/)"
    failed=1
  fi
  secs=$(( $(date +%s) - start ))
  done_runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  printf 'fuzz_%-14s %10s runs %6s s  corpus %5s  %s\n' "$t" "${done_runs:-?}" "$secs" \
    "$(ls "$work" | wc -l)" "$result"
  rm -rf "$work"
done
exit $failed

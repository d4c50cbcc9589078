#!/usr/bin/env bash
# Fuzz every input reader (fuzz/README.md): set up, build the fuzz preset
# (clang, libFuzzer, ASan + UBSan) and run each target for a bounded time on a
# scratch corpus seeded from data/ and fuzz/corpus/.
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET]    (default 60)
# Prints the executions each target reached; exits 1 when any target found
# something (crash, sanitizer report, leak, timeout, out-of-memory, an
# unexpected exception), naming the saved input under build/fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2
  exit 2
fi

bash scripts/setup.sh --tests
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"

build="$PWD/build/fuzz"
work="$build/run"          # scratch corpora and logs, rebuilt on every run
findings="$build/findings" # inputs that found something, kept across runs
rm -rf "$work"
mkdir -p "$work" "$findings"

seed() {  # seed TARGET FILE...: the target's scratch corpus starts from copies
  mkdir -p "$work/corpus/$1"
  cp "${@:2}" "$work/corpus/$1/"
}
seed scene data/scenes/*.json
seed csv data/lab/*.csv fuzz/corpus/point_table/*
seed point_table fuzz/corpus/point_table/* data/lab/*.csv
seed set fuzz/corpus/set/*

# allow_addr2line: readable stacks even without llvm-symbolizer (package llvm-14).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allow_addr2line=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:allow_addr2line=1}"

# Scenes are refused before they allocate more than 90 % of this (the size check
# of ffp's MPM kinds), so that a mesh of 1e-5 m is a SceneError, not an OOM
# finding; the models the fuzzers may build stay well inside -rss_limit_mb.
export FFP_MEMORY_LIMIT_MB="${FFP_MEMORY_LIMIT_MB:-200}"

found=0
for target in scene csv point_table set; do
  log="$work/$target.log"
  status=0
  "$build/fuzz/fuzz_$target" "$work/corpus/$target" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix="$findings/$target-" >"$log" 2>&1 || status=$?
  runs=$(sed -n 's/^Done \([0-9]*\) runs in .*/\1/p' "$log" | tail -n 1)
  if [ "$status" -eq 0 ] && [ -n "$runs" ]; then
    echo "fuzz: $target: $runs executions in $seconds s, nothing found"
    continue
  fi
  found=1
  input=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -n 1)
  reached=$(sed -n 's/^#\([0-9]*\).*/\1/p' "$log" | tail -n 1)
  echo "fuzz: $target: FINDING (exit $status) after ${reached:-0} executions"
  grep -E 'ERROR:|runtime error:|terminate called|what\(\):|SUMMARY:' "$log" | head -n 8 | sed 's/^/fuzz:   /'
  echo "fuzz: $target: input ${input:-(none saved)}; log $log"
  echo "fuzz: $target: repeat with $build/fuzz/fuzz_$target ${input:-INPUT}"
done
if [ "$found" -ne 0 ]; then
  echo "fuzz: FAILED: a target found something (see above)"
  exit 1
fi
echo "fuzz: all targets clean ($seconds s each)"

#!/usr/bin/env bash
# Set up, build and run the whole test suite.
#   bash scripts/test.sh             Release build (build/release)
#   bash scripts/test.sh --sanitize  AddressSanitizer + UBSan build (build/asan)
set -euo pipefail
cd "$(dirname "$0")/.."
preset=release
if [ "${1:-}" = "--sanitize" ]; then preset=asan; fi

bash scripts/setup.sh --tests
# The tests build the libraries one file at a time, as CI does, even after main.sh's unity build.
# main.sh leaves the tests and benchmarks out of the shared release tree: turn them back on.
extra=()
if [ "$preset" = release ]; then extra=(-DFFP_BUILD_BENCHMARKS=ON); fi
cmake --preset "$preset" -DFFP_UNITY_BUILD=OFF -DFFP_BUILD_TESTS=ON "${extra[@]}" >/dev/null
cmake --build --preset "$preset"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --preset "$preset" -j 2

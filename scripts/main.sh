#!/usr/bin/env bash
# Set up, build Release and run the main job: the default FFP validation study
# and its report (report/report.md with figures).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release -DFFP_UNITY_BUILD=ON -DFFP_BUILD_TESTS=OFF -DFFP_BUILD_BENCHMARKS=OFF >/dev/null
# Only the program, as a unity build: the report needs nothing else (tests and benchmarks are a
# third of the build; FFP_UNITY_BUILD in CMakeLists.txt).
cmake --build --preset release --target ffp
./build/release/drivers/app/ffp report --out report "$@"

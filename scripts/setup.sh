#!/usr/bin/env bash
# Install the Debian packages ffp needs. Idempotent: on a machine that has
# everything it installs nothing and says so.
#   bash scripts/setup.sh          what the program and the main job need (compiler, libraries, gnuplot)
#   bash scripts/setup.sh --tests  that, plus what only the tests, benchmarks and fuzzing use
set -euo pipefail

packages=(
  build-essential cmake ninja-build
  libeigen3-dev libceres-dev libgsl-dev nlohmann-json3-dev libcli11-dev
  gnuplot-nox                  # the figures of every run and of the report
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(
    catch2 libbenchmark-dev      # the test suite and the benchmarks
    clang-14 libclang-rt-14-dev  # libFuzzer and its sanitizers, for scripts/fuzz.sh
    clang-format-14              # the layout check of the tests (.clang-format)
    slurm-wlm munge parallel     # the scheduler tests: a one-node Slurm, GNU parallel
  )
elif [ -n "${1:-}" ]; then
  echo "usage: bash scripts/setup.sh [--tests]" >&2
  exit 2
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} dependencies are already installed; nothing to do"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
    echo "setup: missing ${missing[*]} and not root (no sudo): install them as root" >&2
    exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"

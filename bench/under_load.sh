#!/usr/bin/env bash
# The reference FFP run beside busy processes: its wall time must not collapse when
# other processes take the cores.
#   bash bench/under_load.sh [FFP_BINARY] [REPEATS]
# Prints the median wall time of: one thread and the default (the thread
# governor) with two busy processes beside the run, and the default and
# two threads forced with nothing beside it. A benchmark, not a test: times
# depend on the machine. Run it on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
ffp=${1:-build/release/drivers/app/ffp}
repeats=${2:-3}
scene=data/scenes/ffp_reference.json
scratch=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$scratch"' EXIT

median_time() {  # median wall time of "$@" over $repeats runs
  local times=()
  for _ in $(seq "$repeats"); do
    local start end
    start=$(date +%s.%N)
    "$@" run "$scene" --out "$scratch/out" --quiet --force
    end=$(date +%s.%N)
    times+=("$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.2f", b - a}')")
  done
  printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores; $ffp"
idle_default=$(median_time "$ffp")
idle_two=$(median_time env OMP_NUM_THREADS=2 "$ffp")
echo "idle:   default $idle_default s, OMP_NUM_THREADS=2 $idle_two s"
for _ in 1 2; do (while :; do :; done) & done
sleep 1
loaded_one=$(median_time env OMP_NUM_THREADS=1 "$ffp")
loaded_default=$(median_time "$ffp")
loaded_two_active=$(median_time env OMP_NUM_THREADS=2 OMP_WAIT_POLICY=active "$ffp")
echo "loaded (2 busy processes): OMP_NUM_THREADS=1 $loaded_one s, default $loaded_default s," \
     "OMP_NUM_THREADS=2 active $loaded_two_active s"
echo "loaded default / loaded one thread = $(awk -v a="$loaded_default" -v b="$loaded_one" 'BEGIN {printf "%.2f", a / b}')"

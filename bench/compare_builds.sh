#!/usr/bin/env bash
# Side-by-side speed of builds of the MPM step: the protocol of every before/after
# table in docs/performance.md, in one command.
#   bash bench/compare_builds.sh [-r ROUNDS] [-t "1 2"] [-s STAGE_STEPS] BUILD [BUILD...]
# BUILD: a git revision (checked out into a worktree under $FFP_COMPARE_DIR, default
# /tmp/ffp-compare, and its ffp_mpm_bench built there once), or the path of an
# ffp_mpm_bench binary. The first BUILD is the reference of the ratios. The worktrees
# stay for the next comparison; delete the directory and `git worktree prune` to drop them.
#
# Each round runs every build once per thread count, alternating builds, so that the
# host's drift (a third from hour to hour on the 2-core EPYC guests) falls on all of
# them alike; one-thread runs are pinned to one core. Every run is BM_MpmStep on the
# 102,400-particle sand block, a fixed 300 steps after five warm-up steps, linear and
# GIMP. A revision whose benchmark predates the fixed window (commit c15f4a0) gets it
# patched in, so that every build does the same work. Prints the median M particle-steps/s of
# each build, and each build's ratio to the first: the median and the range of the
# rounds' ratios (a round's ratio compares runs minutes apart, not hours).
# With -s N, each run also prints its stage timers over N steps (FFP_MPM_BENCH_STAGES).
# A benchmark, not a test: run it on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=5
threads="1 2"
stage_steps=""
usage() {
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}
while getopts "r:t:s:h" option; do
  case $option in
    r) rounds=$OPTARG ;;
    t) threads=$OPTARG ;;
    s) stage_steps=$OPTARG ;;
    *) usage ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || usage
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "compare_builds: -r ROUNDS must be a whole number >= 1 (got '$rounds')" >&2; exit 2; }
for t in $threads; do
  [[ $t =~ ^[1-9][0-9]*$ ]] || { echo "compare_builds: -t takes thread counts >= 1 (got '$t')" >&2; exit 2; }
done

root=${FFP_COMPARE_DIR:-/tmp/ffp-compare}
mkdir -p "$root"

# The benchmark binary of one BUILD argument (built if it is a revision).
binary_of() {
  local build=$1
  if [ -f "$build" ] && [ -x "$build" ]; then
    echo "$build"
    return
  fi
  local sha
  sha=$(git rev-parse --verify --quiet "$build^{commit}") ||
    { echo "compare_builds: '$build' is neither an executable nor a git revision" >&2; exit 2; }
  local tree=$root/${sha:0:12}
  local bin=$tree/build/bench/ffp_mpm_bench
  if [ ! -x "$bin" ]; then
    if [ ! -d "$tree" ]; then
      git worktree add --detach --force "$tree" "$sha" >/dev/null 2>&1 ||
        { echo "compare_builds: could not check out $build into $tree" >&2; exit 1; }
    fi
    if ! grep -q kMeasuredSteps "$tree/bench/mpm_bench.cpp"; then  # before the fixed window
      sed -i 's/->Unit(benchmark::kMillisecond)/->Iterations(300)->Unit(benchmark::kMillisecond)/' \
        "$tree/bench/mpm_bench.cpp"
    fi
    echo "compare_builds: building $build (${sha:0:12}) in $tree" >&2
    cmake -S "$tree" -B "$tree/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFFP_UNITY_BUILD=OFF >"$tree/build.log" 2>&1 &&
      cmake --build "$tree/build" -j "$(nproc)" --target ffp_mpm_bench >>"$tree/build.log" 2>&1 ||
      { echo "compare_builds: the build of $build failed; see $tree/build.log" >&2; exit 1; }
  fi
  echo "$bin"
}

names=()
binaries=()
for build in "$@"; do
  names+=("$build")
  binaries+=("$(binary_of "$build")")
done

pin=""
if command -v taskset >/dev/null 2>&1 && [ "$(nproc)" -ge 2 ]; then pin="taskset -c 1"; fi
results=$(mktemp)
trap 'rm -f "$results"' EXIT
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores; $rounds rounds" >&2
for round in $(seq "$rounds"); do
  for t in $threads; do
    for b in "${!binaries[@]}"; do
      runner=""
      [ "$t" = 1 ] && runner=$pin
      output=$(env OMP_NUM_THREADS="$t" ${stage_steps:+FFP_MPM_BENCH_STAGES=$stage_steps} $runner "${binaries[$b]}" \
        --benchmark_filter="BM_MpmStep/gimp:[01]/threads:$t/cells:160" 2>&1) ||
        { echo "compare_builds: ${names[$b]} failed:" >&2; echo "$output" >&2; exit 1; }
      [ -n "$stage_steps" ] && echo "$output" | grep -v '^\(-\|Benchmark\|Run on\|Load\|\*\*\*\|[0-9]\{4\}-\)' >&2
      # One line per shape: round threads build shape rate.
      echo "$output" | awk -v r="$round" -v t="$t" -v b="$b" '
        /BM_MpmStep\/gimp:[01]\// {
          shape = ($0 ~ /gimp:1/) ? "GIMP" : "linear"
          if (match($0, /particle_steps_per_s=[0-9.]+[kMG]?/)) {
            v = substr($0, RSTART + 21, RLENGTH - 21); u = substr(v, length(v)); x = v + 0
            if (u == "k") x /= 1000; else if (u == "G") x *= 1000; else if (u != "M") x /= 1e6
            printf "%d %d %d %s %.4f\n", r, t, b, shape, x
          }
        }' >>"$results"
    done
    echo "  round $round, $t thread(s) done" >&2
  done
done

# Medians per (threads, shape, build), and each build's per-round ratios to build 0.
printf '%s\n' "${names[@]}" | awk -v results="$results" '
  function median(list,    n, a, i, j, x) {
    n = split(list, a, " ")
    for (i = 2; i <= n; ++i) { x = a[i]; for (j = i - 1; j >= 1 && a[j] > x; --j) a[j + 1] = a[j]; a[j + 1] = x }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  function range(list,    n, a, i, lo, hi) {
    n = split(list, a, " "); lo = hi = a[1]
    for (i = 2; i <= n; ++i) { if (a[i] < lo) lo = a[i]; if (a[i] > hi) hi = a[i] }
    return sprintf("%.2f-%.2f", lo, hi)
  }
  { name[NR - 1] = $0; builds = NR }
  END {
    while ((getline line < results) > 0) {
      split(line, f, " "); key = f[2] " " f[4]
      rate[key, f[3], f[1]] = f[5]; rates[key, f[3]] = rates[key, f[3]] " " f[5]
      if (!(key in seen)) { seen[key] = 1; keys[++nkeys] = key }
      if (f[1] > maxround) maxround = f[1]
    }
    for (b = 0; b < builds; ++b) printf "build %d: %s\n", b, name[b]
    printf "%-8s %-7s %-6s %12s %8s %12s\n", "threads", "shape", "build", "M p-steps/s", "ratio", "ratio range"
    for (k = 1; k <= nkeys; ++k) {
      split(keys[k], kk, " ")
      for (b = 0; b < builds; ++b) {
        ratios = ""
        for (r = 1; r <= maxround; ++r)
          if (((keys[k], b, r) in rate) && ((keys[k], 0, r) in rate))
            ratios = ratios " " rate[keys[k], b, r] / rate[keys[k], 0, r]
        printf "%-8s %-7s %-6d %12.2f %8.3f %12s\n", kk[1], kk[2], b,
               median(substr(rates[keys[k], b], 2)), median(substr(ratios, 2)), range(substr(ratios, 2))
      }
    }
  }'

#!/usr/bin/env bash
# Run every shipped scene with one ffp binary and keep what each run writes, so that
# two builds can be compared file by file (a refactoring must leave them byte-identical).
#
#   scripts/scene_outputs.sh FFP_BINARY OUT_DIR [GLOB]   run every scene (or those whose name matches GLOB)
#                                                        into OUT_DIR/<scene>/
#   scripts/scene_outputs.sh --compare DIR_A DIR_B       compare two such folders (or two runs of one scene);
#                                                        exit 1 on a difference
#
# Compared: every file a run writes except images and the summary's machine-dependent keys
# (wall time, thread counts, version). The scenes that take minutes run a shortened window
# (the overrides below); the same overrides are used for both builds.
set -euo pipefail

if [ "${1:-}" = "--compare" ]; then
  exec python3 - "$2" "$3" <<'EOF'
import json, os, sys
a, b = sys.argv[1], sys.argv[2]
volatile = {"wall_time_s", "threads", "mpm_threads", "ffp_version", "runs_wall_time_s", "report_version"}
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in volatile and "wall" not in k}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
def files(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            if f.endswith(".png") or f.startswith(".ffp-output") or f.endswith(".log") or f == "timing.txt":
                continue
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out
fa, fb = files(a), files(b)
bad = 0
for f in sorted(fa ^ fb):
    print(f"only in {'A' if f in fa else 'B'}: {f}"); bad += 1
for f in sorted(fa & fb):
    pa, pb = os.path.join(a, f), os.path.join(b, f)
    if f.endswith(".json"):
        same = strip(json.load(open(pa))) == strip(json.load(open(pb)))
    else:
        same = open(pa, "rb").read() == open(pb, "rb").read()
    if not same:
        print(f"differs: {f}"); bad += 1
print(f"{len(fa & fb)} files compared, {bad} differences")
sys.exit(1 if bad else 0)
EOF
fi

ffp=$(realpath "$1")
out=$(realpath -m "$2")
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"

# Shortened windows for the scenes that take minutes (the same for every build compared).
declare -A quick=(
  [ffp_steel]="--set end_time_s=0.004"
  [ffp_micropolar]="--set end_time_s=0.01"
  [calibration_dr15_mpm_05cm]="--set max_iterations=1"
  [calibration_dr15_mpm_1cm]="--set max_iterations=1"
  [inverse_reference]="--set max_iterations=1"
  [inverse_experiment]="--set max_iterations=1"
)

for scene in "$root"/data/scenes/*.json; do
  name=$(basename "$scene" .json)
  # shellcheck disable=SC2053
  [[ $name == ${3:-*} ]] || continue
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  if (cd "$root" && "$ffp" run "$scene" ${quick[$name]:-} --out "$out/$name" --force >"$out/$name.log" 2>&1); then
    status=ok
  else
    status="exit $?"
  fi
  printf '%-34s %-8s %6.1f s\n' "$name" "$status" "$(echo "$(date +%s.%N) - $start" | bc)"
done | tee "$out/timing.txt"

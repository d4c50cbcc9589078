#!/usr/bin/env python3
"""A synthetic FFP record from a run of this solver: its deceleration with
Gaussian noise (a share of the peak, 1 % by default) added to every row, in the
`record` kind's columns (time_s, deceleration_g: net, + while slowing).

    python3 scripts/make_synthetic_record.py RUN_DIR OUT.csv [NOISE_SHARE] [SEED]

RUN_DIR is an `ffp run` output folder (its history.csv is read). Python's
standard library only, so that it runs wherever the program builds."""
import csv
import random
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run_dir, out = sys.argv[1], sys.argv[2]
    share = float(sys.argv[3]) if len(sys.argv) > 3 else 0.01
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    rows = list(csv.DictReader(open(f"{run_dir}/history.csv")))
    peak = max(float(r["deceleration_g"]) for r in rows)
    noise = random.Random(seed)
    lines = [f"# synthetic record: {run_dir}/history.csv, Gaussian noise sigma = {share:g} x peak ({share * peak:.4g} g), seed {seed}",
             "time_s,deceleration_g"]
    for r in rows:
        lines.append(f"{float(r['time_s']):.10g},{float(r['deceleration_g']) + noise.gauss(0.0, share * peak):.10g}")
    with open(out + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    import os
    os.replace(out + ".tmp", out)


if __name__ == "__main__":
    main()

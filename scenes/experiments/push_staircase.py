#!/usr/bin/env python3
"""The staircase that runs push-recovery-seeds.sweep.xml within a budget:

    scenes/experiments/push_staircase.py <stride binary> <out dir> [extra sweep flags...]

Every (speed, control) cell walks unpushed and at 10 N in each direction; a (speed, direction,
control) cell walks at 20, 30, 40 N only while every seed kept its walk at the push before. Each
step is one `stride sweep ... --resume --only ...` (one process, --jobs 1), so a stopped study
keeps every walk it finished and the same command carries on.
"""
import csv
import os
import subprocess
import sys
import time

SWEEP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "push-recovery-seeds.sweep.xml")
LABEL = {"forward": "fwd", "backward": "back", "left": "left"}
SEEDS = [str(s) for s in range(1, 21)]


def rows(out):
    path = os.path.join(out, "runs.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def every_seed_kept(rs, speed, control, direction, n):
    walks = [r for r in rs if (r["speed"], r["control"], r["dir"], r["N"]) ==
             (speed, control, direction, str(n))]
    return len(walks) == len(SEEDS) and all(r["status"] == "ok" and r["lost"] == "0"
                                            for r in walks)


def step(stride, out, extra, speed, control, pushes):
    cmd = [stride, "sweep", SWEEP, "--physics", "solver=exact", "--jobs", "1", "--out", out,
           "--resume", "--quiet", "--only", "speed=" + speed, "--only", "control=" + control,
           "--only", "push=" + ",".join(pushes), "--only", "seed=" + ",".join(SEEDS)] + extra
    print(time.strftime("%H:%M:%S"), " ".join(cmd), flush=True)
    subprocess.run(cmd, stdout=subprocess.DEVNULL, check=False)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    stride, out, extra = sys.argv[1], sys.argv[2], sys.argv[3:]
    for n in (0, 10, 20, 30, 40):
        for speed in ("slow", "medium", "fast"):
            for control in ("posture", "recovery"):
                if n == 0:
                    pushes = ["0"]
                elif n == 10:
                    pushes = [LABEL[d] + "10" for d in LABEL]
                else:
                    rs = rows(out)
                    pushes = [LABEL[d] + str(n) for d in LABEL
                              if every_seed_kept(rs, speed, control, d, n - 10)]
                if pushes:
                    step(stride, out, extra, speed, control, pushes)


if __name__ == "__main__":
    main()

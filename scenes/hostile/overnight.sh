#!/usr/bin/env bash
# Runs overnight.sweep.xml (1000 posture walks + 250 broken runs) with the traces of two runs
# (hip_slow and hip_medium, seed 1) blocked by directories, then checks what
# docs/sweeps-and-tuning.md promises: the sweep ends by itself (exit 1: some runs failed), every
# good walk has its row, every broken run is a failed row with its reason, and the blocked traces
# fail their two runs and nothing else.
#   scenes/hostile/overnight.sh <build dir> [jobs=2] [out=overnight-sweep] [seeds=125]
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: overnight.sh <build dir> [jobs] [out] [seeds]}
jobs=${2:-2}
out=${3:-overnight-sweep}
seeds=${4:-125}
rm -rf "$out"
mkdir -p "$out/traces/run-0.csv" "$out/traces/run-$seeds.csv"  # hip_slow and hip_medium, seed 1
start=$(date +%s)
"$build/stride" sweep "$here/overnight.sweep.xml" --seeds "$seeds" --jobs "$jobs" --out "$out" \
  --no-plots 2>"$out/stderr.txt" >"$out/stdout.txt"
code=$?
echo "exit $code after $(($(date +%s) - start)) s (expected 1: some runs failed)"
python3 - "$out/runs.csv" "$seeds" <<'PY'
import csv, collections, sys
rows = list(csv.DictReader(open(sys.argv[1])))
seeds = int(sys.argv[2])
broken = {"broken_urdf", "pushed_apart"}
good = [r for r in rows if r["case"] not in broken]
bad = [r for r in rows if r["case"] in broken]
kinds = collections.Counter()
for r in rows:
    if r["status"] == "failed":
        why = r["reason"]
        kinds["bad URDF" if "inertia" in why else "diverged" if "diverged" in why
              else "trace not written" if "trace not written" in why else "other: " + why[:60]] += 1
print(f"rows {len(rows)} (planned {10 * seeds}); good walks {len(good)}, of them ok "
      f"{sum(r['status'] == 'ok' for r in good)}, fell {sum(r['fell'] in ('1', 'true', 'yes') for r in good)}")
print(f"broken runs {len(bad)}, failed {sum(r['status'] == 'failed' for r in bad)}")
print("failed rows by reason:", dict(kinds))
ids = sorted(int(r["run"]) for r in rows)
ok = len(rows) == 10 * seeds and ids == list(range(10 * seeds)) and \
     all(r["status"] == "failed" and r["reason"] for r in bad) and \
     sum(r["status"] == "failed" for r in good) == kinds["trace not written"] == 2
print("checks:", "all hold" if ok else "FAILED")
sys.exit(0 if ok else 1)
PY

#!/usr/bin/env bash
# Throughput of the sweep engine on the posture study's walks (the nine cases of
# scenes/experiments/posture.sweep.xml, seeds 1..S): the same walks one `stride run` at a time,
# then through `stride sweep` with --jobs 1, --jobs 2 and `mpirun -n 2`. Prints wall seconds,
# walks per second and the speed-up over --jobs 1; checks that the sweeps' runs.csv are
# byte-identical; and gives the engine's overhead per run (wall x workers minus the runs' own
# seconds from timing.csv, over the runs) against a walk's own time.
#   bench/sweep_throughput.sh <build dir> [seeds=2]
set -euo pipefail
build=$(realpath "$1")
seeds=${2:-2}
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sweep=$here/scenes/experiments/posture.sweep.xml
cases="none_slow none_medium none_fast hip_slow hip_medium hip_fast ankle_slow ankle_medium ankle_fast"
walks=$((9 * seeds))
now() { date +%s.%N; }

# The same walks as the sweep's: 2 s standing + 15 s pattern + 1 s.
t0=$(now)
for c in $cases; do
  for s in $(seq 1 "$seeds"); do
    "$build/stride" run "$here/scenes/experiments/$c.xml" --seconds 18 --seed "$s" > /dev/null
  done
done
t1=$(now)
echo "single $(python3 -c "print($t1 - $t0)") 1" > "$tmp/walls"

sweep_with() {  # name, workers, command words before the sweep's own
  local name=$1 workers=$2; shift 2
  local a b
  a=$(now)
  "$@" sweep "$sweep" --seeds "$seeds" --quiet --no-plots --out "$tmp/$name" ${JOBS_FLAG:-} > /dev/null
  b=$(now)
  echo "$name $(python3 -c "print($b - $a)") $workers" >> "$tmp/walls"
}
JOBS_FLAG="--jobs 1" sweep_with jobs1 1 "$build/stride"
JOBS_FLAG="--jobs 2" sweep_with jobs2 2 "$build/stride"
if command -v mpirun > /dev/null; then
  sweep_with mpi2 2 mpirun --allow-run-as-root --oversubscribe -n 2 "$build/stride"
fi

python3 - "$tmp" "$walks" <<'PY'
import csv, sys, pathlib
tmp, walks = pathlib.Path(sys.argv[1]), int(sys.argv[2])
walls = {n: (float(t), int(w)) for n, t, w in (l.split() for l in (tmp / "walls").read_text().splitlines())}
names = {"single": "stride run, one at a time", "jobs1": "stride sweep --jobs 1",
         "jobs2": "stride sweep --jobs 2", "mpi2": "mpirun -n 2 stride sweep"}
base = walls["jobs1"][0]
reference = (tmp / "jobs1" / "runs.csv").read_bytes()
for n, (t, w) in walls.items():
    line = f"{names[n]:28s} {t:8.1f} s  {walks / t:6.3f} walks/s  {base / t:5.2f}x of --jobs 1"
    if n != "single":
        rows = list(csv.DictReader(open(tmp / n / "timing.csv")))
        own = sum(float(r["seconds"]) for r in rows)
        overhead = (t * w - own) / len(rows)
        line += f"  overhead {overhead:6.3f} s/run = {100 * overhead / (own / len(rows)):5.2f} % of a walk"
        line += "  rows identical" if (tmp / n / "runs.csv").read_bytes() == reference else "  ROWS DIFFER"
    print(line)
PY

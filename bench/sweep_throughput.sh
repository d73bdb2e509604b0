#!/usr/bin/env bash
# Throughput of the sweep engine on the posture study's walks (the nine cases of
# scenes/experiments/posture.sweep.xml, seeds 1..S): the same walks one `stride run` at a time,
# then through `stride sweep` with --jobs 1, --jobs 2 and `mpirun -n 2`. The four take turns,
# R rounds of each in one invocation, so that on a shared machine they see the same load (compare
# the ratios, not the absolute figures). Prints for each: wall seconds, CPU seconds (user + system of it and
# every process it started), walks per second and per CPU second, the speed-up over --jobs 1;
# checks that the sweeps' runs.csv are byte-identical; and gives the engine's overhead per run
# against a walk: CPU seconds per walk above `stride run`'s (which also loads its scene and
# builds its world once per walk), and wall x workers minus the runs' own seconds (timing.csv).
#   bench/sweep_throughput.sh <build dir> [seeds=2] [rounds=1]
set -euo pipefail
build=$(realpath "$1")
seeds=${2:-2}
rounds=${3:-1}
here=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sweep=$here/scenes/experiments/posture.sweep.xml
cases="none_slow none_medium none_fast hip_slow hip_medium hip_fast ankle_slow ankle_medium ankle_fast"
walks=$((9 * seeds))

# Runs "$@" and appends "<name> <wall s> <cpu s> <workers>" to $tmp/walls.
measure() {
  local name=$1 workers=$2; shift 2
  python3 - "$tmp/walls" "$name" "$workers" "$@" <<'PY'
import resource, subprocess, sys, time
walls, name, workers, argv = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
before = resource.getrusage(resource.RUSAGE_CHILDREN)
t0 = time.monotonic()
subprocess.run(["bash", "-c", " ".join(argv)], check=True, stdout=subprocess.DEVNULL)
wall = time.monotonic() - t0
after = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
open(walls, "a").write(f"{name} {wall} {cpu} {workers}\n")
PY
}

# The same walks as the sweep's: 2 s standing + 15 s pattern + 1 s.
singles=$tmp/singles.sh
for c in $cases; do
  for s in $(seq 1 "$seeds"); do
    echo "'$build/stride' run '$here/scenes/experiments/$c.xml' --seconds 18 --seed $s > /dev/null"
  done
done > "$singles"
flags="--seeds $seeds --quiet --no-plots"
for r in $(seq 1 "$rounds"); do
  measure single 1 bash "$singles"
  measure jobs1 1 "'$build/stride'" sweep "'$sweep'" $flags --jobs 1 --out "'$tmp/jobs1-$r'"
  measure jobs2 2 "'$build/stride'" sweep "'$sweep'" $flags --jobs 2 --out "'$tmp/jobs2-$r'"
  if command -v mpirun > /dev/null; then
    measure mpi2 2 mpirun --allow-run-as-root --oversubscribe -n 2 "'$build/stride'" sweep \
      "'$sweep'" $flags --out "'$tmp/mpi2-$r'"
  fi
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores"
echo "each turn (name, wall s, CPU s, workers):"
sed 's/^/  /' "$tmp/walls"

python3 - "$tmp" "$walks" "$rounds" <<'PY'
import csv, sys, pathlib
tmp, rounds = pathlib.Path(sys.argv[1]), int(sys.argv[3])
walks = int(sys.argv[2]) * rounds
m = {}
for n, t, c, w in (l.split() for l in (tmp / "walls").read_text().splitlines()):
    t0, c0, _ = m.get(n, (0.0, 0.0, 0))
    m[n] = (t0 + float(t), c0 + float(c), int(w))
names = {"single": "stride run, one at a time", "jobs1": "stride sweep --jobs 1",
         "jobs2": "stride sweep --jobs 2", "mpi2": "mpirun -n 2 stride sweep"}
base = m["jobs1"][0]
single_cpu = m["single"][1] / walks
print(f"{walks} walks each ({rounds} rounds); CPU per walk under stride run: {single_cpu:.3f} s")
for n, (t, c, w) in m.items():
    line = (f"{names[n]:26s} {t:7.1f} s wall {c:7.1f} s CPU  {walks / t:6.3f} walks/s"
            f"  {walks / c:6.3f} walks/CPU s  {base / t:5.2f}x of --jobs 1")
    if n != "single":
        timing = [row for r in range(1, rounds + 1)
                  for row in csv.DictReader(open(tmp / f"{n}-{r}" / "timing.csv"))]
        own = sum(float(r["seconds"]) for r in timing)
        wall_over = (t * w - own) / len(timing)
        cpu_over = c / walks - single_cpu
        line += (f"  overhead/run: CPU {cpu_over:+.3f} s = {100 * cpu_over / single_cpu:+.2f} %,"
                 f" wall x workers {wall_over:.3f} s = {100 * wall_over / (own / len(timing)):.2f} %")
        same = all((tmp / f"{n}-{r}" / "runs.csv").read_bytes() ==
                   (tmp / f"jobs1-{r}" / "runs.csv").read_bytes() for r in range(1, rounds + 1))
        line += "  rows identical" if same else "  ROWS DIFFER"
    print(line)
PY

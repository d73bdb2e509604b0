#!/usr/bin/env bash
# Console `plot` against its number of keys: wall seconds of recording N keys over 1 s of the
# standing NAO (1000 rows) and writing the CSV and the PNG, for N = 25, 50, 100, 200, 400,
# median of 3 each, with the ratio to the previous N (2.0 per doubling is linear).
#   bench/plot_keys_scaling.sh <build dir> [repetitions=3]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
stride="$1/stride"
reps=${2:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
previous=""
for n in 25 50 100 200 400; do
  keys=$(printf 'robot.torso.z %.0s' $(seq "$n"))
  times=()
  for _ in $(seq "$reps"); do
    start=$(date +%s.%N)
    "$stride" -c "plot $keys to $tmp/p.csv; run 1; plot stop" "$root/scenes/nao_stand.xml" >/dev/null
    times+=("$(echo "$(date +%s.%N) - $start" | bc)")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((reps + 1) / 2))p")
  ratio=${previous:+$(echo "scale=2; $median / $previous" | bc)}
  echo "keys $n: ${median} s (median of $reps)${ratio:+, x$ratio of the previous}"
  previous=$median
done

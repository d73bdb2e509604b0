#!/usr/bin/env bash
# The lockstep LoLA walk's real-time factor against the in-process walk's, side by side: the
# Ch. 4 hip walk at 12 ms, in process (scenes/lola/hip_medium_12ms.xml) and as two processes over
# a unix socket (`stride run scenes/experiments/hip_medium.xml --lola` + `stride robot`), in
# alternation, N pairs; prints each pair and the median ratio. Target: the LoLA run's factor is
# at least 0.8 of the in-process one's.
#   bench/lola_walk_rtf.sh [build dir=build] [pairs=5] [seconds=17]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
pairs=${2:-5}
seconds=${3:-17}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rtf() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['real_time_factor'])" "$1"; }
ratios=()
for i in $(seq "$pairs"); do
  "$build/stride" run scenes/lola/hip_medium_12ms.xml --seconds "$seconds" \
    --report "$work/in_process.json" >/dev/null
  "$build/stride" run scenes/experiments/hip_medium.xml --seconds "$seconds" --lola "$work/s" \
    --report "$work/lola.json" >/dev/null 2>"$work/sim.err" &
  sim=$!
  while [ ! -S "$work/s" ]; do sleep 0.01; done
  "$build/stride" robot --config scenes/robots/nao/config/hip_walk.xml --lola "$work/s" \
    >/dev/null 2>&1 || true
  wait "$sim"
  a=$(rtf "$work/in_process.json"); b=$(rtf "$work/lola.json")
  r=$(python3 -c "print(f'{$b / $a:.3f}')")
  ratios+=("$r")
  echo "pair $i: in-process ${a}x  lola ${b}x  ratio $r"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{v[NR]=$1} END {print "median ratio " v[int((NR+1)/2)]}'

#!/usr/bin/env bash
# One walk scene under several solver settings: copies of the scene with attributes set in its
# <physics> element, each run with `stride run` and summarised from its report. Shows how much a
# walk's distance owes to the solver (sliding of loaded feet, feet rocking on an edge).
#   scenes/experiments/solver_sweep.sh <stride> <scene> "<setting> ..." [seeds] [seconds]
#   a setting is attr=value[,attr=value...] of <physics>, e.g.
#   solver_sweep.sh build/stride scenes/walking/open_loop_medium.xml \
#     "iterations=10 iterations=20 iterations=40 solver=exact" 1 17.05
# Prints one line per run: setting seed fell steps fk-distance true-distance foot-slip
# foot-slip-net-x foot-tilt-max foot-tilted-time torso-yaw wall-time.
set -euo pipefail
stride=$(realpath "$1")
source_scene=$(realpath "$2")
settings=$3
seeds=${4:-1}
seconds=${5:-17.05}
tmp=$(mktemp -d)
# The copy lives next to the original so that its relative paths still resolve.
scene=$(dirname "$source_scene")/.solver_sweep_$$.xml
trap 'rm -rf "$tmp" "$scene"' EXIT
for setting in $settings; do
  attrs=""
  drop=()  # a setting replaces the scene's own value of that attribute
  for pair in ${setting//,/ }; do
    attrs+=" ${pair%%=*}=\"${pair#*=}\""
    drop+=(-e "s#(<physics[^>]*) ${pair%%=*}=\"[^\"]*\"#\1#")
  done
  sed -E "${drop[@]}" -e "s#<physics([ />])#<physics$attrs\1#" "$source_scene" > "$scene"
  for ((seed = 1; seed <= seeds; ++seed)); do
    "$stride" run "$scene" --seconds "$seconds" --seed "$seed" --report "$tmp/r.json" > /dev/null
    python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); r=j["robots"][0]; w=r["walk"]
print(*sys.argv[2:], "fell" if w["fell"] or r["fell"] else "up", w["steps"],
      *("%.3f" % w[k] for k in ("fk_distance", "true_distance", "foot_slip", "foot_slip_net_x",
                               "foot_tilt_max", "foot_tilted_time")),
      "%.3f" % r["torso"]["yaw"], "%.2f" % j["wall_time"])' "$tmp/r.json" "$setting" "$seed"
  done
done

#!/usr/bin/env bash
# Floor roughness x strategy x speed x seed for the Sec. 4.3.4.2 walks: copies of the
# {none,hip,ankle}_{slow,medium,fast} scenes with the <uneven> patch's height and tilt replaced
# (or removed: "flat"), each run with `stride run` and summarised from its report. Motor
# attributes (name=value ...) change the leg motors (roll, pitch) through <motor> in <robot>;
# a fifth argument "arm-swing" turns on the yaw-moment arm swing of Sec. 4.4 in every walk.
#   scenes/experiments/floor_sweep.sh <stride> "<height>:<tilt> ..." [seeds] ["attr=value ..."] [arm-swing]
#   e.g. floor_sweep.sh build/stride "flat 1mm:0.5deg 3mm:1deg 4.5mm:1.5deg 6mm:2deg" 3
#        floor_sweep.sh build/stride 3mm:1deg 3 spring=150
#        floor_sweep.sh build/stride 3mm:1deg 6 backlash=2deg
#        floor_sweep.sh build/stride 3mm:1deg 12 backlash=2deg arm-swing
# Prints one line per walk: floor strategy speed seed fell steps true-distance max|pitch| max|roll|,
# in this order whatever JOBS (walks at once, default: all processors) is.
set -euo pipefail
stride=$(realpath "$1")
floors=$2
seeds=${3:-3}
motor=""
for pair in ${4:-}; do motor+=" ${pair%%=*}=\"${pair#*=}\""; done
arm_swing=${5:-}
if [[ -n $arm_swing && $arm_swing != arm-swing ]]; then
  echo "floor_sweep.sh: fifth argument: expected 'arm-swing', got '$arm_swing'" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
jobs=${JOBS:-$(nproc)}
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "floor_sweep.sh: JOBS: expected a count >= 1, got '$jobs'" >&2; exit 2; }
# One scene per floor, strategy and speed; one line per walk in $tmp/jobs.
n=0
for floor in $floors; do
  for strategy in none hip ankle; do
    for speed in slow medium fast; do
      scene=$tmp/$n.xml
      n=$((n + 1))
      sed "s#\.\./robots/#$here/../robots/#g" "$here/${strategy}_${speed}.xml" > "$scene"
      if [[ -n $motor ]]; then
        sed -i "s#</robot>#<motor name=\"roll\"$motor/><motor name=\"pitch\"$motor/></robot>#" "$scene"
      fi
      if [[ -n $arm_swing ]]; then
        sed -i 's#field="gain_scale" value="0"#field="gain_scale" value="1"#' "$scene"
      fi
      if [[ $floor == flat ]]; then
        sed -i '/<uneven /d' "$scene"
      else
        sed -i -E "s#(<uneven[^>]*) height=\"[^\"]*\" tilt=\"[^\"]*\"#\1 height=\"${floor%%:*}\" tilt=\"${floor##*:}\"#" "$scene"
      fi
      for ((seed = 1; seed <= seeds; ++seed)); do
        echo "$scene $floor $strategy $speed $seed" >> "$tmp/jobs"
      done
    done
  done
done
walk() {  # scene floor strategy speed seed -> one summary line in <scene>.<seed>.out
  # 255 makes xargs stop at the first bad run instead of repeating its error for every walk
  "$stride" run "$1" --seconds 18.5 --seed "$5" --report "$1.$5.json" > /dev/null || exit 255
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))["robots"][0]; w=r["walk"]
print(*sys.argv[2:], "fell" if w["fell"] or r["fell"] else "up", w["steps"], "%.2f" % w["true_distance"],
      "%.3f" % max(-w["pitch_min"], w["pitch_max"]), "%.3f" % max(-w["roll_min"], w["roll_max"]))' \
    "$1.$5.json" "${@:2}" > "$1.$5.out"
}
export -f walk
export stride
xargs -P "$jobs" -L 1 bash -c 'walk "$@"' _ < "$tmp/jobs"
while read -r scene _ _ _ seed; do cat "$scene.$seed.out"; done < "$tmp/jobs"

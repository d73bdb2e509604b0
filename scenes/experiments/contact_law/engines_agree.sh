#!/usr/bin/env bash
# Issue 47's must-show: the open-loop and the hip-strategy medium walks (arms still, and with the
# thesis' arm swing), N perturbed starts each, on ODE exact and MuJoCo Newton at one step, as
# `stride converge` tables (scenes/experiments/README.md, "engines agree").
#   scenes/experiments/contact_law/engines_agree.sh <stride> <out-dir> [step] [starts] [walks]
#   e.g. engines_agree.sh build/stride out/agree 1ms 16
#        engines_agree.sh build/stride out/agree 0.5ms 4 "hip_medium_arm_swing"
# Writes <out-dir>/<walk>_<step>.txt per walk and prints each table's rows. One walk at a time,
# one job: on a shared machine run it under `nice`.
set -euo pipefail
stride=$(realpath "$1")
out=$2
step=${3:-1ms}
starts=${4:-16}
walks=${5:-"open_loop_medium hip_medium hip_medium_arm_swing"}
here=$(dirname "$(realpath "$0")")
mkdir -p "$out"
for walk in $walks; do
  "$stride" converge "$here/$walk.xml" --settings "solver=exact,step=$step engine=mujoco,solver=exact,step=$step" \
    --starts "$starts" --jobs 1 --no-plots > "$out/${walk}_$step.txt"
  echo "== $walk, $step, $starts starts"
  grep -E '^(setting|solver=|engine=|step=)' "$out/${walk}_$step.txt"
done

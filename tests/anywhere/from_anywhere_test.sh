#!/bin/bash
# The shipped scenes, robots and default data paths work from a directory outside the checkout:
# a console script with a provider swap whose estimator needs the robot model, kinematics, the
# landing study, a log recorded after `mr` replaying with no mismatch, and an experiment and a
# sweep writing into --out.
# usage: from_anywhere_test.sh <stride binary> <source dir>
set -u
stride=$1 src=$2
. "$src/tests/anywhere/common.sh"
case "$work" in "$src"*) echo "FAIL: $work is inside the checkout"; exit 1 ;; esac
[ ! -e scenes ] || { echo "FAIL: $work has a scenes/"; exit 1; }

# A balance strategy swapped in on the standing NAO: its CoM estimator needs the robot model.
expect_run 0 'ok representation:ComState.valid = true' "$stride" -c "mr JointRequest AnkleBalance; \
  run 1; expect representation:ComState.valid == true; expect robot.fell == false" \
  scenes/nao_stand_controlled.xml
expect_run 0 'total mass \(kg\): 5\.305' "$stride" kin com --q "LHipPitch=-0.3 RHipPitch=-0.3"
expect_run 0 'impedance' "$stride" landing --seconds 0.4
expect_run 0 'TorsoStateEstimator online' "$stride" experiment kalman --seeds 1 --jobs 1 \
  --out results --no-plots
ls results/*.csv >/dev/null 2>&1 || { echo "FAIL: no CSV in results/"; failures=$((failures + 1)); }
expect_run 0 'ok log\.mismatches = 0' "$stride" --script "$src/tests/scripts/log_after_mr.con"
[ -s after_mr.log ] || { echo "FAIL: no after_mr.log here"; failures=$((failures + 1)); }
expect_run 0 'iterations +runs' "$stride" sweep "$src/tests/sweep/data/stand.sweep.xml" --jobs 1 --out sweep_out
ls sweep_out/*.csv >/dev/null 2>&1 || { echo "FAIL: no CSV in sweep_out/"; failures=$((failures + 1)); }
# A scene given by its shipped name runs from here, and a missing one says what was looked for.
expect_run 0 'upright' "$stride" run scenes/nao_stand.xml --seconds 0.1
expect_run 3 'scenes/no_such\.xml' "$stride" run scenes/no_such.xml --seconds 0.1
finish

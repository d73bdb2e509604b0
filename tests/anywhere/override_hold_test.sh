#!/bin/bash
# A provided representation overridden with `set` holds for every one of 100 control frames, then
# `unchanged` gives it back to its provider (override_hold.con writes the logs' CSVs).
# usage: override_hold_test.sh <stride binary> <source dir>
set -u
stride=$1 src=$2
. "$src/tests/anywhere/common.sh"
expect_run 0 'ok override:JointRequest = \(none\)' "$stride" --script \
  "$src/tests/anywhere/override_hold.con"
# hold.csv: frame, JointRequest.position[HeadYaw], ActuatorFrame.position[HeadYaw]
head -1 hold.csv | grep -q 'JointRequest.position\[HeadYaw\]' || { echo "FAIL: header"; exit 1; }
awk -F, 'NR > 1 { n++; if ($2 != 0.5 || $3 != 0.5) bad++ }
         END { printf "held frames: %d, not 0.5: %d\n", n, bad; exit !(n >= 100 && bad == 0) }' \
  hold.csv || failures=$((failures + 1))
awk -F, 'NR > 1 { n++; if ($2 != 0) bad++ }
         END { printf "released frames: %d, not 0: %d\n", n, bad; exit !(n >= 100 && bad == 0) }' \
  released.csv || failures=$((failures + 1))
finish

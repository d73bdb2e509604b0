#!/bin/bash
# The same kind of failure exits with the same code from every command (docs/console.md "Exit codes"):
# 2 wrong command line, 3 a file or command text that cannot be read or parsed, 1 it ran and
# failed. And help finds things: console commands and keys in `stride help`, `--help` on every
# command, whole words first, parameter lists with ranges.
# usage: exit_codes_test.sh <stride binary> <source dir>
set -u
stride=$1 src=$2
. "$src/tests/anywhere/common.sh"
scene=scenes/nao_stand_controlled.xml

# 2: the command line is wrong
expect_run 2 'stride run: missing <scene>' "$stride" run
expect_run 2 'stride kin: expected fk, ik or com' "$stride" kin
expect_run 2 'stride experiment: --seeds' "$stride" experiment posture --seeds 0
expect_run 2 "unknown flag '--bogus'" "$stride" --bogus
expect_run 2 'stride landing: --speed' "$stride" landing --speed fast
expect_run 2 'stride balance: unknown argument' "$stride" balance classify --nope 1
expect_run 2 'stride pattern: unknown argument' "$stride" pattern --nope
expect_run 2 'stride push-sweep: missing --scene' "$stride" push-sweep --impulses 1:2:1
expect_run 2 'stride swing-leg: missing <study>' "$stride" swing-leg
expect_run 2 'stride dyn: expected params' "$stride" dyn
# 3: an input cannot be read or parsed
expect_run 3 'no_such\.xml' "$stride" run no_such.xml
expect_run 3 "script 'no_such\.con': cannot open" "$stride" --script no_such.con
expect_run 3 "unknown command 'bogus'" "$stride" -c "bogus" "$scene"
expect_run 3 "URDF file 'no_such\.urdf': cannot open" "$stride" kin com --q "LHipPitch=0" \
  --urdf no_such.urdf
expect_run 3 'no_such\.xml' "$stride" landing --scene no_such.xml
printf 'load %s\nrun 0.1\nbogus 1\n' "$src/$scene" >typo.con
expect_run 3 'typo\.con:3: unknown command' "$stride" --script typo.con
# 1: it ran and failed
expect_run 1 'expect sim.time > 5 failed' "$stride" -c "run 0.1; expect sim.time > 5" "$scene"
printf 'load %s\nexpect robot.fell == true\n' "$src/$scene" >fails.con
expect_run 1 'fails\.con:2: expect robot.fell == true failed' "$stride" --script fails.con
# 0, and help that finds things
expect_run 0 'console commands' "$stride" help
expect_run 0 'provider:X' "$stride" help
expect_run 0 'exit codes: 0 done; 1 it ran and failed' "$stride" help
expect_run 0 '^  log start' "$stride" help log
if "$stride" help log | grep -q '^  plot'; then
  echo "FAIL: help log shows plot (a whole word matches first)"; failures=$((failures + 1))
fi
expect_run 0 'module request' "$stride" mr --help
expect_run 0 'usage: stride run <scene>' "$stride" run --help
expect_run 0 'console command run \[seconds\]' "$stride" run --help
# Every command's --help in process: tests/console/help_test.cpp; here the binary's routing.
expect_run 0 'usage: stride landing' "$stride" landing --help
expect_run 0 'usage: stride experiment' "$stride" experiment kalman --seeds 2 --help
expect_run 0 'console command' "$stride" help --help
expect_run 0 'log start <file>' "$stride" log --help
expect_run 0 'T_stride = 0.5 \[s\] in > 0' "$stride" pattern --set '?'
expect_run 0 'z_min = 0.327 \[m\]' "$stride" pattern --preset slow --set '?'
expect_run 0 'HipStrategy\.kp_pitch = .* in \[' "$stride" experiment posture --set '?'
expect_run 0 'AnkleBalance\.' "$stride" push-sweep --set '?'
finish

#!/bin/bash
# The live REPL through a pipe: `run` without seconds runs in the background while the commands
# that arrive are answered between steps; `pause` stops it (repl_tmux_test.sh does the same in a
# terminal).
# usage: live_pipe_test.sh <stride binary> <source dir>
set -u
stride=$1 src=$2
. "$src/tests/anywhere/common.sh"
{
  echo run
  sleep 1
  echo "echo A"; echo "get sim.time"
  sleep 0.5
  echo "echo B"; echo "get sim.time"
  echo "set representation:JointRequest position[HeadYaw]=0.3"
  echo "echo C"; echo "get representation:JointRequest.position[HeadYaw]"
  echo pause
  echo "echo D"; echo "get sim.time"
  sleep 0.5
  echo "echo E"; echo "get sim.time"
  echo "step"
  echo run
  echo "run 1"
  echo quit
} | "$stride" scenes/nao_stand_controlled.xml >out.txt 2>&1
after() { awk -v m="$1" '$0 == m {getline; print; exit}' out.txt; }
a=$(after A) b=$(after B) c=$(after C) d=$(after D) e=$(after E)
echo "sim.time while running: $a, $b; held head $c; after pause: $d, $e"
ok=1
awk -v a="$a" -v b="$b" 'BEGIN {exit !(a > 0 && b > a)}' || ok=0
[ "$c" = "0.3" ] || ok=0
awk -v b="$b" -v d="$d" -v e="$e" 'BEGIN {exit !(d >= b && d == e)}' || ok=0
grep -q '^running from t=0 ' out.txt || ok=0
grep -q '^paused at t=' out.txt || ok=0
grep -q 'run: the simulation is running in the background (pause first)' out.txt || ok=0
[ "$ok" = 1 ] || { echo "FAIL:"; sed 's/^/  | /' out.txt | head -40; exit 1; }
echo "ok: answered while running, stopped by pause"

#!/bin/bash
# Issue 49 points 1 and 4 in a real terminal (tmux): `run` typed by a person goes at the wall
# clock's pace and says so, `realtime off` is shown in the prompt; lines typed while `plot stop`
# renders (the first gnuplot of the process) all run: none is eaten by gnuplot.
# usage: repl_points_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

open t "'$stride' scenes/nao_stand_controlled.xml"
wait_for '^stride> ?$'
# Point 4: the plot's lines, then three more typed at once while it renders.
tm send-keys -t t "plot sim.time to $home/p.png" Enter "run 0.2" Enter "plot stop" Enter \
  "echo typed-during-plot-1" Enter "echo typed-during-plot-2" Enter "get sim.time" Enter
wait_for '^wrote .*p\.png$'
wait_for '^typed-during-plot-1$' 20
wait_for '^typed-during-plot-2$' 20
wait_for '^0\.2$' 20

# Point 1: real time by default at a terminal, said when the run starts.
type_line t run
wait_for '^running from t=0\.2 in real time \(realtime off: as fast as possible'
sleep 2
type_line t pause
wait_for '^paused at t='
t=$(screen | awk '/^paused at t=/ {sub(/^paused at t=/, ""); v = $0} END {print v}')
# 2 s of wall time (plus the typing) is at most ~2.6 s of simulation in real time.
awk -v t="$t" 'BEGIN {exit !(t > 0.2 && t < 2.9)}' || fail "2 s of real time ran to t=$t"
type_line t 'realtime off'
wait_for '^stride \(fast\)> ?$'
type_line t 'run'
wait_for 'running from t=.* as fast as possible \(realtime on: at the wall clock'"'"'s pace'
type_line t 'pause'
type_line t 'realtime on'
wait_for '^stride> ?$'
type_line t quit
echo "ok: real time by default and shown; no typed line lost to plot stop (paused at t=$t)"

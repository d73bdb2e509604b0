#!/bin/bash
# Issue 49 point 8 against `stride run <walk> --debug`: the run waits, paused, for the first
# console (said in its banner), so a console that connects late still sees the walk from t=0;
# `restart` puts the scene back to its start and runs it again.
# usage: remote_run_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

debug_run
sleep 3  # a console a few seconds late
open t "'$stride' --connect 127.0.0.1:$port"
wait_for '^stride> ?$' 30
wait_for 'a console connected: running' 30 sim  # not anchored: the server thread's own line may interleave
t1=$(value_of first representation:FrameInfo.time)
awk -v t="$t1" 'BEGIN {exit !(t >= 0 && t < 2.5)}' || fail "the walk ran before the console came (t=$t1)"
sleep 5
t2=$(value_of second representation:FrameInfo.time)
awk -v a="$t1" -v b="$t2" 'BEGIN {exit !(b > a + 1)}' || fail "the run did not go on ($t1, $t2)"
type_line t restart
wait_for '^restarted ' 30
wait_for '^restarted the scene \(a console asked\)$' 30 sim
# The console's background run follows the restarted robot (its frames count from 0 again)
# for longer than its 2 s patience without losing the stream.
sleep 3
screen | grep -q 'no frame from' && fail "the console lost the restarted robot's stream"
type_line t pause
t3=$(value_of third representation:FrameInfo.time)
awk -v b="$t2" -v c="$t3" 'BEGIN {exit !(c < b)}' || fail "restart did not go back to the start ($t2, $t3)"
type_line t quit
no_sanitizer_report
echo "ok: waited for the console (t=$t1), ran on (t=$t2), restarted (t=$t3)"

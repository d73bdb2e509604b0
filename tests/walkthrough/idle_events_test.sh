#!/bin/bash
# Issue 49, events over `connect`: a console idle at its prompt (no run, no command typed) is told
# of the robot's fall at once, in one line above the prompt, and what was half typed survives.
# usage: idle_events_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

debug_run
open t "'$stride' --connect 127.0.0.1:$port"
wait_for '^stride> ?$' 30
wait_for 'a console connected: running' 30 sim
sleep 2  # the robot walks a while first
# Held hips and knees fell the walking robot a moment later, while the console only waits.
type_line t 'set representation:JointRequest position[LHipPitch]=-1.45 position[RHipPitch]=-1.45 position[LKneePitch]=0 position[RKneePitch]=0'
wait_for '^stride> ?$' 30
tm send-keys -t t 'get robot.na'   # half typed, never entered
wait_for '^t=[0-9.]+ event: FELL at t=[0-9.]+ s \(IMU tilt' 30
sleep 1
[ "$(screen | grep -c 'event: FELL')" = 1 ] || fail "the fall was not said exactly once"
screen | sed '/^$/d' | tail -n 1 | grep -q '^stride> get robot\.na$' || fail "the half-typed line was not kept below the event"
tm send-keys -t t 'me' Enter
wait_for '^nao' 30
type_line t quit
no_sanitizer_report
echo "ok: the idle console was told of the fall at once, the typed line kept"

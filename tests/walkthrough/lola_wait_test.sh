#!/bin/bash
# Issue 49 point 8 over LoLA: `stride robot --debug` against the simulated NAO (the
# docs/physical-robot.md flow) holds the robot standing, its controller paused, until a console
# connects (said in its banner), so a console a few seconds late sees the walk from its start.
# In lockstep the wait goes at LoLA's 12 ms too: the simulator's run is not raced through.
# usage: lola_wait_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

lola_pair "$home/sim.sock" "--seconds 120 --realtime"
wait_for '^stride robot: standing, controller paused until the first console connects' 60 robot
sleep 4  # a console a few seconds late
open t "'$stride' --connect 127.0.0.1:$port"
wait_for '^stride> ?$' 30
wait_for 'stride robot: a console connected: controller running' 30 robot
f1=$(value_of first representation:FrameInfo.frame)
awk -v f="$f1" 'BEGIN {exit !(f >= 0 && f < 250)}' || fail "the controller ran before the console came (frame $f1)"
sleep 3
f2=$(value_of second representation:FrameInfo.frame)
awk -v a="$f1" -v b="$f2" 'BEGIN {exit !(b > a + 100)}' || fail "the controller did not go on ($f1, $f2)"
pitch=$(value_of third 'representation:InertialSensorData.angles[1]')
awk -v p="$pitch" 'BEGIN {exit !(p > -0.5 && p < 0.5)}' || fail "the robot is not upright (pitch $pitch)"
type_line t quit

# Lockstep: 20 s of simulation would be over in about 2 s of racing; holding, it is not.
tm kill-window -t robot
tm kill-window -t sim
lola_pair "$home/lockstep.sock" "--seconds 20"
wait_for '^stride robot: standing, controller paused' 60 robot
sleep 5
screen sim | grep -q '^scene hip_medium .* hash ' && fail "the lockstep simulation ended while the robot waited" sim
open t2 "'$stride' --connect 127.0.0.1:$port"
wait_for 'stride robot: a console connected: controller running' 30 robot
wait_for '^stride> ?$' 30 t2
tm send-keys -t t2 quit Enter
no_sanitizer_report
echo "ok: the controller waited for the console (frame $f1, then $f2), the robot upright (pitch $pitch)"

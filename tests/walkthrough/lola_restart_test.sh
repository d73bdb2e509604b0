#!/bin/bash
# Issue 49 point 8, restart over LoLA: after a fall, `restart` of `stride robot --debug` on the
# simulated NAO restarts its controller and puts the simulated robot back at the scene's start
# (the simulator's side channel), so the walk runs again upright, from its start.
# usage: lola_restart_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

# upright <marker>: the IMU's roll and pitch both within 0.4 rad; prints them.
upright() {
  local roll pitch
  roll=$(value_of "$1-roll" 'representation:InertialSensorData.angles[0]')
  pitch=$(value_of "$1-pitch" 'representation:InertialSensorData.angles[1]')
  echo "roll $roll pitch $pitch"
  awk -v r="$roll" -v p="$pitch" 'BEGIN {exit !(r > -0.4 && r < 0.4 && p > -0.4 && p < 0.4)}'
}

lola_pair "$home/sim.sock" "--seconds 120 --realtime"
open t "'$stride' --connect 127.0.0.1:$port"
wait_for '^stride> ?$' 30
wait_for 'stride robot: a console connected: controller running' 30 robot
sleep 1
type_line t 'set representation:JointRequest position[LHipPitch]=-1.45 position[RHipPitch]=-1.45 position[LKneePitch]=0 position[RKneePitch]=0'
wait_for 'event: FELL at t=[0-9.]+ s' 30
sleep 2
fallen=$(upright fallen) && fail "the robot did not fall ($fallen)"
type_line t restart
wait_for '^restarted ' 30
wait_for 'scene back at its start \(the client.s controller restarted\)' 30 sim
wait_for 'the simulator put the robot back at its start' 30 robot
wait_for 'controller restarted from its configured start' 30 robot
sleep 1
standing=$(upright standing) || fail "the robot is not back on its feet after restart ($standing)"
f1=$(value_of frame1 representation:FrameInfo.frame)
awk -v f="$f1" 'BEGIN {exit !(f >= 0 && f < 200)}' || fail "the controller did not start again (frame $f1)"
sleep 4  # through the walk's 2 s standing into its steps
walking=$(upright walking) || fail "the restarted walk fell ($walking)"
f2=$(value_of frame2 representation:FrameInfo.frame)
awk -v a="$f1" -v b="$f2" 'BEGIN {exit !(b > a + 250)}' || fail "the controller did not go on ($f1, $f2)"
type_line t quit
no_sanitizer_report
echo "ok: fallen ($fallen), restarted upright ($standing, frame $f1), walking ($walking, frame $f2)"

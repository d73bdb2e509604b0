#!/bin/bash
# Issue 49's walkthrough as a person does it, typed into real terminals (tmux) and read back from
# the screen. Part 1, the REPL on a walking scene: watch, plot (live lines, then the PNG), set a
# walk preset mid-walk (no NaN), mr, a push that fells the robot, announced in one line. Part 2,
# remote over LoLA: the simulator serves a NAO (`stride run --lola --realtime`), `stride robot
# --debug` controls it, the console connects, restarts the robot's controller, plots live,
# records a log on the robot, hears of the robot's fall, downloads the log and replays it here. Loopback only; bounded waits.
# usage: walkthrough_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

# --- Part 1: the REPL on a walking scene ---------------------------------------------------
open t "'$stride' scenes/walking/open_loop_medium.xml"
wait_for '^stride> ?$'
type_line t 'watch representation:FrameInfo.time robot.torso.pitch every 100'
type_line t "plot robot.torso.pitch representation:InertialSensorData.angles[1] to $home/walk.csv"
wait_for '^recording 2 value'
type_line t 'realtime off'
wait_for '^stride \(fast\)> ?$'
type_line t run
wait_for '^running from t=0 as fast as possible'
wait_for '^t=[0-9.]+ +representation:FrameInfo.time=[0-9.]+ +robot.torso.pitch=' 60
wait_for '^plot: [0-9]+ rows  robot.torso.pitch ' 60   # the plot shows itself while it records
type_line t 'set module:PatternWalk preset=fast'
type_line t 'echo set-done'
wait_for '^set-done$'
type_line t 'get module:PatternWalk.T_stride'
type_line t 'set module:PatternWalk T_stride=nan'   # allowed: "from the preset" is NaN already
type_line t 'set module:PatternWalk A_l=inf'
wait_for '^error: PatternWalk.A_l: inf refused: a parameter never becomes NaN or infinite'
type_line t 'mr JointRequest ?'
wait_for 'JointRequest'
type_line t 'push torso 0 400 0 0.2'
wait_for 'event: FELL at t=[0-9.]+ s \(IMU tilt' 60
sleep 1
[ "$(screen | grep -c 'event: FELL')" = 1 ] || fail "the fall was not said exactly once"
type_line t pause
wait_for '^paused at t='
type_line t 'plot stop'
wait_for "^wrote $home/walk\.png$" 60
type_line t 'echo typed-after-plot-stop'
wait_for '^typed-after-plot-stop$'
[ -s "$home/walk.png" ] || fail "no walk.png"
gp_size=$(stat -c %s "$home/walk.gp")
type_line t quit

# --- Part 2: the remote session over LoLA ---------------------------------------------------
mkdir -p "$home/robot_logs"
lola_pair "$home/sim.sock" "--seconds 300 --realtime" "--log-dir '$home/robot_logs'"
open console "'$stride' --connect 127.0.0.1:$port"
wait_for "^connected to .*127\.0\.0\.1:$port" 30 console
wait_for '^stride> ?$' 30 console
type_line console restart
wait_for '^restarted ' 30 console
wait_for 'controller restarted from its configured start' 30 robot
type_line console pause
type_line console "plot representation:InertialSensorData.angles[1] to $home/remote.csv"
type_line console 'log start walk.log'
wait_for '^logging to walk\.log' 30 console
type_line console run
wait_for '^plot: [0-9]+ rows  InertialSensorData.angles\[1\] ' 60 console
type_line console 'log stop'
# A fall on the robot is said over the connection too, without any debug request on.
type_line console 'set representation:JointRequest position[LHipPitch]=-1.45 position[RHipPitch]=-1.45 position[LKneePitch]=0 position[RKneePitch]=0'
wait_for 'event: FELL at t=[0-9.]+ s \(IMU tilt' 60 console
type_line console pause
type_line console 'set representation:JointRequest unchanged'
type_line console 'plot stop'
wait_for "^wrote $home/remote\.png$" 60 console
type_line console "log save $home/walk.log"
wait_for "walk\.log" 60 console
for _ in $(seq 1 100); do [ -s "$home/walk.log" ] && break; sleep 0.2; done
[ -s "$home/walk.log" ] || fail "the robot's log was not downloaded" console
type_line console "log load $home/walk.log"
type_line console 'log replay'
wait_for '^error: log replay: .*load a scene first' 30 console
type_line console disconnect
type_line console 'load scenes/experiments/hip_medium.xml'
wait_for '^loaded local hip_medium' 60 console
type_line console 'log replay'
# The log began mid-walk: the replay runs every frame and says why it cannot match bit for bit.
wait_for '^replayed [0-9]+ frames, compared [0-9]+ representations: ' 120 console
wait_for '^note: the log starts at controller frame [0-9]+, not at the controller' 30 console
type_line console quit
echo "ok: REPL walkthrough (walk.gp $gp_size bytes) and remote LoLA session with restart, live plot, log download and replay"

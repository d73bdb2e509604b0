#!/bin/bash
# Issue 50: a console steers a NAO walking through `stride robot` over LoLA (the simulated NAO of
# scenes/walking/requests/steer.xml, in real time): `set representation:WalkRequest ...` starts a
# forward walk, the walk grants it (WalkStatus), a turn follows, and `mode=stand` stops it into a
# stand, upright throughout, with no leg IK frame beyond the joint limits and the measured yaw
# (WalkOdometry) within 20 % of the plan's.
# usage: walk_request_lola_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
. "$src/tests/walkthrough/tmux_lib.sh"

# The robot config's controller without its schedule: the console is the schedule here.
sed '/<at time/,/<\/at>/d; s#"\.\./nao.urdf"#"'"$src"'/scenes/robots/nao/nao.urdf"#' \
  "$src/scenes/robots/nao/config/steer.xml" > "$home/console_walk.xml"
grep -q '<at time' "$home/console_walk.xml" && fail "the schedule is still in the robot config"
lola_scene="$src/scenes/walking/requests/steer.xml" lola_config="$home/console_walk.xml"
lola_pair "$home/sim.sock" "--seconds 120 --realtime"
open t "'$stride' --connect 127.0.0.1:$port"
wait_for '^stride> ?$' 30
sleep 2  # stood up
type_line t "set representation:WalkRequest mode=walk forward=0.2"
sleep 3
granted=$(value_of first representation:WalkStatus.granted_forward)
[ "$granted" = "0.2" ] || fail "granted forward speed $granted, not 0.2"
type_line t "set representation:WalkRequest mode=walk forward=0 turn=0.5"
sleep 3
turn=$(value_of second representation:WalkStatus.granted_turn)
[ "$turn" = "0.5" ] || fail "granted turn $turn, not 0.5"
type_line t "set representation:WalkRequest mode=stand forward=0 turn=0"
sleep 2
type_line t "get representation:WalkStatus.state"
wait_for '^standing$' 20
x=$(value_of third 'representation:WalkStatus.odometry[0]')
yaw=$(value_of fourth 'representation:WalkStatus.odometry[2]')
awk -v x="$x" -v y="$yaw" 'BEGIN {exit !(x > 0.3 && y > 0.8)}' || fail "the plan did not walk and turn (x $x, yaw $yaw)"
# The heading loop holds the measured yaw (WalkOdometry: the calibrated gyro) on the plan's.
measured=$(value_of seventh 'representation:WalkOdometry.yaw')
awk -v m="$measured" -v y="$yaw" 'BEGIN {d = m - y; if (d < 0) d = -d; exit !(d < 0.2 * y)}' ||
  fail "the measured yaw $measured is not within 20 % of the plan's $yaw"
beyond=$(value_of fifth representation:WalkingJointRequest.ik_beyond_limit_frames)
[ "$beyond" = "0" ] || fail "$beyond frames beyond the joint limits"
pitch=$(value_of sixth 'representation:InertialSensorData.angles[1]')
awk -v p="$pitch" 'BEGIN {exit !(p > -0.3 && p < 0.3)}' || fail "the robot is not upright (pitch $pitch)"
type_line t quit
no_sanitizer_report
echo "ok: steered over LoLA: forward $granted m/s, turn $turn rad/s, stopped standing; plan x $x m, yaw $yaw rad (measured $measured); pitch $pitch"

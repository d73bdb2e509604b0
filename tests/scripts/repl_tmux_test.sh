#!/bin/bash
# Types into the real `stride` REPL inside tmux and reads the screen back: tab completion of
# commands, keys and fields; an error that does not end the session; history across runs; a
# background `run` during which get, set, mr, realtime and pause are answered, and Ctrl-C pauses.
# Runs in a temporary directory outside the checkout (the shipped scene is found by its name).
# usage: repl_tmux_test.sh <stride binary> <source dir>. Exit 77 (skipped) without tmux.
set -u
stride=$1 src=$2
if ! command -v tmux >/dev/null 2>&1; then
  echo "SKIP: tmux is not installed"
  exit 77
fi
home=$(mktemp -d)
sock="stride_repl_test_$$"
tm() { tmux -L "$sock" "$@"; }
cleanup() { tm kill-server >/dev/null 2>&1; rm -rf "$home"; }
# A fresh tmux server per session: restarting one on a dying socket races with its exit.
trap cleanup EXIT
fail() { echo "FAIL: $1"; echo "--- screen ---"; tm capture-pane -p -t t; exit 1; }
# Waits until the screen shows text matching the regex $1 (up to 60 s).
wait_for() {
  for _ in $(seq 1 300); do
    tm capture-pane -p -t t | grep -Eq -- "$1" && return 0
    sleep 0.2
  done
  fail "screen never showed /$1/"
}
start() {
  tm new-session -d -s t -x 160 -y 50 \
    "cd '$home' && HOME='$home' '$stride' scenes/nao_stand_controlled.xml; sleep 30"
  wait_for '^stride> ?$'
}

start
# Completion: command, key prefix, representation-less module name, field.
tm send-keys -t t 'ge' Tab 'mod' Tab 'St' Tab '.kn' Tab
wait_for 'stride> get module:Stand\.knee_pitch'
tm send-keys -t t Enter
wait_for '^0\.6$'
# A typo is one error line with a suggestion; the session goes on.
tm send-keys -t t 'rnu 0.1' Enter
wait_for "unknown command 'rnu'; did you mean 'run'\?"
tm send-keys -t t 'set module:Stand knee_pitch=7' Enter
wait_for '^error: .*knee_pitch'
tm send-keys -t t 'get module:Stand.knee_pitch' Enter
tm send-keys -t t 'echo history-marker-42' Enter
wait_for '^history-marker-42$'
tm send-keys -t t 'quit' Enter
sleep 1
grep -q 'echo history-marker-42' "$home/.stride_history" || fail "history file lacks the line"
tm kill-server >/dev/null 2>&1
sock="${sock}_second"

# History across runs: Up brings back the previous session's lines, newest (quit) first.
start
tm send-keys -t t Up
wait_for '^stride> quit$'
tm send-keys -t t Up
wait_for 'stride> echo history-marker-42'
tm send-keys -t t Enter
wait_for '^history-marker-42$'
tm send-keys -t t 'quit' Enter
tm kill-server >/dev/null 2>&1
sock="${sock}_third"

# The value printed after `echo <marker>`: the first line below the marker that is a number.
value_after() {
  tm capture-pane -p -S - -t t | awk -v m="$1" '$0 == m {f = 1; next} f && /^-?[0-9.e+-]+$/ {print; exit}'
}
# Prints `get <key>` after a marker line and returns the value.
get_value() {
  marker="v-$RANDOM-$RANDOM"
  tm send-keys -t t "echo $marker" Enter "get $1" Enter
  for _ in $(seq 1 100); do
    v=$(value_after "$marker")
    [ -n "$v" ] && { echo "$v"; return 0; }
    sleep 0.1
  done
  fail "no value for $1"
}
more() { awk -v a="$1" -v b="$2" 'BEGIN {exit !(b > a)}'; }

# A background run: the prompt answers while the simulation advances between the commands.
start
tm send-keys -t t 'run' Enter
wait_for '^running from t=0 '
t1=$(get_value sim.time)
sleep 0.5
t2=$(get_value sim.time)
more "$t1" "$t2" || fail "sim.time did not advance while running ($t1, $t2)"
f1=$(get_value representation:FrameInfo.frame)
# set, mr and realtime apply between frames while it runs.
tm send-keys -t t 'set representation:JointRequest position[HeadYaw]=0.4' Enter
tm send-keys -t t 'mr JointRequest Stand' Enter
wait_for '^JointRequest <- Stand$'
v=$(get_value 'representation:JointRequest.position[HeadYaw]')
[ "$v" = "0.4" ] || fail "the held override reads $v"
tm send-keys -t t 'realtime on' Enter
r1=$(get_value sim.time)
sleep 1
r2=$(get_value sim.time)
awk -v a="$r1" -v b="$r2" 'BEGIN {exit !(b > a && b - a < 1.6)}' ||
  fail "realtime: $r1 -> $r2 in 1 s of wall time"
tm send-keys -t t 'realtime off' Enter
tm send-keys -t t 'pause' Enter
wait_for '^paused at t='
p1=$(get_value sim.time)
sleep 0.5
p2=$(get_value sim.time)
[ "$p1" = "$p2" ] || fail "sim.time moved after pause ($p1, $p2)"
more "$t2" "$p1" || fail "paused before it ran ($t2, $p1)"
f2=$(get_value representation:FrameInfo.frame)
more "$f1" "$f2" || fail "no control frames ran ($f1, $f2)"
# Ctrl-C pauses a background run; at the idle prompt it only drops the typed line.
tm send-keys -t t 'run' Enter
wait_for 'running from t='"$p1"
sleep 0.3
tm send-keys -t t C-c
for _ in $(seq 1 100); do
  [ "$(tm capture-pane -p -S - -t t | grep -c '^paused at t=')" -ge 2 ] && break
  sleep 0.1
done
[ "$(tm capture-pane -p -S - -t t | grep -c '^paused at t=')" -ge 2 ] || fail "Ctrl-C did not pause"
tm send-keys -t t 'half typed' C-c
tm send-keys -t t 'echo still-here' Enter
wait_for '^still-here$'
tm send-keys -t t 'quit' Enter
echo "ok: completion, errors, history and a background run in the terminal REPL"

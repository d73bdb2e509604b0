#!/bin/bash
# Types into the real `stride` REPL inside tmux and reads the screen back: tab completion of
# commands, keys and fields; an error that does not end the session; history across runs.
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
    "cd '$src' && HOME='$home' '$stride' scenes/nao_stand_controlled.xml; sleep 30"
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
echo "ok: completion, errors and history in the terminal REPL"

# Shared by the walkthrough tests: a private tmux server, typing, and waiting for the screen.
# Sourced with $stride set; leaves $home (a temporary HOME and working directory) and cleans up.
if ! command -v tmux >/dev/null 2>&1; then
  echo "SKIP: tmux is not installed"
  exit 77
fi
home=$(mktemp -d /tmp/stride_walkthrough.XXXXXX)
sock="stride_walkthrough_$$"
tm() { tmux -L "$sock" "$@"; }
extra_cleanup() { :; }
cleanup() { tm kill-server >/dev/null 2>&1; extra_cleanup; rm -rf "$home"; }
trap cleanup EXIT
screen() { tm capture-pane -p -S - -t "${1:-t}"; }
fail() { echo "FAIL: $1"; echo "--- screen ---"; screen "${2:-t}" | tail -n 60; exit 1; }
# wait_for <regex> [seconds] [window]: until the screen (with scrollback) shows a matching line.
wait_for() {
  local limit=$(( ${2:-60} * 5 ))
  for _ in $(seq 1 "$limit"); do
    screen "${3:-t}" | grep -Eq -- "$1" && return 0
    sleep 0.2
  done
  fail "screen never showed /$1/" "${3:-t}"
}
# open <window> <command...>: a new window running the command in $home (kept open after it ends).
open() {
  local name=$1
  shift
  if tm has-session -t t 2>/dev/null; then
    tm new-window -d -t 't:' -n "$name" "cd '$home' && HOME='$home' $*; sleep 600"
  else
    tm new-session -d -s t -n "$name" -x 200 -y 50 "cd '$home' && HOME='$home' $*; sleep 600"
  fi
}
# type_line <window> <text>: the text and Enter in one burst, as a fast typist or a paste does.
type_line() { tm send-keys -t "$1" "$2" Enter; }
# The number on the first line matching <regex> after the last line that equals <marker>.
number_after() {
  screen "$3" | awk -v m="$1" -v re="$2" '$0 == m {f = 1; v = ""; next} f && v == "" && $0 ~ re {
    if (match($0, /-?[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?/)) v = substr($0, RSTART, RLENGTH)} END {print v}'
}
# value_of <marker> <key> [window]: the number the console prints for `get <key>` after `echo
# <marker>`.
value_of() {
  local w=${3:-t} v
  type_line "$w" "echo $1"
  type_line "$w" "get $2"
  wait_for "^$1\$" 60 "$w"
  for _ in $(seq 1 50); do
    v=$(number_after "$1" '^-?[0-9.e+-]+$' "$w")
    [ -n "$v" ] && { echo "$v"; return; }
    sleep 0.2
  done
  fail "no value after $1" "$w"
}
# debug_run: the medium walk served by `stride run --debug` (window sim), waiting paused for its
# first console; sets $port to its debug server's.
debug_run() {
  open sim "'$stride' run scenes/walking/open_loop_medium.xml --seconds 120 --debug 127.0.0.1:0"
  wait_for '^paused at t=0 until the first console connects$' 60 sim
  port=$(screen sim | sed -n 's/^debug server on 127\.0\.0\.1:\([0-9]*\) .*/\1/p' | head -n 1)
}
# lola_pair <socket> <simulator flags> [robot flags]: the simulated NAO on LoLA (window sim) and
# `stride robot --debug` driving it (window robot); sets $port to its debug server's. The scene
# and robot config are the hip walk's unless $lola_scene / $lola_config name others.
lola_pair() {
  open sim "'$stride' run '${lola_scene:-scenes/experiments/hip_medium.xml}' $2 --lola '$1'"
  for _ in $(seq 1 300); do [ -S "$1" ] && break; sleep 0.2; done
  [ -S "$1" ] || fail "the simulator's LoLA socket never appeared" sim
  open robot "'$stride' robot --config '${lola_config:-$src/scenes/robots/nao/config/hip_walk.xml}' --lola '$1' --debug 127.0.0.1:0 ${3:-} 2>&1"
  wait_for 'debug server on 127\.0\.0\.1:[0-9]+' 60 robot
  port=$(screen robot | sed -n 's/.*debug server on 127\.0\.0\.1:\([0-9]*\).*/\1/p' | head -n 1)
}
# no_sanitizer_report: fails when a window shows a sanitizer's report (the ASan + UBSan build).
no_sanitizer_report() {
  local w
  sleep 1  # a console that just quit has written its leak check by now
  for w in $(tm list-windows -t t -F '#W'); do
    screen "$w" | grep -Eq 'Sanitizer|runtime error:' && fail "a sanitizer report in window $w" "$w"
  done
  return 0
}

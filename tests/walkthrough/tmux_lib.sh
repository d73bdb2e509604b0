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

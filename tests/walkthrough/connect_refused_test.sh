#!/bin/bash
# `stride --connect` to a port nobody serves: one error line and a non-zero exit, not a local
# console with no scene that the person then types into (issue 49 point 8).
# usage: connect_refused_test.sh <stride binary> <source dir>
set -u
stride=$1
# A port that was free a moment ago: bound by python, then closed.
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')
out=$(echo 'echo fell-back-to-a-local-console' | timeout 30 "$stride" --connect "127.0.0.1:$port" 2>&1)
rc=$?
echo "exit $rc: $out"
[ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] || { echo "FAIL: exit $rc"; exit 1; }
case "$out" in *fell-back-to-a-local-console*) echo "FAIL: a local console ran"; exit 1 ;; esac
[ "$(printf '%s\n' "$out" | grep -c .)" = 1 ] || { echo "FAIL: not one line"; exit 1; }
echo "ok: a refused connect is an error"

#!/bin/sh
# usage: expect_failure.sh <stride> <script.con> <expected message>
# Passes when the script exits non-zero, prints the message on stderr, and stops at the failure.
stride=$1 script=$2 expected=$3
out=$("$stride" --script "$script" 2>/tmp/stride_expect_failure.$$)
rc=$?
err=$(cat /tmp/stride_expect_failure.$$); rm -f /tmp/stride_expect_failure.$$
if [ "$rc" -eq 0 ]; then echo "FAIL: exit code 0"; exit 1; fi
case "$err" in *"$expected"*) ;; *) echo "FAIL: stderr was: $err"; exit 1;; esac
case "$out" in *"must not run"*) echo "FAIL: ran past the failure"; exit 1;; esac
echo "ok: exit $rc, $err"

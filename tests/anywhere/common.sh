# Shared by the tests in this folder: a fresh directory outside the checkout, and `expect_run`.
# Sourced with $stride set; leaves $work as the working directory (removed on exit).
work=$(mktemp -d /tmp/stride_anywhere.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

# expect_run <exit code> <regex the output must match> <command...>: runs the command, checks its
# exit code and that stdout+stderr match the (extended) regex.
expect_run() {
  local want=$1 pattern=$2
  shift 2
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ "$rc" -ne "$want" ] || ! printf '%s\n' "$out" | grep -Eq -- "$pattern"; then
    echo "FAIL: $* (in $PWD)"
    echo "  exit $rc (want $want), output did not match /$pattern/ or the code differs:"
    printf '%s\n' "$out" | tail -n 15 | sed 's/^/  | /'
    failures=$((failures + 1))
    return 1
  fi
  echo "ok: $* -> exit $rc"
}

finish() {
  [ "$failures" -eq 0 ] && echo "all passed" && exit 0
  echo "$failures check(s) failed"
  exit 1
}

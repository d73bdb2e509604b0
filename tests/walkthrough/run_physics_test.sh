#!/bin/bash
# Issue 49 point 7: `stride run <scene> --physics engine=mujoco` is taken as `sweep` and
# `experiment` take it (the run is MuJoCo's: another state hash than ODE's), and a bad setting is
# one line naming it. usage: run_physics_test.sh <stride binary> <source dir>
set -u
stride=$1 src=$2
scene="$src/scenes/nao_stand_controlled.xml"
hash_of() { sed -n 's/.*hash \([0-9a-f]*\).*/\1/p' | head -n 1; }
ode=$("$stride" run "$scene" --seconds 0.2 2>/dev/null | hash_of)
mujoco=$("$stride" run "$scene" --seconds 0.2 --physics engine=mujoco 2>&1 | hash_of)
again=$("$stride" run "$scene" --seconds 0.2 --physics engine=mujoco 2>&1 | hash_of)
echo "ode $ode, mujoco $mujoco, again $again"
[ -n "$ode" ] && [ -n "$mujoco" ] || { echo "FAIL: no report"; exit 1; }
[ "$ode" != "$mujoco" ] || { echo "FAIL: --physics engine=mujoco ran ODE"; exit 1; }
[ "$mujoco" = "$again" ] || { echo "FAIL: not deterministic"; exit 1; }
bad=$("$stride" run "$scene" --seconds 0.2 --physics engine=bogus 2>&1)
rc=$?
echo "bad: exit $rc: $bad"
[ "$rc" -ne 0 ] && [ "$(printf '%s\n' "$bad" | grep -c .)" = 1 ] &&
  printf '%s' "$bad" | grep -q "engine.*'bogus' (expected one of ode, mujoco)" ||
  { echo "FAIL: a bad --physics"; exit 1; }
echo "ok: stride run --physics"

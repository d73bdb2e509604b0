#!/bin/bash
# `cmake --install` to a temporary prefix: the installed stride finds its scenes and robots under
# the prefix (not in the checkout it was built from) and works from any directory.
# usage: installed_test.sh <build dir> <source dir>
set -u
build=$1 src=$2
. "$src/tests/anywhere/common.sh"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null || { echo "FAIL: cmake --install"; exit 1; }
stride="$prefix/bin/stride"
[ -x "$stride" ] || { echo "FAIL: no $stride"; exit 1; }
[ -f "$prefix/share/stride/scenes/robots/nao/nao.urdf" ] || { echo "FAIL: no robot installed"; exit 1; }
mkdir elsewhere && cd elsewhere || exit 1
expect_run 0 "data directory: $prefix/share/stride " "$stride" help
expect_run 0 'upright' "$stride" run scenes/nao_stand.xml --seconds 0.1
# A scene only the prefix has: the installed stride reads the prefix, not the checkout.
cp "$prefix/share/stride/scenes/nao_stand.xml" "$prefix/share/stride/scenes/prefix_only.xml"
expect_run 0 'upright' "$stride" run scenes/prefix_only.xml --seconds 0.1
expect_run 0 'ok representation:ComState.valid = true' "$stride" -c "mr JointRequest AnkleBalance; \
  run 0.5; expect representation:ComState.valid == true" scenes/nao_stand_controlled.xml
expect_run 0 'total mass' "$stride" kin com --q "LHipPitch=-0.3"
# A --scenes directory that is neither here nor shipped is named as given.
expect_run 3 "scenes/no_such_dir' not found" "$stride" \
  experiment posture --seeds 1 --scenes scenes/no_such_dir
# STRIDE_DATA overrides the prefix: pointing at the checkout works; one without scenes/ is named.
expect_run 0 "data directory: $src " env STRIDE_DATA="$src" "$stride" help
expect_run 0 'upright' env STRIDE_DATA="$src" "$stride" run scenes/nao_stand.xml --seconds 0.1
expect_run 3 "STRIDE_DATA='$work' has no scenes/" env STRIDE_DATA="$work" "$stride" kin com \
  --q "LHipPitch=0"
finish

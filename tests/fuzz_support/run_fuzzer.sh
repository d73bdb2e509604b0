#!/usr/bin/env bash
# Builds one libFuzzer target (clang, ASan + UBSan in every library it reaches, in build-fuzz) and
# runs it on its committed corpus:
#   tests/fuzz_support/run_fuzzer.sh <name> [seconds=600] [libFuzzer flags...]
# <name>: parser, scene, physics, console_exec, log, sweep, tune, lola, debug, identify (the target is
# tests/fuzz_<name>/<name>_fuzzer.cpp; tests/CMakeLists.txt makes one per such file).
# e.g. `... physics 3600 -jobs=2 -workers=2` or `... lola 9000 -runs=1000000`. New inputs go to
# build-fuzz/<name>_corpus; the committed corpus (tests/fuzz_<name>/corpus) is only read; crashes
# go to build-fuzz/<name>_artifacts.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
name=${1:?"a target: parser, scene, physics, console_exec, log, sweep, tune, lola, debug or identify"}
seconds=${2:-600}
shift $(($# < 2 ? $# : 2))
case $name in  # the longest input libFuzzer may build, per target
  parser) max_len=512 ;;
  scene | sweep | debug) max_len=4096 ;;
  physics) max_len=16384 ;;
  console_exec | lola) max_len=2048 ;;
  log | identify) max_len=65536 ;;
  tune) max_len=8192 ;;
  *) echo "run_fuzzer.sh: unknown fuzz target '$name' (parser, scene, physics, console_exec, log, sweep, tune, lola, debug, identify)" >&2; exit 2 ;;
esac
folder=fuzz_$name
[[ $name == console_exec ]] && folder=fuzz_console
cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=None "-DCMAKE_CXX_FLAGS=-O1 -g" -DSTRIDE_SANITIZE=ON -DSTRIDE_FUZZ=ON \
  -DSTRIDE_BENCH=OFF >/dev/null
cmake --build build-fuzz --target "${name}_fuzzer" -j 2
mkdir -p "build-fuzz/${name}_corpus" "build-fuzz/${name}_artifacts"
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$root/.ci/lsan.supp:print_suppressions=0"
cd build-fuzz  # with -jobs=N libFuzzer writes fuzz-<k>.log here
exec "./tests/${name}_fuzzer" -max_total_time="$seconds" -max_len="$max_len" \
  -timeout=30 -print_final_stats=1 -artifact_prefix="$root/build-fuzz/${name}_artifacts/" "$@" \
  "$root/build-fuzz/${name}_corpus" "$root/tests/$folder/corpus"
